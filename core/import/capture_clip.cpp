// SPDX-License-Identifier: GPL-3.0-or-later
// The capture engine's clip paths (capture_engine.hpp kClip*): buffers per open clip, the clip
// region's shapes, and cutting a buffer when its clip is applied (clip.hpp).
#include <QPainter>

#include <algorithm>
#include <iterator>

#include "capture_engine.hpp"

namespace fivebar::svg {

void CaptureEngine::store(CapturedRun&& run) {
  if (run.paths.empty()) return;
  std::vector<CapturedRun>& runs = clipBuffers_.empty() ? runs_ : clipBuffers_.back();
  if (runs.empty() || runs.back().topIndex != run.topIndex || runs.back().rgb != run.rgb) {
    runs.push_back(std::move(run));
    return;
  }
  auto& paths = runs.back().paths;
  paths.insert(paths.end(), std::make_move_iterator(run.paths.begin()),
               std::make_move_iterator(run.paths.end()));
}

bool CaptureEngine::collectClip(std::vector<Polyline>&& rings, FillRule rule) {
  if (!collecting_) return false;
  ClipShape shape;
  shape.rule = rule == FillRule::EvenOdd ? FillRule::EvenOdd : FillRule::NonZero;
  for (Polyline& ring : rings)
    if (ring.points.size() > 2) shape.rings.push_back(std::move(ring.points));
  if (!shape.rings.empty()) clipShapes_.push_back(std::move(shape));
  return true;
}

void CaptureEngine::clipCommand(std::uint32_t command) {
  flushPending();
  if (command == kClipBegin) {
    clipBuffers_.emplace_back();
    return;
  }
  if (command == kClipShapesUser || command == kClipShapesBox) {
    collecting_ = true;
    collectBox_ = command == kClipShapesBox;
    clipSpace_ = painter()->combinedTransform();
    clipShapes_.clear();
    return;
  }
  if (command != kClipApply || clipBuffers_.empty()) return;
  collecting_ = false;
  std::vector<CapturedRun> runs = std::move(clipBuffers_.back());
  clipBuffers_.pop_back();
  std::vector<ClipShape> shapes = std::move(clipShapes_);
  clipShapes_.clear();
  if (collectBox_) {  // unit square -> the buffered lines' bounding box in the clip's user space
    bool invertible = false;
    const QTransform userFromPage = clipSpace_.inverted(&invertible);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const CapturedRun& run : runs)
      for (const Polyline& line : run.paths)
        for (const Vec2& p : line.points) {
          const QPointF u = userFromPage.map(QPointF(p.x(), p.y()));
          x0 = std::min(x0, u.x()), y0 = std::min(y0, u.y());
          x1 = std::max(x1, u.x()), y1 = std::max(y1, u.y());
        }
    if (!invertible || !(x1 > x0) || !(y1 > y0)) shapes.clear();  // no box: nothing shows
    const QTransform pageFromBox = QTransform(x1 - x0, 0, 0, y1 - y0, x0, y0) * clipSpace_;
    for (ClipShape& shape : shapes)
      for (auto& ring : shape.rings)
        for (Vec2& p : ring) {
          const QPointF u = userFromPage.map(QPointF(p.x(), p.y()));
          const QPointF q = pageFromBox.map(u);
          p = Vec2(q.x(), q.y());
        }
  }
  for (CapturedRun& run : runs) {
    run.paths = clipLines(std::move(run.paths), shapes);
    store(std::move(run));
  }
}

}  // namespace fivebar::svg
