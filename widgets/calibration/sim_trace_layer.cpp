// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/sim_trace_layer.hpp"

#include <QPainter>
#include <QPainterPath>

#include "widgets/calibration/simulated_machine.hpp"
#include "session/machine_session.hpp"

namespace fivebar::widgets::calibration {

namespace {
const QColor kTrace(200, 70, 0);
}

SimTraceLayer::SimTraceLayer(session::MachineSession& session, SimulatedTruth& truth, QObject* parent)
    : QObject(parent), session_(session), truth_(truth) {
  connect(&session_, &session::MachineSession::statusUpdated, this, &SimTraceLayer::refresh);
  connect(&session_, &session::MachineSession::connectionChanged, this, [this](bool connected) {
    if (connected) {
      trace_.clear();
      points_ = 0;
    }
    refresh();
  });
  connect(&truth_, &SimulatedTruth::changed, this, &SimTraceLayer::changed);
}

bool SimTraceLayer::visible() const { return truth_.active() && !trace_.empty(); }

void SimTraceLayer::refresh() {
  if (session_.simulatedTransport() == nullptr) return;  // keep the last drawing
  const auto trace = session_.simulatedDrawnTrace();
  std::size_t points = 0;
  for (const auto& s : trace) points += s.size();
  if (points == points_ && trace.size() == trace_.size()) return;
  trace_ = trace;
  points_ = points;
  emit changed();
}

void SimTraceLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  if (!visible()) return;
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(QPen(kTrace, 1.4));
  painter.setBrush(Qt::NoBrush);
  for (const auto& s : trace_) {
    if (s.empty()) continue;
    QPainterPath path(view.widgetFromMachine(QPointF(s.front().x(), s.front().y())));
    for (std::size_t i = 1; i < s.size(); ++i) path.lineTo(view.widgetFromMachine(QPointF(s[i].x(), s[i].y())));
    painter.drawPath(path);
  }
  // Legend, bottom right.
  const QString text = tr("Drawn by the simulated pen (imperfect machine)");
  const QFontMetrics fm(painter.font());
  const double w = fm.horizontalAdvance(text) + 42.0, h = fm.height() + 10.0;
  const QRectF box(painter.viewport().width() - w - 10, painter.viewport().height() - h - 10, w, h);
  painter.setPen(QColor(160, 160, 160));
  painter.setBrush(QColor(255, 255, 255, 225));
  painter.drawRect(box);
  const double y = box.center().y();
  painter.setPen(QPen(kTrace, 2.0));
  painter.drawLine(QPointF(box.left() + 8, y), QPointF(box.left() + 30, y));
  painter.setPen(Qt::black);
  painter.drawText(QPointF(box.left() + 36, y + fm.ascent() / 2.0 - 1), text);
  painter.restore();
}

}  // namespace fivebar::widgets::calibration
