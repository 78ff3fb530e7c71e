// SPDX-License-Identifier: GPL-3.0-or-later
// The one placement rule. Contract: auto_placement.hpp.
#include "core/planning/auto_placement.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/support/parallel.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

// About this many points of a drawing are sampled to bound a mode's margin from above.
constexpr std::size_t kScreenPoints = 20000;
// A drawing within this factor of 100 % counts as fitting at true size (the rectangle search
// is refined to far less; this only keeps 99.9999 % from being called "scaled").
constexpr double kTrueSizeSlack = 1e-9;

// Bounds of the visible points rotated by rotationRad about the origin.
std::optional<RectMm> rotatedBounds(const Drawing& d, double rotationRad) {
  const Eigen::Rotation2Dd rot(rotationRad);
  std::optional<RectMm> box;
  for (const Layer& l : d.layers) {
    if (!l.visible) continue;
    for (const Polyline& path : l.paths)
      for (const Vec2& p0 : path.points) {
        const Vec2 p = rot * p0;
        if (!box) box = RectMm{p.x(), p.y(), p.x(), p.y()};
        box->x0 = std::min(box->x0, p.x()), box->x1 = std::max(box->x1, p.x());
        box->y0 = std::min(box->y0, p.y()), box->y1 = std::max(box->y1, p.y());
      }
  }
  return box;
}

// sin of the type II margin of the pose reaching p with angles q; negative when the pose is in
// the other assembly mode.
double signedSinTypeII(const Geometry& g, const JointAngles& q, const Vec2& p, AssemblyMode a) {
  const Vec2 d1 = p - elbow1(g, q.theta1), d2 = p - elbow2(g, q.theta2);
  const double s = std::min(1.0, std::abs(cross(d1, d2)) / (g.b1 * g.b2));
  return assemblyModeOf(makePose(g, q, p)) == a ? s : -s;
}

struct Option {
  AutoPlacement placed;
  std::optional<double> marginRad;
};

// true when a ranks before b under the Auto rule.
bool ranksBefore(const Option& a, const Option& b) {
  if (a.marginRad.has_value() != b.marginRad.has_value()) return a.marginRad.has_value();
  if (a.marginRad) return *a.marginRad > *b.marginRad;
  return a.placed.placement.scale > b.placed.placement.scale;
}

}  // namespace

std::optional<RectMm> fitRectangle(const MachineProfile& p, WorkingMode mode, double aspect) {
  const WorkspaceSettings s = workspaceSettings(p);
  const WorkspaceMap map = computeMap(p.geometry, s, mode, gridCovering(p.geometry, kFitGridCells), 1);
  const std::optional<Rect> r = largestSafeRectangle(map, p.geometry, s, aspect);
  if (!r) return std::nullopt;
  return RectMm{r->xMin, r->yMin, r->xMax, r->yMax};
}

std::optional<double> screenMarginRad(const Drawing& d, const std::optional<RectMm>& bounds,
                                      const Placement& placement, const MachineProfile& p,
                                      WorkingMode mode) {
  const Eigen::Affine2d machineFromWorkT = machineFromWork(bounds, placement);
  std::size_t total = 0;
  for (const Layer& l : d.layers)
    if (l.visible)
      for (const Polyline& path : l.paths) total += path.points.size();
  const std::size_t stride = std::max<std::size_t>(1, total / kScreenPoints);
  double bound = 1.0;
  std::size_t k = 0;
  for (const Layer& l : d.layers) {
    if (!l.visible) continue;
    for (const Polyline& path : l.paths)
      for (const Vec2& w : path.points) {
        if (k++ % stride != 0) continue;
        const Vec2 x = machineFromWorkT * w;
        Vec2 distal = x;  // P, where the pen (with the calibrated pen offset) is at x
        const IkResult ik = penInverse(p, x, mode, &distal);
        if (!ik.ok()) return std::nullopt;
        const double s = signedSinTypeII(p.geometry, ik.angles, distal, p.assembly);
        if (s < 0.0) return std::nullopt;
        bound = std::min(bound, s);
      }
  }
  return std::asin(bound);
}

std::optional<AutoPlacement> autoPlacement(const Drawing& drawing, const MachineProfile& profile,
                                           std::optional<WorkingMode> mode, double rotationRad,
                                           PlacementSizing sizing) {
  const std::optional<RectMm> bounds = drawingBounds(drawing);
  if (!bounds) return std::nullopt;
  const std::optional<RectMm> rotated = rotatedBounds(drawing, rotationRad);
  const double aspect = rotated && rotated->height() > 1e-9 && rotated->width() > 1e-9
                            ? rotated->width() / rotated->height() : 0.0;
  std::vector<WorkingMode> modes(kAllWorkingModes.begin(), kAllWorkingModes.end());
  if (mode) modes = {*mode};
  std::vector<std::optional<Option>> slots(modes.size());
  parallelFor(modes.size(), planningThreads(), [&](std::size_t i) {
    const std::optional<RectMm> rect = fitRectangle(profile, modes[i], aspect);
    if (!rect) return;
    const std::optional<Placement> fitted =
        fitPlacement(bounds, *rect, true, kFitMarginMm, rotationRad);
    if (!fitted) return;
    Option o;
    o.placed.mode = modes[i];
    o.placed.rectMm = *rect;
    o.placed.fitScale = fitted->scale;
    o.placed.placement = *fitted;
    if (sizing == PlacementSizing::TrueSize) {
      o.placed.scaledDown = fitted->scale < 1.0 - kTrueSizeSlack;
      o.placed.placement.scale = std::min(1.0, fitted->scale);
    }
    o.marginRad = screenMarginRad(drawing, bounds, o.placed.placement, profile, modes[i]);
    slots[i] = o;
  });
  std::optional<Option> best;
  for (const auto& o : slots)
    if (o && (!best || ranksBefore(*o, *best))) best = o;
  if (!best) return std::nullopt;
  return best->placed;
}

Message scaleNote(const AutoPlacement& placed) {
  if (!placed.scaledDown) return {};
  const double percent = placed.placement.scale * 100.0;
  return FB_TR("Placement", "scaled to %1 % to fit the workspace").arg(percent, percent < 10.0 ? 1 : 0);
}

}  // namespace fivebar
