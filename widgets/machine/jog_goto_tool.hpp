// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas tool for "go to": a click on the canvas plans a checked move of the pen to that point
// (drivers/jog planGoTo: pen up and a safe travel at rapid rate, every leg checked) and draws the path the pen will take;
// nothing moves until the move is confirmed (confirm(), Enter in the jog panel). A refused target
// is drawn in red with the reason.
#pragma once

#include <QObject>
#include <optional>

#include "widgets/canvas/canvas_layer.hpp"
#include "session/machine_ports.hpp"
#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"

namespace fivebar::widgets {

class GoToTool : public QObject, public CanvasTool {
  Q_OBJECT
 public:
  // Sees the session's state and may only plan and send checked moves (JogPort).
  GoToTool(session::MachineView& view, session::JogPort& jog, QObject* parent = nullptr);

  // Plans a go-to to a machine-frame point (what a click does).
  void pick(QPointF machineMm);
  const std::optional<jog::JogPlan>& pending() const { return pending_; }
  std::optional<QPointF> target() const { return target_; }

  bool mousePress(QMouseEvent* event, const paint::ViewTransform& view) override;
  bool mouseMove(QMouseEvent* event, const paint::ViewTransform& view) override;
  bool mouseRelease(QMouseEvent* event, const paint::ViewTransform& view) override;
  void paintOverlay(QPainter& painter, const paint::ViewTransform& view) override;
  QCursor cursorAt(QPointF widgetPx, const paint::ViewTransform& view) const override;

 public slots:
  // Sends the pending move; false when there is none or the machine refuses it.
  bool confirm();
  void cancel();

 signals:
  // A target was picked: ok when the move can be confirmed; text says where / why not.
  void picked(bool ok, const QString& text);
  void cleared();
  // The confirmed move was sent: the go-to is done (the tool is disarmed by its owner).
  void moveSent();
  void repaintNeeded();

 private:
  session::MachineView& view_;
  session::JogPort& jog_;
  std::optional<QPointF> target_;
  std::optional<jog::JogPlan> pending_;
  std::vector<Vec2> pendingPathMm_;  // the pen's path of pending_ (machine frame)
  std::optional<QPointF> hoverMm_;
};

}  // namespace fivebar::widgets
