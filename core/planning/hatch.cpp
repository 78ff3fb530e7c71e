// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/hatch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fivebar {
namespace {

// An edge of a ring in the rotated frame (hatch lines horizontal), from a to b.
struct Edge {
  Vec2 a, b;
  double yMin, yMax;
};

struct Crossing {
  double x;
  int direction;  // +1 upwards, -1 downwards
};

bool insideByRule(int winding, FillRule rule) {
  return rule == FillRule::EvenOdd ? (winding & 1) != 0 : winding != 0;
}

class Hatcher {
 public:
  Hatcher(const std::vector<std::vector<Vec2>>& rings, FillRule rule, double angleRad)
      : rule_(rule), cos_(std::cos(angleRad)), sin_(std::sin(angleRad)) {
    for (const std::vector<Vec2>& ring : rings) {
      const std::size_t n = ring.size();
      if (n < 3) continue;
      for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = toRotated(ring[i]), b = toRotated(ring[(i + 1) % n]);
        if (a.y() == b.y()) continue;  // horizontal edges never cross a scanline
        edges_.push_back({a, b, std::min(a.y(), b.y()), std::max(a.y(), b.y())});
      }
    }
    std::sort(edges_.begin(), edges_.end(), [](const Edge& l, const Edge& r) { return l.yMin < r.yMin; });
  }

  std::vector<Polyline> run(double spacingMm) {
    std::vector<Polyline> out;
    if (edges_.empty()) return out;
    double yLow = edges_.front().yMin, yHigh = yLow;
    for (const Edge& e : edges_) yHigh = std::max(yHigh, e.yMax);
    // A grid shared by every shape: lines at (k + 1/2) * spacing.
    const double kFirst = std::ceil(yLow / spacingMm - 0.5), kLast = std::floor(yHigh / spacingMm - 0.5);
    std::vector<Chain> open;
    std::size_t next = 0;
    std::vector<const Edge*> active;
    for (double k = kFirst; k <= kLast; k += 1.0) {
      const double y = (k + 0.5) * spacingMm;
      while (next < edges_.size() && edges_[next].yMin <= y) active.push_back(&edges_[next++]);
      std::erase_if(active, [&](const Edge* e) { return e->yMax < y; });
      const std::vector<std::pair<double, double>> segments = spans(active, y);
      std::vector<Chain> extended;
      std::vector<bool> used(open.size(), false);
      for (const auto& [x0, x1] : segments) {
        bool joined = false;
        for (std::size_t c = 0; c < open.size() && !joined; ++c) {
          if (used[c] || open[c].x1 < x0 || open[c].x0 > x1) continue;  // no overlap
          const bool leftward = open[c].rightward;  // alternate direction
          const Vec2 from = open[c].end;
          const Vec2 start(leftward ? x1 : x0, y), end(leftward ? x0 : x1, y);
          if (!connectorInside(from, start)) continue;
          used[c] = joined = true;
          Chain chain = std::move(open[c]);
          chain.points.push_back(start);
          chain.points.push_back(end);
          chain.end = end;
          chain.rightward = !leftward;
          chain.x0 = x0;
          chain.x1 = x1;
          extended.push_back(std::move(chain));
        }
        if (!joined) {
          Chain chain;
          chain.points = {Vec2(x0, y), Vec2(x1, y)};
          chain.end = chain.points.back();
          chain.rightward = true;
          chain.x0 = x0;
          chain.x1 = x1;
          extended.push_back(std::move(chain));
        }
      }
      for (std::size_t c = 0; c < open.size(); ++c)
        if (!used[c]) finish(std::move(open[c]), out);
      open = std::move(extended);
    }
    for (Chain& chain : open) finish(std::move(chain), out);
    return out;
  }

 private:
  struct Chain {
    std::vector<Vec2> points;  // rotated frame
    Vec2 end;
    bool rightward = true;
    double x0 = 0.0, x1 = 0.0;  // the last span
  };

  Vec2 toRotated(const Vec2& p) const { return {cos_ * p.x() + sin_ * p.y(), -sin_ * p.x() + cos_ * p.y()}; }
  Vec2 fromRotated(const Vec2& q) const { return {cos_ * q.x() - sin_ * q.y(), sin_ * q.x() + cos_ * q.y()}; }

  static double crossX(const Edge& e, double y) {
    return e.a.x() + (y - e.a.y()) * (e.b.x() - e.a.x()) / (e.b.y() - e.a.y());
  }
  static bool crosses(const Edge& e, double y) { return (e.a.y() <= y) != (e.b.y() <= y); }

