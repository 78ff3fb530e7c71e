// SPDX-License-Identifier: GPL-3.0-or-later
// Distances between points, segments and polylines, for tolerance checks.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar::test {

inline double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Distance from p to the polyline through pts (closed: the last point joins the first).
inline double distanceToPolyline(const Vec2& p, const std::vector<Vec2>& pts, bool closed) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    best = std::min(best, distanceToSegment(p, pts[i], pts[i + 1]));
  if (closed && pts.size() > 2) best = std::min(best, distanceToSegment(p, pts.back(), pts.front()));
  if (pts.size() == 1) best = (p - pts[0]).norm();
  return best;
}

}  // namespace fivebar::test
