// SPDX-License-Identifier: GPL-3.0-or-later
// Frame-budget painting of a PathScene: renders it into an offscreen image that covers the
// viewport plus a margin, then blits. While only the pan changes the image is reused; while the
// order limit only grows (a running simulation's trace) just the new segments are added. Zoom,
// options or scene changes re-render (level of detail keeps that bounded); with quick zoom on,
// zoom steps show the cached image scaled until a settled re-render.
#pragma once

#include <QImage>
#include <QPainter>
#include <memory>

#include "widgets/canvas/path_scene.hpp"
#include "paint/view_transform.hpp"

namespace fivebar::widgets {

class SceneRenderer {
 public:
  // `optionsKey` identifies every option except the order limit (callers bump it when colours,
  // travel visibility or the scene transform change).
  void paint(QPainter& painter, const paint::ViewTransform& view,
             const std::shared_ptr<const PathScene>& scene, const ScenePaintOptions& options,
             quint64 optionsKey);
  void invalidate() { scene_.reset(); }

  // Quick zoom: while on, a change of zoom alone redraws the cached image scaled (a preview
  // that may look soft) instead of re-rendering; stale() then says a settled re-render is due
  // (the canvas asks for it once the wheel stops). Off: every zoom re-renders.
  void setQuickZoom(bool on) { quickZoom_ = on; }
  bool stale() const { return stale_; }
  int previewFrames() const { return previewFrames_; }

  // Counters for tests and the benchmark.
  int fullRenders() const { return fullRenders_; }
  int incrementalRenders() const { return incrementalRenders_; }

 private:
  bool covers(const paint::ViewTransform& view) const;
  void renderFull(const paint::ViewTransform& view, const ScenePaintOptions& options);

  std::shared_ptr<const PathScene> scene_;
  QImage image_;
  paint::ViewTransform imageView_;  // the view the image was rendered with (expanded viewport)
  quint64 optionsKey_ = 0;
  int orderBegin_ = 0;
  int orderLimit_ = -1;
  double opacity_ = 1.0;
  bool quickZoom_ = false;
  bool stale_ = false;
  int previewFrames_ = 0;
  int fullRenders_ = 0;
  int incrementalRenders_ = 0;
};

}  // namespace fivebar::widgets
