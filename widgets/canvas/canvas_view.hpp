// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas: a QWidget that owns only the view (zoom, pan) and composes painting layers and the
// active tool. Wheel zooms around the cursor, middle-button or space+left drag pans; every other
// mouse event goes to the tool. It stores no document state.
#pragma once

#include <QWidget>
#include <vector>

#include "widgets/canvas/canvas_layer.hpp"
#include "paint/view_transform.hpp"

namespace fivebar::widgets {

class CanvasView : public QWidget {
  Q_OBJECT
 public:
  explicit CanvasView(QWidget* parent = nullptr);

  const paint::ViewTransform& view() const { return view_; }
  // Layers paint in the order added, above the grid. Not owned.
  void addLayer(CanvasLayer* layer);
  // The tool receiving mouse events; nullptr for none. Not owned.
  void setTool(CanvasTool* tool);
  CanvasTool* tool() const { return tool_; }

  // Paints the whole canvas (grid, layers, tool overlay) for the current view: paintEvent and
  // offscreen rendering (tests, benchmarks) share it.
  void render(QPainter& painter);

 public slots:
  void zoomIn();
  void zoomOut();
  // Fits the given machine-frame rectangle (mm) into the viewport.
  void fitRect(const QRectF& machineRectMm);
  void centerOn(QPointF machineMm);
  void setView(const paint::ViewTransform& view);

 signals:
  void viewChanged();
  // Machine-frame position under the cursor (mm), for the status bar.
  void cursorMoved(QPointF machineMm);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;

 private:
  paint::ViewTransform view_;
  std::vector<CanvasLayer*> layers_;
  CanvasTool* tool_ = nullptr;
  bool spaceHeld_ = false;
  bool panning_ = false;
  QPointF lastPanPx_;
};

}  // namespace fivebar::widgets
