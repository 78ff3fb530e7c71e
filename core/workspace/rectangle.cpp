// SPDX-License-Identifier: GPL-3.0-or-later
// Largest axis-aligned rectangle in the singularity-free region: maximal rectangle in the binary
// grid of safe cells (histogram and stack, O(nx ny)), then refined side by side against the exact
// point evaluation.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

// A rectangle of whole cells: columns [ix0, ix1], rows [iy0, iy1], inclusive.
struct CellRect {
  int ix0 = 0, iy0 = 0, ix1 = -1, iy1 = -1;
};

// Area (cells^2) of the best rectangle of the wanted aspect ratio inside a W x H cell block.
double score(int W, int H, double aspect) {
  if (aspect <= 0.0) return static_cast<double>(W) * H;
  const double h = std::min<double>(H, W / aspect);
  return aspect * h * h;
}

// Every maximal all-safe block is met as (row, popped bar); the best-scoring one wins.
CellRect largestBlock(const WorkspaceMap& map, double aspect) {
  const GridSpec& g = map.grid;
  std::vector<int> height(static_cast<std::size_t>(g.nx) + 1, 0);  // sentinel 0 at nx
  std::vector<int> stack;
  stack.reserve(height.size());
  double best = 0.0;
  CellRect bestRect;
  for (int iy = 0; iy < g.ny; ++iy) {
    for (int ix = 0; ix < g.nx; ++ix) height[ix] = map.safe(g.index(ix, iy)) ? height[ix] + 1 : 0;
    stack.clear();
    for (int ix = 0; ix <= g.nx; ++ix) {
      while (!stack.empty() && height[stack.back()] >= height[ix]) {
        const int H = height[stack.back()];
        stack.pop_back();
        const int left = stack.empty() ? 0 : stack.back() + 1;
        const int W = ix - left;
        const double s = H > 0 ? score(W, H, aspect) : 0.0;
        if (s > best) {
          best = s;
          bestRect = {left, iy - H + 1, ix - 1, iy};
        }
      }
      stack.push_back(ix);
    }
  }
  return bestRect;
}

bool isSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Vec2& p) {
  const PointSample x = evaluatePoint(g, s, mode, p);
  return x.reachable && x.typeIIMarginRad >= s.typeIIMarginRad &&
         x.typeIMarginRad >= s.typeIMarginRad;
}

// Spacing of the samples along a growing edge: the boundary can bulge into the rectangle between
// two samples by at most spacing^2 / (8 R) for a boundary curve of radius R, i.e. under
// kRectangleInsetMm for R > 1.6 mm.
constexpr double kEdgeSpacingMm = 0.25;
// The final rectangle keeps this far inside the sampled boundary.
constexpr double kRectangleInsetMm = 0.005;

// Samples r on an (nx+1) x (ny+1) lattice at most spacingX / spacingY apart, edges included.
bool latticeIsSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Rect& r,
                   double spacingX, double spacingY) {
  const int nx = std::max(1, static_cast<int>(std::ceil(r.width() / spacingX)));
  const int ny = std::max(1, static_cast<int>(std::ceil(r.height() / spacingY)));
  for (int j = 0; j <= ny; ++j) {
    const double y = r.yMin + r.height() * j / ny;
    for (int i = 0; i <= nx; ++i)
      if (!isSafe(g, s, mode, Vec2(r.xMin + r.width() * i / nx, y))) return false;
  }
  return true;
}

// Checks `outer` minus `inner` (inner inside outer), as up to four strips, `fineMm` apart along
// each strip's long side and `spacingMm` across it.
bool ringIsSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Rect& inner,
                const Rect& outer, double spacingMm, double fineMm = kEdgeSpacingMm) {
  const double fine = std::min(spacingMm, fineMm);
  const Rect strips[4] = {{outer.xMin, outer.yMin, inner.xMin, outer.yMax},
                          {inner.xMax, outer.yMin, outer.xMax, outer.yMax},
                          {inner.xMin, outer.yMin, inner.xMax, inner.yMin},
                          {inner.xMin, inner.yMax, inner.xMax, outer.yMax}};
  for (int k = 0; k < 4; ++k) {
    const Rect& r = strips[k];
    if (r.width() <= 0.0 || r.height() <= 0.0) continue;
    const bool vertical = k < 2;  // left and right strips run along y
    if (!latticeIsSafe(g, s, mode, r, vertical ? spacingMm : fine, vertical ? fine : spacingMm))
      return false;
  }
  return true;
}

