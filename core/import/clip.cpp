// SPDX-License-Identifier: GPL-3.0-or-later
#include "clip.hpp"

#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace fivebar::svg {
namespace {

constexpr double kOnEdgeMm = 1e-9;  // a point this close to an edge is on it (inside)

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool onSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm() <= kOnEdgeMm;
}

// Winding number of the rings around p (signed crossings of the ray to +x) and the number of
// crossings; onEdge when p lies on an edge.
int winding(const Vec2& p, const std::vector<std::vector<Vec2>>& rings, int& crossings, bool& onEdge) {
  int w = 0;
  crossings = 0;
  onEdge = false;
  for (const auto& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = ring[i];
      const Vec2& b = ring[(i + 1) % n];
      if (onSegment(p, a, b)) {
        onEdge = true;
        return 0;
      }
      if ((a.y() <= p.y()) != (b.y() <= p.y())) {
        const double side = cross(b - a, p - a);
        if (b.y() > a.y() && side > 0.0) ++w, ++crossings;
        else if (b.y() <= a.y() && side < 0.0) --w, ++crossings;
      }
    }
  }
  return w;
}

bool insideShape(const Vec2& p, const ClipShape& shape) {
  int crossings = 0;
  bool onEdge = false;
  const int w = winding(p, shape.rings, crossings, onEdge);
  if (onEdge) return true;
  return shape.rule == FillRule::EvenOdd ? crossings % 2 == 1 : w != 0;
}

// Parameters t in (0, 1) where segment a-b crosses an edge of the clip.
void crossingParameters(const Vec2& a, const Vec2& b, const std::vector<ClipShape>& clip,
                        std::vector<double>& ts) {
  const Vec2 d = b - a;
  const double minX = std::min(a.x(), b.x()), maxX = std::max(a.x(), b.x());
  const double minY = std::min(a.y(), b.y()), maxY = std::max(a.y(), b.y());
  for (const ClipShape& shape : clip)
    for (const auto& ring : shape.rings) {
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec2& c = ring[i];
        const Vec2& e = ring[(i + 1) % n];
        if (std::max(c.x(), e.x()) < minX || std::min(c.x(), e.x()) > maxX ||
            std::max(c.y(), e.y()) < minY || std::min(c.y(), e.y()) > maxY)
          continue;
        const Vec2 f = e - c;
        const double denom = cross(d, f);
        if (denom == 0.0) continue;  // parallel: the pieces' midpoints decide
        const double t = cross(c - a, f) / denom;
        const double u = cross(c - a, d) / denom;
        if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) ts.push_back(t);
      }
    }
}

// A stroke cut into its pieces inside the clip; returns false when it was cut.
bool clipStroke(const Polyline& line, const std::vector<ClipShape>& clip, std::vector<Polyline>& out) {
  const auto& pts = line.points;
  const std::size_t n = pts.size();
  const std::size_t segments = line.closed ? n : n - 1;
  std::vector<Polyline> pieces;
  Polyline current;
  current.flattened = line.flattened;
  bool allInside = true;
  auto finish = [&] {
    if (current.points.size() >= 2) pieces.push_back(current);
    current.points.clear();
  };
  std::vector<double> ts;
  for (std::size_t i = 0; i < segments; ++i) {
    const Vec2& a = pts[i];
    const Vec2& b = pts[(i + 1) % n];
    ts.assign({0.0, 1.0});
    crossingParameters(a, b, clip, ts);
    std::sort(ts.begin(), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      if (ts[k + 1] - ts[k] <= 0.0) continue;
      const Vec2 p = a + ts[k] * (b - a), q = a + ts[k + 1] * (b - a);
      if (insideClip(0.5 * (p + q), clip)) {
        if (current.points.empty() || current.points.back() != p) {
          finish();
          current.points.push_back(p);
        }
        current.points.push_back(q);
      } else {
        allInside = false;
        finish();
      }
    }
  }
  finish();
  if (allInside && !pieces.empty()) {  // untouched: keep it as it was (closed, fill marks)
    out.push_back(line);
    return true;
  }
  // An open piece that ends where the first begins on a closed ring is one piece.
  if (line.closed && pieces.size() >= 2 && pieces.back().points.back() == pieces.front().points.front()) {
    pieces.back().points.insert(pieces.back().points.end(), pieces.front().points.begin() + 1,
                                pieces.front().points.end());
    pieces.front() = std::move(pieces.back());
    pieces.pop_back();
  }
  for (Polyline& piece : pieces) out.push_back(std::move(piece));
  return false;
}

