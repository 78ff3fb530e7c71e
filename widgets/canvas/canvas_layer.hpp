// SPDX-License-Identifier: GPL-3.0-or-later
// Extension points of the canvas: a CanvasLayer paints one stratum (workspace overlays, the
// drawing, the job, the machine, markers) with a QPainter& in the widget frame; a CanvasTool
// receives the mouse events the view does not use for zoom and pan (placement handles, the
// machine panels' click-to-go-to). Both are owned by whoever creates them, not by the canvas.
#pragma once

#include <QCursor>
#include <QMouseEvent>
#include <QPainter>

#include "paint/view_transform.hpp"

namespace fivebar::widgets {

class CanvasLayer {
 public:
  virtual ~CanvasLayer() = default;
  virtual void paint(QPainter& painter, const paint::ViewTransform& view) = 0;
};

class CanvasTool {
 public:
  virtual ~CanvasTool() = default;
  // Each returns true when it used the event (the view then repaints).
  virtual bool mousePress(QMouseEvent* event, const paint::ViewTransform& view) = 0;
  virtual bool mouseMove(QMouseEvent* event, const paint::ViewTransform& view) = 0;
  virtual bool mouseRelease(QMouseEvent* event, const paint::ViewTransform& view) = 0;
  // Tool feedback (handles, previews) painted above every layer.
  virtual void paintOverlay(QPainter& painter, const paint::ViewTransform& view) = 0;
  // Cursor for the given widget position (hover feedback).
  virtual QCursor cursorAt(QPointF widgetPx, const paint::ViewTransform& view) const = 0;
};

}  // namespace fivebar::widgets
