// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/canvas_view.hpp"

#include <QKeyEvent>
#include <QPainter>
#include <QWheelEvent>
#include <cmath>

#include "paint/machine_painter.hpp"

namespace fivebar::widgets {
namespace {
constexpr double kZoomStep = 1.25;          // per button press / shortcut
constexpr double kWheelZoomPerDegree = 1.0 / 120.0 * std::log(1.2);  // 1.2x per wheel notch
constexpr double kFitMarginPx = 24.0;
}  // namespace

CanvasView::CanvasView(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(320, 240);
  view_.setViewportPx(size());
}

void CanvasView::addLayer(CanvasLayer* layer) {
  layers_.push_back(layer);
  update();
}

void CanvasView::setTool(CanvasTool* tool) {
  tool_ = tool;
  unsetCursor();
  update();
}

void CanvasView::render(QPainter& painter) {
  paint::paintGrid(painter, view_);
  for (CanvasLayer* layer : layers_) layer->paint(painter, view_);
  if (tool_ != nullptr) tool_->paintOverlay(painter, view_);
}

void CanvasView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  render(painter);
}

void CanvasView::resizeEvent(QResizeEvent*) {
  view_.setViewportPx(size());
  emit viewChanged();
}

void CanvasView::zoomIn() {
  view_.zoomAround(QPointF(width() / 2.0, height() / 2.0), kZoomStep);
  emit viewChanged();
  update();
}

void CanvasView::zoomOut() {
  view_.zoomAround(QPointF(width() / 2.0, height() / 2.0), 1.0 / kZoomStep);
  emit viewChanged();
  update();
}

void CanvasView::fitRect(const QRectF& machineRectMm) {
  view_.setViewportPx(size());
  view_.fit(machineRectMm, kFitMarginPx);
  emit viewChanged();
  update();
}

void CanvasView::centerOn(QPointF machineMm) {
  view_.setCenterMm(machineMm);
  emit viewChanged();
  update();
}

void CanvasView::setView(const paint::ViewTransform& view) {
  view_ = view;
  view_.setViewportPx(size());
  emit viewChanged();
  update();
}

void CanvasView::wheelEvent(QWheelEvent* event) {
  const double degrees = event->angleDelta().y() / 8.0;
  if (degrees == 0.0) return;
  view_.zoomAround(event->position(), std::exp(degrees * 8.0 * kWheelZoomPerDegree));
  emit viewChanged();
  update();
  event->accept();
}

void CanvasView::mousePressEvent(QMouseEvent* event) {
  const bool panButton = event->button() == Qt::MiddleButton ||
                         (event->button() == Qt::LeftButton && spaceHeld_);
  if (panButton) {
    panning_ = true;
    lastPanPx_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    return;
  }
  if (tool_ != nullptr && tool_->mousePress(event, view_)) update();
}

void CanvasView::mouseMoveEvent(QMouseEvent* event) {
  emit cursorMoved(view_.machineFromWidget(event->position()));
  if (panning_) {
    view_.panByPx(event->position() - lastPanPx_);
    lastPanPx_ = event->position();
    emit viewChanged();
    update();
    return;
  }
  if (tool_ != nullptr) {
    if (tool_->mouseMove(event, view_)) update();
    if (!spaceHeld_) setCursor(tool_->cursorAt(event->position(), view_));
  }
}

void CanvasView::mouseReleaseEvent(QMouseEvent* event) {
  if (panning_) {
    panning_ = false;
    setCursor(spaceHeld_ ? Qt::OpenHandCursor : Qt::ArrowCursor);
    return;
  }
  if (tool_ != nullptr && tool_->mouseRelease(event, view_)) update();
}

void CanvasView::keyPressEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
    spaceHeld_ = true;
    setCursor(Qt::OpenHandCursor);
    return;
  }
  QWidget::keyPressEvent(event);
}

void CanvasView::keyReleaseEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
    spaceHeld_ = false;
    unsetCursor();
    return;
  }
  QWidget::keyReleaseEvent(event);
}

}  // namespace fivebar::widgets