QPainterPath pathOf(const std::vector<std::vector<Vec2>>& rings, FillRule rule) {
  QPainterPath path;
  path.setFillRule(rule == FillRule::EvenOdd ? Qt::OddEvenFill : Qt::WindingFill);
  for (const auto& ring : rings) {
    QPolygonF polygon;
    for (const Vec2& p : ring) polygon << QPointF(p.x(), p.y());
    path.addPolygon(polygon);
    path.closeSubpath();
  }
  return path;
}

// A fill-only shape (its rings) intersected with the clip region as areas.
void clipFill(const std::vector<Polyline>& rings, const QPainterPath& region, std::vector<Polyline>& out) {
  std::vector<std::vector<Vec2>> points;
  for (const Polyline& r : rings) points.push_back(r.points);
  const FillRule rule = rings.front().fill == FillRule::None ? FillRule::NonZero : rings.front().fill;
  const QPainterPath clipped = pathOf(points, rule).intersected(region);
  bool first = true;
  for (const QPolygonF& polygon : clipped.toSubpathPolygons()) {
    Polyline line;
    for (const QPointF& p : polygon) line.points.emplace_back(p.x(), p.y());
    line.points.erase(std::unique(line.points.begin(), line.points.end()), line.points.end());
    if (line.points.size() > 2 && line.points.front() == line.points.back()) line.points.pop_back();
    if (line.points.size() < 3) continue;
    line.closed = true;
    line.fill = rule;
    line.fillOnly = true;
    line.fillStart = first;
    line.flattened = rings.front().flattened;
    first = false;
    out.push_back(std::move(line));
  }
}

}  // namespace

bool insideClip(const Vec2& p, const std::vector<ClipShape>& clip) {
  return std::any_of(clip.begin(), clip.end(), [&](const ClipShape& s) { return insideShape(p, s); });
}

std::vector<Polyline> clipLines(std::vector<Polyline>&& lines, const std::vector<ClipShape>& clip) {
  std::vector<Polyline> out;
  if (clip.empty()) return out;  // an empty clip region hides everything
  QPainterPath region;
  bool regionBuilt = false;
  for (std::size_t i = 0; i < lines.size();) {
    const Polyline& line = lines[i];
    if (line.fillOnly && line.fill != FillRule::None) {
      std::size_t end = i + 1;
      while (end < lines.size() && lines[end].fillOnly && !lines[end].fillStart) ++end;
      if (!regionBuilt) {
        region.setFillRule(Qt::WindingFill);
        for (const ClipShape& s : clip) region = region.united(pathOf(s.rings, s.rule));
        regionBuilt = true;
      }
      clipFill(std::vector<Polyline>(lines.begin() + static_cast<std::ptrdiff_t>(i),
                                     lines.begin() + static_cast<std::ptrdiff_t>(end)),
               region, out);
      i = end;
      continue;
    }
    // A stroked shape: its rings together; when one is cut, none keeps the fill marks.
    std::size_t end = i + 1;
    if (line.fill != FillRule::None)
      while (end < lines.size() && lines[end].fill != FillRule::None && !lines[end].fillStart &&
             !lines[end].fillOnly)
        ++end;
    const std::size_t first = out.size();
    bool whole = true;
    for (std::size_t k = i; k < end; ++k)
      if (lines[k].points.size() >= 2) whole = clipStroke(lines[k], clip, out) && whole;
    if (!whole)
      for (std::size_t k = first; k < out.size(); ++k) {
        out[k].fill = FillRule::None;
        out[k].fillStart = out[k].fillOnly = false;
      }
    i = end;
  }
  return out;
}

}  // namespace fivebar::svg
