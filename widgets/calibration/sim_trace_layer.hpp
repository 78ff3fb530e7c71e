// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas layer of what the simulated machine's pen really drew (MachineSession::
// simulatedDrawnTrace, machine frame) while the studio's simulated machine is imperfect
// (SimulatedTruth): beside the plan, so the maker sees how the imperfect machine bends a drawing.
// The last drawing stays shown after a disconnect (it is on the paper); a new connection starts a
// new one. Copies the trace when a status report shows it grew; paints only the copy.
#pragma once

#include <QObject>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "widgets/canvas/canvas_layer.hpp"

namespace fivebar::session {
class MachineSession;
}  // namespace fivebar::session

namespace fivebar::widgets {
}

namespace fivebar::widgets::calibration {

class SimulatedTruth;

class SimTraceLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  SimTraceLayer(session::MachineSession& session, SimulatedTruth& truth, QObject* parent = nullptr);
  void paint(QPainter& painter, const paint::ViewTransform& view) override;
  // What is shown (empty while the simulated machine is perfect).
  const std::vector<std::vector<Vec2>>& trace() const { return trace_; }
  bool visible() const;
  // Reads the session's trace again (called on every status report).
  void refresh();

 signals:
  void changed();

 private:
  session::MachineSession& session_;
  SimulatedTruth& truth_;
  std::vector<std::vector<Vec2>> trace_;
  std::size_t points_ = 0;
};

}  // namespace fivebar::widgets::calibration
