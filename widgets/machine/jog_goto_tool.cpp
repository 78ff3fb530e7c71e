// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/jog_goto_tool.hpp"

#include "session/go_to.hpp"

#include <QLocale>
#include <QPainterPath>

#include "paint/studio_palette.hpp"

namespace fivebar::widgets {

GoToTool::GoToTool(session::MachineView& view, session::JogPort& jog, QObject* parent)
    : QObject(parent), view_(view), jog_(jog) {
  connect(&view_, &session::MachineView::connectionChanged, this, [this] { cancel(); });
}

void GoToTool::pick(QPointF machineMm) {
  target_ = machineMm;
  const auto start = jog_.jogStart();
  if (!start || !view_.isConnected()) {
    pending_.reset();
    pendingPathMm_.clear();
    emit picked(false, tr("Connect the machine first: its position is not known."));
    emit repaintNeeded();
    return;
  }
  pending_ = session::planGoTo(jog_, view_.profile(), *start, Vec2(machineMm.x(), machineMm.y()));
  pendingPathMm_ = session::goToPenPathMm(view_.profile(), *start, *pending_);
  if (pending_->ok()) {
    emit picked(true, tr("Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).", nullptr,
                         int(pending_->targets.size()))
                          .arg(QLocale().toString(machineMm.x(), 'f', 1))
                          .arg(QLocale().toString(machineMm.y(), 'f', 1)));
  } else {
    emit picked(false, tr("Cannot go there: %1").arg(session::MachineSession::studioText(pending_->reason)));
  }
  emit repaintNeeded();
}

bool GoToTool::confirm() {
  if (!pending_ || !pending_->ok()) return false;
  const bool sent = jog_.sendJog(*pending_);
  if (sent) {
    cancel();
    emit moveSent();  // one click, one move: the tool disarms (the jog panel unchecks Go to)
  }
  return sent;
}

void GoToTool::cancel() {
  const bool had = target_.has_value();
  target_.reset();
  pending_.reset();
  if (had) {
    emit cleared();
    emit repaintNeeded();
  }
}

bool GoToTool::mousePress(QMouseEvent* event, const paint::ViewTransform& view) {
  if (event->button() != Qt::LeftButton) return false;
  pick(view.machineFromWidget(event->position()));
  return true;
}

bool GoToTool::mouseMove(QMouseEvent* event, const paint::ViewTransform& view) {
  hoverMm_ = view.machineFromWidget(event->position());
  return !target_.has_value();  // the hover line follows the cursor until a target is picked
}

bool GoToTool::mouseRelease(QMouseEvent*, const paint::ViewTransform&) { return false; }

void GoToTool::paintOverlay(QPainter& painter, const paint::ViewTransform& view) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  const auto pen = view_.penMm();
  if (!target_ && hoverMm_ && pen) {  // a light hint line from the pen to the cursor
    painter.setPen(QPen(paint::palette::travel(), 1.0, Qt::DotLine));
    painter.drawLine(view.widgetFromMachine(QPointF(pen->x(), pen->y())),
                     view.widgetFromMachine(*hoverMm_));
  }
  if (target_) {
    const bool ok = pending_ && pending_->ok();
    const QColor colour = ok ? paint::palette::selection() : paint::palette::problem();
    if (pending_ && pendingPathMm_.size() > 1) {
      QPainterPath path;
      path.moveTo(view.widgetFromMachine(QPointF(pendingPathMm_[0].x(), pendingPathMm_[0].y())));
      for (const Vec2& p : pendingPathMm_) path.lineTo(view.widgetFromMachine(QPointF(p.x(), p.y())));
      painter.setPen(QPen(colour, 2.0, Qt::DashLine));
      painter.drawPath(path);
    }
    const QPointF t = view.widgetFromMachine(*target_);
    painter.setPen(QPen(colour, 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(t, 7.0, 7.0);
    painter.drawLine(t - QPointF(11, 0), t + QPointF(11, 0));
    painter.drawLine(t - QPointF(0, 11), t + QPointF(0, 11));
  }
  painter.restore();
}

QCursor GoToTool::cursorAt(QPointF, const paint::ViewTransform&) const { return QCursor(Qt::CrossCursor); }

}  // namespace fivebar::widgets