// Rect `r` with one side (0 left, 1 right, 2 bottom, 3 top) moved outward by `d`.
Rect moved(Rect r, int side, double d) {
  switch (side) {
    case 0: r.xMin -= d; break;
    case 1: r.xMax += d; break;
    case 2: r.yMin -= d; break;
    default: r.yMax += d; break;
  }
  return r;
}

// How far side `side` of r may move outward and stay on the analysed grid.
double roomToGridEdge(const GridSpec& grid, const Rect& r, int side) {
  switch (side) {
    case 0: return r.xMin - grid.x0;
    case 1: return grid.x0 + grid.nx * grid.cellMm - r.xMax;
    case 2: return r.yMin - grid.y0;
    default: return grid.y0 + grid.ny * grid.cellMm - r.yMax;
  }
}

// The edge `side` of r, sampled kEdgeSpacingMm apart.
bool edgeIsSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Rect& r,
                int side) {
  Rect line = r;
  switch (side) {
    case 0: line.xMax = r.xMin; break;
    case 1: line.xMin = r.xMax; break;
    case 2: line.yMax = r.yMin; break;
    default: line.yMin = r.yMax; break;
  }
  return latticeIsSafe(g, s, mode, line, kEdgeSpacingMm, kEdgeSpacingMm);
}

Rect scaledAboutCentre(const Rect& r, double f) {
  const double cx = 0.5 * (r.xMin + r.xMax), cy = 0.5 * (r.yMin + r.yMax);
  const double hw = 0.5 * r.width() * f, hh = 0.5 * r.height() * f;
  return {cx - hw, cy - hh, cx + hw, cy + hh};
}

// Largest growth in [0, maxGrowth] for which grow(t) stays safe, by bisection.
template <typename Grow>
double bisectGrowth(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Rect& r,
                    double maxGrowth, double spacingMm, double fineMm, Grow grow) {
  double lo = 0.0, hi = maxGrowth;
  for (int k = 0; k < 10; ++k) {
    const double mid = 0.5 * (lo + hi);
    (ringIsSafe(g, s, mode, r, grow(mid), spacingMm, fineMm) ? lo : hi) = mid;
  }
  return lo;
}

// Fixed shape: alternately centre r in the free room along x and y (the room towards each side
// found by bisection) and scale it about its centre as far as it stays safe.
Rect growWithAspect(const WorkspaceMap& map, const Geometry& g, const WorkspaceSettings& s, Rect r) {
  const GridSpec& grid = map.grid;
  const double c = grid.cellMm, spacing = 0.5 * c;
  for (int pass = 0; pass < 3; ++pass) {
    double room[4];
    for (int side = 0; side < 4; ++side) {
      const double limit = std::max(0.0, std::min(2.0 * c, roomToGridEdge(grid, r, side)));
      room[side] = bisectGrowth(g, s, map.mode, r, limit, spacing, spacing,
                                [&](double t) { return moved(r, side, t); });
    }
    const double dx = 0.5 * (room[1] - room[0]), dy = 0.5 * (room[3] - room[2]);
    r = {r.xMin + dx, r.yMin + dy, r.xMax + dx, r.yMax + dy};
    double limit = 2.0 * c;
    for (int side = 0; side < 4; ++side) limit = std::min(limit, 2.0 * roomToGridEdge(grid, r, side));
    const double base = std::max(r.width(), 1e-9);
    const double f = bisectGrowth(g, s, map.mode, r, std::max(0.0, limit) / base, spacing, spacing,
                                  [&](double t) { return scaledAboutCentre(r, 1.0 + t); });
    r = scaledAboutCentre(r, 1.0 + f);
  }
  auto edgesSafe = [&] {
    for (int side = 0; side < 4; ++side)
      if (!edgeIsSafe(g, s, map.mode, r, side)) return false;
    return true;
  };
  // The growth above sampled its rings `spacing` apart (cheap); the edges are now checked
  // kEdgeSpacingMm apart. A bulge of the boundary between coarse samples is cut off by the
  // smallest shrink that clears it (bisection within a quarter cell), else by quarter cells.
  if (!edgesSafe()) {
    const Rect grown = r;
    const double step = 0.25 * c / std::max(std::min(r.width(), r.height()), 1e-9);
    r = scaledAboutCentre(grown, 1.0 - step);
    if (edgesSafe()) {
      double lo = 1.0 - step, hi = 1.0;
      for (int k = 0; k < 6; ++k) {
        const double mid = 0.5 * (lo + hi);
        r = scaledAboutCentre(grown, mid);
        (edgesSafe() ? lo : hi) = mid;
      }
      r = scaledAboutCentre(grown, lo);
    }
  }
  for (int k = 0; k < 8 && !edgesSafe(); ++k)
    r = scaledAboutCentre(r, 1.0 - 0.25 * c / std::max(std::min(r.width(), r.height()), 1e-9));
  const double shorter = std::max(std::min(r.width(), r.height()), 1e-9);
  const double inset = std::min(kRectangleInsetMm, 0.25 * shorter);
  return scaledAboutCentre(r, 1.0 - 2.0 * inset / shorter);
}

}  // namespace