  // The inside spans of the scanline at y, left to right.
  std::vector<std::pair<double, double>> spans(const std::vector<const Edge*>& active, double y) const {
    std::vector<Crossing> crossings;
    for (const Edge* e : active)
      if (crosses(*e, y)) crossings.push_back({crossX(*e, y), e->b.y() > e->a.y() ? 1 : -1});
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& l, const Crossing& r) { return l.x < r.x; });
    std::vector<std::pair<double, double>> out;
    int winding = 0;
    double start = 0.0;
    for (const Crossing& c : crossings) {
      const bool before = insideByRule(winding, rule_);
      winding += c.direction;
      const bool after = insideByRule(winding, rule_);
      if (!before && after) start = c.x;
      if (before && !after && c.x > start) {
        if (!out.empty() && out.back().second == start) out.back().second = c.x;  // touching spans
        else out.emplace_back(start, c.x);
      }
    }
    return out;
  }

  int windingAt(const Vec2& p) const {
    int winding = 0;
    for (const Edge& e : edges_) {
      if (e.yMin > p.y()) break;
      if (crosses(e, p.y()) && crossX(e, p.y()) > p.x()) winding += e.b.y() > e.a.y() ? 1 : -1;
    }
    return winding;
  }

  // The joining segment p -> q (both on the boundary) stays inside: no edge crosses its interior
  // and its midpoint is inside.
  bool connectorInside(const Vec2& p, const Vec2& q) const {
    const double yLow = std::min(p.y(), q.y()), yHigh = std::max(p.y(), q.y());
    const Vec2 d = q - p;
    const Vec2 mid = 0.5 * (p + q);
    double midToBoundary = std::numeric_limits<double>::infinity();
    for (const Edge& e : edges_) {
      if (e.yMin > yHigh) break;
      if (e.yMax < yLow) continue;
      const Vec2 f = e.b - e.a;
      const double along = std::clamp((mid - e.a).dot(f) / f.squaredNorm(), 0.0, 1.0);
      midToBoundary = std::min(midToBoundary, (e.a + along * f - mid).norm());
      const double denom = d.x() * f.y() - d.y() * f.x();
      if (std::abs(denom) <= 1e-12 * d.norm() * f.norm()) continue;  // parallel (or collinear)
      const Vec2 w = e.a - p;
      const double t = (w.x() * f.y() - w.y() * f.x()) / denom;  // along the connector
      const double u = (w.x() * d.y() - w.y() * d.x()) / denom;  // along the edge
      if (t > 1e-9 && t < 1.0 - 1e-9 && u >= -1e-12 && u <= 1.0 + 1e-12) return false;
    }
    // A join along the boundary (a straight side between two lines) is on it, not outside.
    if (midToBoundary <= 1e-9 * (1.0 + mid.norm())) return true;
    return insideByRule(windingAt(mid), rule_);
  }

  void finish(Chain&& chain, std::vector<Polyline>& out) const {
    Polyline line;
    line.points.reserve(chain.points.size());
    for (const Vec2& q : chain.points) line.points.push_back(fromRotated(q));
    out.push_back(std::move(line));
  }

  FillRule rule_;
  double cos_, sin_;
  std::vector<Edge> edges_;
};

}  // namespace

const char* toString(FillMode mode) {
  switch (mode) {
    case FillMode::Outline: return "outline";
    case FillMode::Hatch: return "hatch";
    case FillMode::None: return "none";
  }
  return "outline";
}

std::optional<FillMode> fillModeFromString(std::string_view text) {
  if (text == "outline") return FillMode::Outline;
  if (text == "hatch") return FillMode::Hatch;
  if (text == "none") return FillMode::None;
  return std::nullopt;
}

std::string validate(const HatchSettings& s) {
  if (!std::isfinite(s.spacingMm) || s.spacingMm < kMinHatchSpacingMm)
    return "hatch spacing must be at least 0.01 mm";
  if (!std::isfinite(s.angleRad)) return "hatch angle must be a finite number";
  return {};
}

std::vector<Polyline> hatchArea(const std::vector<std::vector<Vec2>>& rings, FillRule rule,
                                double spacingMm, double angleRad) {
  if (rule == FillRule::None || !(spacingMm >= kMinHatchSpacingMm)) return {};
  return Hatcher(rings, rule, angleRad).run(spacingMm);
}

std::vector<Polyline> applyFill(const std::vector<Polyline>& paths, FillMode mode,
                                const HatchSettings& settings) {
  if (mode == FillMode::Outline) return paths;
  std::vector<Polyline> out;
  out.reserve(paths.size());
  for (std::size_t i = 0; i < paths.size();) {
    const Polyline& first = paths[i];
    if (first.fill == FillRule::None) {
      out.push_back(first);
      ++i;
      continue;
    }
    // One filled shape: this ring and the following ones until the next shape starts.
    std::size_t end = i + 1;
    while (end < paths.size() && paths[end].fill != FillRule::None && !paths[end].fillStart) ++end;
    std::vector<std::vector<Vec2>> rings;
    bool flattened = false;  // a hatch line ends on a flattened ring: it carries that error
    for (std::size_t j = i; j < end; ++j) {
      const Polyline& ring = paths[j];
      if (!ring.fillOnly || (mode == FillMode::Hatch && settings.outline)) out.push_back(ring);
      rings.push_back(ring.points);
      flattened = flattened || ring.flattened;
    }
    if (mode == FillMode::Hatch) {
      for (Polyline& line : hatchArea(rings, first.fill, settings.spacingMm, settings.angleRad)) {
        line.flattened = flattened;
        out.push_back(std::move(line));
      }
      if (settings.crosshatch)
        for (Polyline& line : hatchArea(rings, first.fill, settings.spacingMm,
                                        settings.angleRad + 0.5 * std::numbers::pi)) {
          line.flattened = flattened;
          out.push_back(std::move(line));
        }
    }
    i = end;
  }
  return out;
}

}  // namespace fivebar
