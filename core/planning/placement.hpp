// SPDX-License-Identifier: GPL-3.0-or-later
// Placement of a drawing on the machine: the work frame (mm, y up, as imported) is scaled,
// rotated and translated into the machine frame (mm, conventions.md). The drawing's bounding-box
// centre (visible layers) lands on Placement::centerMm.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/planning/strokes.hpp"

namespace fivebar {

// An axis-aligned rectangle in millimetres (x0 <= x1, y0 <= y1). Frame given by the context:
// drawing bounds are in the work frame, fit targets (e.g. the largest singularity-free rectangle
// from core/workspace.hpp) are in the machine frame.
struct RectMm {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  Vec2 center() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
  // True when p lies inside, allowing `toleranceMm` outside each edge.
  bool contains(const Vec2& p, double toleranceMm = 0.0) const {
    return p.x() >= x0 - toleranceMm && p.x() <= x1 + toleranceMm && p.y() >= y0 - toleranceMm &&
           p.y() <= y1 + toleranceMm;
  }
};

struct Placement {
  Vec2 centerMm = Vec2::Zero();  // machine-frame position of the drawing's bbox centre, mm
  double rotationRad = 0.0;      // counter-clockwise rotation about that centre, rad
  double scale = 1.0;            // uniform scale factor (work mm -> machine mm), > 0
  double stretchY = 1.0;         // extra y scale (work frame) relative to x; 1 keeps the aspect
};

// Bounds of all points of the visible layers (work frame); nullopt when there is no point.
std::optional<RectMm> drawingBounds(const Drawing& drawing);

// Bounds of a set of strokes (frame of the strokes); nullopt when there is no point.
std::optional<RectMm> strokeBounds(const std::vector<Stroke>& strokes);

// machine = centerMm + Rot(rotationRad) * diag(scale, scale * stretchY) * (work - workCenter),
// with workCenter the centre of drawingBounds (origin when the drawing is empty).
Eigen::Affine2d machineFromWork(const Drawing& drawing, const Placement& placement);
// The same from the drawing's bounds (drawingBounds), for callers that place one drawing often.
Eigen::Affine2d machineFromWork(const std::optional<RectMm>& workBounds, const Placement& placement);

// The visible layers' polylines, each layer under its fill (Layer::fill: hatch lines added after
// their shape, fill-only outlines dropped for none; filledPaths in hatch.hpp), mapped into the
// machine frame, in layer order then path order. Closed polylines get their first point appended
// so the stroke closes; polylines with no point are skipped. layerIndex indexes the Drawing,
// pathIndex the layer's filled polylines (its paths when the fill is outline); reversed is false.
std::vector<Stroke> placeDrawing(const Drawing& drawing, const Placement& placement);
std::vector<Stroke> placeDrawing(const Drawing& drawing, const Eigen::Affine2d& machineFromWorkT);

// The placement that fits the drawing (visible layers) into `rect` (machine frame) with
// `marginMm` kept free on every side, centred in it, at the given rotation. keepAspect = false
// stretches y independently (stretchY != 1). nullopt when the drawing has no extent or the
// rectangle minus margins is empty.
std::optional<Placement> fitPlacement(const Drawing& drawing, const RectMm& rect,
                                      bool keepAspect = true, double marginMm = 0.0,
                                      double rotationRad = 0.0);
// The same from the drawing's bounds (drawingBounds).
std::optional<Placement> fitPlacement(const std::optional<RectMm>& workBounds, const RectMm& rect,
                                      bool keepAspect = true, double marginMm = 0.0,
                                      double rotationRad = 0.0);

}  // namespace fivebar