bool rectangleIsSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                     const Rect& r, double spacingMm) {
  return latticeIsSafe(g, s, mode, r, spacingMm, spacingMm);
}

std::optional<Rect> largestSafeRectangle(const WorkspaceMap& map, const Geometry& g,
                                         const WorkspaceSettings& s, double aspectRatio) {
  const CellRect block = largestBlock(map, aspectRatio);
  if (block.ix1 < block.ix0) return std::nullopt;
  const GridSpec& grid = map.grid;
  const double c = grid.cellMm, spacing = 0.5 * c;
  // Start from the safe cell centres (a zero-size rectangle for a single cell).
  Rect r{grid.xCenter(block.ix0), grid.yCenter(block.iy0), grid.xCenter(block.ix1),
         grid.yCenter(block.iy1)};
  if (aspectRatio > 0.0) {  // the wanted shape, centred in the block
    const double h = std::min(r.height(), r.width() / aspectRatio);
    const double cx = 0.5 * (r.xMin + r.xMax), cy = 0.5 * (r.yMin + r.yMax);
    r = {cx - 0.5 * aspectRatio * h, cy - 0.5 * h, cx + 0.5 * aspectRatio * h, cy + 0.5 * h};
  }
  // The samples between cell centres may leave the region where it is not convex: shrink.
  for (int k = 0; k < 8 && !rectangleIsSafe(g, s, map.mode, r, spacing); ++k)
    r = {r.xMin + 0.25 * c, r.yMin + 0.25 * c, r.xMax - 0.25 * c, r.yMax - 0.25 * c};
  if (r.width() < 0.0 || r.height() < 0.0 || !rectangleIsSafe(g, s, map.mode, r, spacing))
    return std::nullopt;
  // Grow towards the true boundary, to a small fraction of a cell.
  if (aspectRatio > 0.0) return growWithAspect(map, g, s, r);
  for (int pass = 0; pass < 2; ++pass) {
    for (int side = 0; side < 4; ++side) {
      const double room = std::max(0.0, std::min(c, roomToGridEdge(grid, r, side)));
      const double d = bisectGrowth(g, s, map.mode, r, room, spacing, kEdgeSpacingMm,
                                    [&](double t) { return moved(r, side, t); });
      r = moved(r, side, d);
    }
  }
  // A side that could not grow was only sampled at the coarse spacing: check each edge finely.
  for (int side = 0; side < 4; ++side) {
    for (int k = 0; k < 8 && !edgeIsSafe(g, s, map.mode, r, side); ++k) r = moved(r, side, -0.125 * c);
  }
  const double inset = std::min(kRectangleInsetMm, 0.25 * std::min(r.width(), r.height()));
  return Rect{r.xMin + inset, r.yMin + inset, r.xMax - inset, r.yMax - inset};
}

}  // namespace fivebar
