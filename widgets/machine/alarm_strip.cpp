// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/alarm_strip.hpp"

#include <QLabel>
#include <QVBoxLayout>

namespace fivebar::widgets {

AlarmStrip::AlarmStrip(session::MachineView& view, QWidget* parent) : QFrame(parent), view_(view) {
  setObjectName(QStringLiteral("alarmStrip"));
  setStyleSheet(QStringLiteral("#alarmStrip { background: #fee2e2; border: 1px solid #dc2626; "
                               "border-radius: 4px; }"));
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);
  layout->addWidget(message_);
  connect(&view_, &session::MachineView::problemChanged, this, &AlarmStrip::refresh);
  connect(&view_, &session::MachineView::connectionChanged, this, &AlarmStrip::refresh);
  refresh();
}

void AlarmStrip::refresh() {
  const session::MachineProblem& p = view_.problem();
  const bool alarm = view_.isConnected() && p.kind == session::MachineProblem::Kind::Alarm;
  setVisible(alarm);
  if (!alarm) return;
  const QString title = p.code > 0 ? tr("Alarm %1: the machine stopped.").arg(p.code)
                                   : tr("Alarm: the machine is locked.");
  message_->setText(QStringLiteral("<b>%1</b> %2<br>%3")
                        .arg(title.toHtmlEscaped(), p.text.toHtmlEscaped(),
                             tr("Reset, Unlock and Set reference pose are in the status bar and "
                                "the Machine panel.")
                                 .toHtmlEscaped()));
}

}  // namespace fivebar::widgets
