// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas tool that moves, rotates and scales the drawing with handles: drag inside the
// drawing's box to move, a corner to scale about the centre, the round handle above the box to
// rotate (Shift snaps to 15 deg). One mouse gesture is one undo step.
#pragma once

#include <QObject>
#include <array>
#include <optional>

#include "widgets/canvas/canvas_layer.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

class PlacementTool : public QObject, public CanvasTool {
  Q_OBJECT
 public:
  static constexpr double kHandleRadiusPx = 6.0;
  static constexpr double kRotateHandleOffsetPx = 28.0;
  static constexpr double kSnapDeg = 15.0;

  explicit PlacementTool(StudioDocument& doc, QObject* parent = nullptr);

  bool mousePress(QMouseEvent* event, const paint::ViewTransform& view) override;
  bool mouseMove(QMouseEvent* event, const paint::ViewTransform& view) override;
  bool mouseRelease(QMouseEvent* event, const paint::ViewTransform& view) override;
  void paintOverlay(QPainter& painter, const paint::ViewTransform& view) override;
  QCursor cursorAt(QPointF widgetPx, const paint::ViewTransform& view) const override;

  enum class Handle { None, Body, Corner, Rotate };
  Handle handleAt(QPointF widgetPx, const paint::ViewTransform& view) const;
  // Corners of the placed drawing's box in the machine frame (counter-clockwise from the
  // work frame's lower-left), or nullopt without a drawing.
  std::optional<std::array<QPointF, 4>> cornersMm() const;

 private:
  void refreshBounds();
  QPointF rotateHandlePx(const paint::ViewTransform& view) const;

  StudioDocument& doc_;
  std::optional<RectMm> workBounds_;  // visible layers, work frame
  Handle active_ = Handle::None;
  int gesture_ = 0;
  Placement start_;
  QPointF startMm_;
};

}  // namespace fivebar::widgets
