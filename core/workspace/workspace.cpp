// SPDX-License-Identifier: GPL-3.0-or-later
// Workspace analysis of one map: areas, boundaries, type II loci and the inscribed rectangle.
#include "core/workspace/workspace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fivebar {

GridSpec gridCovering(const Geometry& g, int cellsOnLongSide, bool workSideOnly) {
  const double r1 = g.a1 + g.b1, r2 = g.a2 + g.b2;
  double xMin = std::max(-0.5 * g.w - r1, 0.5 * g.w - r2);
  double xMax = std::min(-0.5 * g.w + r1, 0.5 * g.w + r2);
  const double yMax = std::min(r1, r2);
  double yMin = workSideOnly ? 0.0 : -yMax;
  if (!(xMax > xMin)) xMax = xMin + 1.0;  // legs that never meet: any small grid
  const int n = std::max(cellsOnLongSide, 2);
  // One cell of border on every side except the y = 0 cut, so closed boundaries close.
  const double spanX = xMax - xMin, spanY = yMax - yMin;
  const int border = workSideOnly ? 1 : 2;
  const double cell = std::max(spanX, spanY) / (n - 2);
  GridSpec grid;
  grid.cellMm = cell;
  grid.nx = std::max(2, static_cast<int>(std::ceil(spanX / cell)) + 2);
  grid.ny = std::max(2, static_cast<int>(std::ceil(spanY / cell)) + border);
  grid.nx = std::min(grid.nx, n);
  grid.ny = std::min(grid.ny, n);
  grid.x0 = 0.5 * (xMin + xMax) - 0.5 * grid.nx * cell;
  grid.y0 = workSideOnly ? yMin : 0.5 * (yMin + yMax) - 0.5 * grid.ny * cell;
  return grid;
}

WorkspaceAnalysis analyse(const WorkspaceMap& map, const Geometry& g, const WorkspaceSettings& s,
                          double aspectRatio) {
  WorkspaceAnalysis a;
  a.mode = map.mode;
  const std::size_t n = map.grid.size();
  const double cellArea = map.grid.cellMm * map.grid.cellMm;
  std::size_t reachable = 0, safe = 0;
  for (std::size_t i = 0; i < n; ++i) {
    reachable += map.reachable[i];
    safe += map.safe(i) ? 1 : 0;
  }
  a.reachableAreaMm2 = static_cast<double>(reachable) * cellArea;
  a.safeAreaMm2 = static_cast<double>(safe) * cellArea;
  a.reachBoundary = contoursOf(map.grid, map.reachSlackMm);
  // Mixed slacks (mm and rad) share one zero level; radians are scaled by a link length.
  const double lengthScaleMm = 0.5 * (g.b1 + g.b2);
  std::vector<float> safeSlack(n);
  for (std::size_t i = 0; i < n; ++i) safeSlack[i] = static_cast<float>(map.safeSlack(i, lengthScaleMm));
  a.safeBoundary = contoursOf(map.grid, safeSlack);
  a.typeIILoci = contoursOf(map.grid, map.signedTypeII);
  a.largestRectangle = largestSafeRectangle(map, g, s, aspectRatio);
  return a;
}

}  // namespace fivebar
