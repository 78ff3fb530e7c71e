// SPDX-License-Identifier: GPL-3.0-or-later
// Workspace analysis per working mode: sampled maps (reach, singularity margins, transmission
// angle, conditioning, resolution), region boundaries and type II loci, areas, and the largest
// axis-aligned rectangle in the singularity-free region (Hoang 2015 design criterion 3).
// Machine frame, millimetres and radians. Results are values; nothing here is cached or global.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {

// A regular grid of square cells. Cell (ix, iy) covers [x0 + ix*cellMm, x0 + (ix+1)*cellMm] x
// [y0 + iy*cellMm, ...] and is sampled at its centre. Cells are stored row by row (iy major).
struct GridSpec {
  double x0 = 0.0;  // lower-left corner of the grid, mm
  double y0 = 0.0;
  double cellMm = 1.0;
  int nx = 0;
  int ny = 0;

  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(ix);
  }
  double xCenter(int ix) const { return x0 + (ix + 0.5) * cellMm; }
  double yCenter(int iy) const { return y0 + (iy + 0.5) * cellMm; }
};

// A grid of square cells covering every point both legs can reach (the intersection of the two
// outer reach discs) plus one cell of border, with cellsOnLongSide cells along its longer side.
// workSideOnly keeps y >= 0, the work side of the motors (conventions.md: +y toward the work).
GridSpec gridCovering(const Geometry& g, int cellsOnLongSide, bool workSideOnly = true);

// What the analysis needs besides the geometry: joint limits and the safety margins.
struct WorkspaceSettings {
  JointLimits limits;               // continuous motor angles, rad
  double typeIIMarginRad = radFromDeg(15.0);  // closest allowed approach to a type II singularity
  double typeIMarginRad = radFromDeg(2.0);    // closest allowed approach to full stretch/fold
  double stepRad1 = radFromDeg(1.0 / 35.5556);  // motor 1 step (microstep) angle
  double stepRad2 = radFromDeg(1.0 / 35.5556);
  // A calibrated pen offset (pen_kinematics.hpp): the maps are then of the PEN's positions (reach
  // and margins of the pose that puts the pen there, the pen's resolution and conditioning).
  // nullopt: the pen is at P.
  std::optional<PenOffset> penOffset;
};
// The profile's limits, margins, step angles and calibrated pen offset.
WorkspaceSettings workspaceSettings(const MachineProfile& p);

// Everything known about one point in one working mode.
struct PointSample {
  bool reachable = false;        // inverse kinematics exists in the mode and is within limits
  double reachSlackMm = 0.0;     // > 0 inside the reachable region, < 0 outside (approximate mm)
  double typeIIMarginRad = 0.0;  // min(mu, pi - mu); valid when reachable
  double typeIMarginRad = 0.0;   // smaller of the two legs' margins
  double muRad = 0.0;            // transmission angle at P between the floating links, [0, pi]
  double signedTypeII = 0.0;     // det(A) / (b1 b2): sin of the signed angle between the links
  double inverseCondition = 0.0; // sigma_min / sigma_max of J, [0, 1]
  double resolutionMm = 0.0;     // worst-direction mm moved per motor step (inf when singular)
};

// The exact per-point evaluation the maps sample (same formulas, double precision).
PointSample evaluatePoint(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                          const Vec2& p);

// Allocates without value-initialising: a map's fields are written cell by cell by the fill
// threads, so zero-filling them first would only double the memory traffic.
template <typename T>
struct NoInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = NoInitAllocator<U>;
  };
  using std::allocator<T>::allocator;
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
using FloatField = std::vector<float, NoInitAllocator<float>>;
using MaskField = std::vector<std::uint8_t, NoInitAllocator<std::uint8_t>>;

// A sampled map of one working mode. Float fields are NaN in unreachable cells, except
// reachSlackMm which is defined everywhere (its zero level is the reach boundary).
struct WorkspaceMap {
  GridSpec grid;
  WorkingMode mode = WorkingMode::PlusPlus;
  double typeIIMarginRad = 0.0;  // thresholds the map was made with
  double typeIMarginRad = 0.0;
  MaskField reachable;  // 1 when reachable in this mode within joint limits
  FloatField reachSlackMm;
  FloatField typeIIMarginRadMap;
  FloatField typeIMarginRadMap;
  FloatField muRad;
  FloatField signedTypeII;
  FloatField inverseCondition;
  FloatField resolutionMm;

  // Reachable and at least the margins away from every singularity.
  bool safe(std::size_t i) const {
    return reachable[i] && typeIIMarginRadMap[i] >= typeIIMarginRad &&
           typeIMarginRadMap[i] >= typeIMarginRad;
  }
  // > 0 in the safe region, < 0 outside, 0 on its boundary (mixed units scaled to mm).
  double safeSlack(std::size_t i, double lengthScaleMm) const;
};

// One mode's map. `threads` worker threads split the rows (1 = the calling thread only).
WorkspaceMap computeMap(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                        const GridSpec& grid, int threads = 2);
// All four working modes at once, sharing the per-arm work (indexed like kAllWorkingModes).
std::array<WorkspaceMap, 4> computeAllModes(const Geometry& g, const WorkspaceSettings& s,
                                            const GridSpec& grid, int threads = 2);
// The same, reusing the storage of `maps` (no allocation when the grid size is unchanged): for
// overlays recomputed while a geometry is edited.
void computeAllModes(const Geometry& g, const WorkspaceSettings& s, const GridSpec& grid,
                     std::array<WorkspaceMap, 4>& maps, int threads = 2);

// Marching squares on cell-centre samples: the level-0 contours of `values` (one per cell,
// > 0 inside), skipping squares with a NaN corner. Polylines in mm, linearly interpolated along
// the cell edges; closed when the contour closes inside the grid.
std::vector<Polyline> contoursOf(const GridSpec& grid, std::span<const float> values);

struct Rect {
  double xMin = 0.0, yMin = 0.0, xMax = 0.0, yMax = 0.0;  // mm
  double width() const { return xMax - xMin; }
  double height() const { return yMax - yMin; }
  double area() const { return width() * height(); }
};

// Whether every point of `r` (sampled at most `spacingMm` apart, edges included) is in the safe
// region of `mode`.
bool rectangleIsSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                     const Rect& r, double spacingMm);

// The largest axis-aligned rectangle in the map's safe region: maximal rectangle in the binary
// grid (histogram and stack), then each side refined against evaluatePoint to a fraction of a
// cell. aspectRatio = width / height when > 0; 0 accepts any shape. nullopt when no cell is safe.
std::optional<Rect> largestSafeRectangle(const WorkspaceMap& map, const Geometry& g,
                                         const WorkspaceSettings& s, double aspectRatio = 0.0);

struct WorkspaceAnalysis {
  WorkingMode mode = WorkingMode::PlusPlus;
  double reachableAreaMm2 = 0.0;
  double safeAreaMm2 = 0.0;                // reachable and at least the margins from singularities
  std::vector<Polyline> reachBoundary;     // boundary of the reachable region
  std::vector<Polyline> safeBoundary;      // boundary of the singularity-free region
  std::vector<Polyline> typeIILoci;        // det(A) = 0 inside the reachable region
  std::optional<Rect> largestRectangle;    // in the safe region
};

WorkspaceAnalysis analyse(const WorkspaceMap& map, const Geometry& g, const WorkspaceSettings& s,
                          double aspectRatio = 0.0);

}  // namespace fivebar
