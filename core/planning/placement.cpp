// SPDX-License-Identifier: GPL-3.0-or-later
// Drawing placement in the machine frame. Contract: placement.hpp.
#include "core/planning/placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/planning/hatch.hpp"
#include "core/support/parallel.hpp"

namespace fivebar {
namespace {

// Grows `box` (or starts it) to include p.
void include(std::optional<RectMm>& box, const Vec2& p) {
  if (!box) {
    box = RectMm{p.x(), p.y(), p.x(), p.y()};
    return;
  }
  box->x0 = std::min(box->x0, p.x());
  box->y0 = std::min(box->y0, p.y());
  box->x1 = std::max(box->x1, p.x());
  box->y1 = std::max(box->y1, p.y());
}

// Linear part of machineFromWork: Rot(rotation) * diag(scale, scale * stretchY).
Eigen::Matrix2d linearPart(const Placement& pl) {
  return Eigen::Rotation2Dd(pl.rotationRad).toRotationMatrix() *
         Eigen::Vector2d(pl.scale, pl.scale * pl.stretchY).asDiagonal();
}

}  // namespace

std::optional<RectMm> drawingBounds(const Drawing& drawing) {
  std::optional<RectMm> box;
  for (const Layer& layer : drawing.layers) {
    if (!layer.visible) continue;
    for (const Polyline& path : layer.paths)
      for (const Vec2& p : path.points) include(box, p);
  }
  return box;
}

std::optional<RectMm> strokeBounds(const std::vector<Stroke>& strokes) {
  std::optional<RectMm> box;
  for (const Stroke& s : strokes)
    for (const Vec2& p : s.points) include(box, p);
  return box;
}

Eigen::Affine2d machineFromWork(const std::optional<RectMm>& workBounds,
                                const Placement& placement) {
  const Vec2 workCenter = workBounds ? workBounds->center() : Vec2::Zero();
  Eigen::Affine2d t = Eigen::Affine2d::Identity();
  t.linear() = linearPart(placement);
  t.translation() = placement.centerMm - t.linear() * workCenter;
  return t;
}

Eigen::Affine2d machineFromWork(const Drawing& drawing, const Placement& placement) {
  return machineFromWork(drawingBounds(drawing), placement);
}

std::vector<Stroke> placeDrawing(const Drawing& drawing, const Placement& placement) {
  return placeDrawing(drawing, machineFromWork(drawing, placement));
}

std::vector<Stroke> placeDrawing(const Drawing& drawing, const Eigen::Affine2d& machineFromWorkT) {
  // Each layer's polylines under its fill (hatch lines computed here, from the imported shapes).
  std::vector<std::vector<Polyline>> filled(drawing.layers.size());
  std::vector<const std::vector<Polyline>*> pathsOf(drawing.layers.size());
  for (std::size_t li = 0; li < drawing.layers.size(); ++li) {
    const Layer& layer = drawing.layers[li];
    pathsOf[li] = &layer.paths;
    if (layer.visible && layer.fill != FillMode::Outline) {
      filled[li] = filledPaths(layer);
      pathsOf[li] = &filled[li];
    }
  }
  std::vector<std::pair<int, int>> index;  // layer and path of each stroke, in order
  for (std::size_t li = 0; li < drawing.layers.size(); ++li) {
    if (!drawing.layers[li].visible) continue;
    const std::vector<Polyline>& paths = *pathsOf[li];
    for (std::size_t pi = 0; pi < paths.size(); ++pi)
      if (!paths[pi].points.empty()) index.emplace_back(static_cast<int>(li), static_cast<int>(pi));
  }
  // Copied in parallel: a large drawing is tens of MB of fresh memory.
  std::vector<Stroke> out(index.size());
  parallelFor(index.size(), planningThreads(), [&](std::size_t k) {
    const auto [li, pi] = index[k];
    const Polyline& path = (*pathsOf[static_cast<std::size_t>(li)])[static_cast<std::size_t>(pi)];
    Stroke& s = out[k];
    s.layerIndex = li;
    s.pathIndex = pi;
    s.flattened = path.flattened;
    s.points.reserve(path.points.size() + (path.closed ? 1 : 0));
    for (const Vec2& p : path.points) s.points.push_back(machineFromWorkT * p);
    if (path.closed && path.points.size() > 1) s.points.push_back(s.points.front());
  });
  return out;
}

std::optional<Placement> fitPlacement(const Drawing& drawing, const RectMm& rect, bool keepAspect,
                                      double marginMm, double rotationRad) {
  return fitPlacement(drawingBounds(drawing), rect, keepAspect, marginMm, rotationRad);
}

std::optional<Placement> fitPlacement(const std::optional<RectMm>& box, const RectMm& rect,
                                      bool keepAspect, double marginMm, double rotationRad) {
  const double availW = rect.width() - 2.0 * marginMm, availH = rect.height() - 2.0 * marginMm;
  if (!box || !(availW > 0.0) || !(availH > 0.0)) return std::nullopt;
  // Extent of the rotated (unscaled) drawing about its bbox centre, split by work axis so that
  // the x and y scales can be chosen independently: rotated point = Rot * (sx u, sy v).
  const Eigen::Matrix2d rot = Eigen::Rotation2Dd(rotationRad).toRotationMatrix();
  // For a rectangle |u| <= hu, |v| <= hv the rotated extents are linear in (sx, sy):
  // half width = sx hu |cos| + sy hv |sin|, half height = sx hu |sin| + sy hv |cos|.
  const double hu = 0.5 * box->width(), hv = 0.5 * box->height();
  const double ac = std::abs(rot(0, 0)), as = std::abs(rot(1, 0));
  Placement pl;
  pl.centerMm = rect.center();
  pl.rotationRad = rotationRad;
  if (keepAspect) {
    const double w = hu * ac + hv * as, h = hu * as + hv * ac;
    if (!(w > 0.0) && !(h > 0.0)) return std::nullopt;
    const double sx = w > 0.0 ? 0.5 * availW / w : std::numeric_limits<double>::infinity();
    const double sy = h > 0.0 ? 0.5 * availH / h : std::numeric_limits<double>::infinity();
    pl.scale = std::min(sx, sy);
    return pl;
  }
  // Independent scales: solve [hu ac, hv as; hu as, hv ac] [sx; sy] = [availW/2; availH/2]
  // when the rotation keeps the system well posed (and both scales positive); otherwise keep
  // the aspect.
  const double det = hu * hv * (ac * ac - as * as);
  if (hu > 0.0 && hv > 0.0 && std::abs(ac * ac - as * as) > 1e-6) {
    const double sx = 0.5 * (availW * hv * ac - availH * hv * as) / det;
    const double sy = 0.5 * (availH * hu * ac - availW * hu * as) / det;
    if (sx > 0.0 && sy > 0.0) {
      pl.scale = sx;
      pl.stretchY = sy / sx;
      return pl;
    }
  }
  return fitPlacement(box, rect, true, marginMm, rotationRad);
}

}  // namespace fivebar
