// SPDX-License-Identifier: GPL-3.0-or-later
#include "dashes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fivebar::svg {

std::optional<DashPattern> dashPatternOf(const QPen& pen) {
  if (pen.style() != Qt::CustomDashLine) return std::nullopt;
  const double width = pen.widthF() > 0.0 ? pen.widthF() : 1.0;  // Qt SVG scales by this width
  DashPattern pattern;
  for (const qreal v : pen.dashPattern()) {
    if (!(v >= 0.0) || !std::isfinite(v)) return std::nullopt;
    pattern.lengths.push_back(v * width);
  }
  if (pattern.lengths.empty()) return std::nullopt;
  if (pattern.lengths.size() % 2 != 0) {
    const std::vector<double> once = pattern.lengths;
    pattern.lengths.insert(pattern.lengths.end(), once.begin(), once.end());
  }
  const double total = std::accumulate(pattern.lengths.begin(), pattern.lengths.end(), 0.0);
  if (!(total > 0.0) || !std::isfinite(total)) return std::nullopt;
  pattern.offset = std::isfinite(pen.dashOffset()) ? pen.dashOffset() * width : 0.0;
  return pattern;
}

namespace {

// Walks one polyline, emitting the dashes into out.
class Dasher {
 public:
  Dasher(const DashPattern& pattern, std::vector<Polyline>& out) : pattern_(pattern), out_(out) {
    const double total = std::accumulate(pattern.lengths.begin(), pattern.lengths.end(), 0.0);
    double start = std::fmod(pattern.offset, total);
    if (start < 0.0) start += total;
    // The entry the offset falls in, and what is left of it.
    while (start >= pattern.lengths[index_]) {
      start -= pattern.lengths[index_];
      index_ = (index_ + 1) % pattern.lengths.size();
    }
    left_ = pattern.lengths[index_] - start;
  }

  // One segment from a to b (page frame), userLength long in user units.
  void segment(const Vec2& a, const Vec2& b, double userLength) {
    if (on() && current_.points.empty()) current_.points.push_back(a);
    double done = 0.0;  // user units along this segment
    while (userLength - done > left_) {
      done += left_;
      const Vec2 p = a + (b - a) * (done / userLength);
      if (on()) {
        current_.points.push_back(p);
        finish();
      } else {
        current_.points.push_back(p);
      }
      index_ = (index_ + 1) % pattern_.lengths.size();
      left_ = pattern_.lengths[index_];
      if (!on()) current_.points.clear();
    }
    left_ -= userLength - done;
    if (on()) current_.points.push_back(b);
  }

  bool on() const { return index_ % 2 == 0; }

  void finish() {
    Polyline line;
    line.points = std::move(current_.points);
    line.points.erase(std::unique(line.points.begin(), line.points.end()), line.points.end());
    line.flattened = flattened_;
    if (line.points.size() >= 2) out_.push_back(std::move(line));
    current_.points.clear();
  }

  bool flattened_ = false;

 private:
  const DashPattern& pattern_;
  std::vector<Polyline>& out_;
  std::size_t index_ = 0;
  double left_ = 0.0;  // user units left in the current entry
  Polyline current_;
};

}  // namespace

std::vector<Polyline> applyDashes(const std::vector<Polyline>& lines, const DashPattern& pattern,
                                  const QTransform& pageFromUser) {
  std::vector<Polyline> out;
  bool invertible = false;
  const QTransform userFromPage = pageFromUser.inverted(&invertible);
  if (!invertible) return lines;
  auto user = [&](const Vec2& p) {
    const QPointF q = userFromPage.map(QPointF(p.x(), p.y()));
    return Vec2(q.x(), q.y());
  };
  // A runaway pattern (0.001-unit dashes over metres of path) stays solid rather than
  // flooding the plot with millions of pen lifts.
  constexpr double kMaxDashes = 1e6;
  const double total = std::accumulate(pattern.lengths.begin(), pattern.lengths.end(), 0.0);
  double userLength = 0.0;
  for (const Polyline& line : lines)
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i)
      userLength += (user(line.points[i + 1]) - user(line.points[i])).norm();
  if (userLength / total * 0.5 * static_cast<double>(pattern.lengths.size()) > kMaxDashes) return lines;
  for (const Polyline& line : lines) {
    const std::size_t first = out.size();
    Dasher dasher(pattern, out);
    dasher.flattened_ = line.flattened;
    const bool startsOn = dasher.on();
    const auto& pts = line.points;
    const std::size_t n = pts.size();
    const std::size_t segments = line.closed ? n : n - 1;
    for (std::size_t i = 0; i < segments && n >= 2; ++i) {
      const Vec2& a = pts[i];
      const Vec2& b = pts[(i + 1) % n];
      const double length = (user(b) - user(a)).norm();
      if (length > 0.0) dasher.segment(a, b, length);
    }
    const bool endsOn = dasher.on();
    dasher.finish();
    // A closed ring whose first and last dashes meet at its start: one dash.
    if (line.closed && startsOn && endsOn && out.size() >= first + 2 && out.back().points.back() == pts.front() &&
        out[first].points.front() == pts.front()) {
      Polyline last = std::move(out.back());
      out.pop_back();
      last.points.insert(last.points.end(), out[first].points.begin() + 1, out[first].points.end());
      out[first] = std::move(last);
    }
  }
  return out;
}

}  // namespace fivebar::svg
