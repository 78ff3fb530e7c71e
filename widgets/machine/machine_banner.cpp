// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/machine_banner.hpp"

#include "widgets/machine/machine_dialogs.hpp"

#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace fivebar::widgets {

MachineBanner::MachineBanner(session::MachineView& view, session::RecoveryPort& recovery, QWidget* parent)
    : QFrame(parent), view_(view), recovery_(recovery) {
  setObjectName(QStringLiteral("machineBanner"));
  setFrameShape(QFrame::StyledPanel);
  title_ = new QLabel(this);
  QFont bold = title_->font();
  bold.setBold(true);
  title_->setFont(bold);
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  reset_ = new QPushButton(tr("Reset"), this);
  reset_->setToolTip(tr("Soft reset (Ctrl-X): stops everything; the machine keeps its position "
                        "unless it was moving."));
  unlock_ = new QPushButton(tr("Unlock ($X)"), this);
  unlock_->setToolTip(tr("Leave the alarm state without homing. Only when you know the machine "
                         "stands where the studio shows it."));
  home_ = new QPushButton(this);
  dismiss_ = new QPushButton(tr("Dismiss"), this);

  // Two columns, so the banner fits a narrow dock.
  auto* buttons = new QGridLayout;
  buttons->addWidget(reset_, 0, 0);
  buttons->addWidget(unlock_, 0, 1);
  buttons->addWidget(home_, 1, 0, 1, 2);
  buttons->addWidget(dismiss_, 2, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 6, 8, 6);
  layout->addWidget(title_);
  layout->addWidget(message_);
  layout->addLayout(buttons);

  connect(reset_, &QPushButton::clicked, this, [this] { recovery_.softReset(); });
  connect(unlock_, &QPushButton::clicked, this, [this] { recovery_.unlock(); });
  connect(home_, &QPushButton::clicked, this, [this] { requestHome(this, view_.profile(), recovery_); });
  connect(dismiss_, &QPushButton::clicked, this, [this] { recovery_.dismissProblem(); });
  connect(&view_, &session::MachineView::problemChanged, this, &MachineBanner::refresh);
  connect(&view_, &session::MachineView::connectionChanged, this, &MachineBanner::refresh);
  connect(&view_, &session::MachineView::poseKnownChanged, this, &MachineBanner::refresh);
  refresh();
}

void MachineBanner::refresh() {
  const session::MachineProblem& p = view_.problem();
  const bool alarm = p.kind == session::MachineProblem::Kind::Alarm;
  // No alarm or error: the banner asks for the reference while the position is not known.
  const QString doubt = view_.isConnected() && !view_.poseKnown() ? view_.poseDoubtText() : QString();
  if (p.kind == session::MachineProblem::Kind::None && !doubt.isEmpty() && view_.lastStatus() != nullptr) {
    showPoseUnknown(doubt);
    return;
  }
  setVisible(p.kind != session::MachineProblem::Kind::None);
  setStyleSheet(alarm ? QStringLiteral("#machineBanner { background: #fee2e2; border: 1px solid #dc2626; "
                                       "border-radius: 4px; }")
                      : QStringLiteral("#machineBanner { background: #fef3c7; border: 1px solid #d97706; "
                                       "border-radius: 4px; }"));
  if (alarm) {
    title_->setText(p.code > 0 ? tr("Alarm %1: the machine stopped").arg(p.code)
                               : tr("Alarm: the machine is locked"));
  } else {
    title_->setText(tr("Error %1: a command was rejected").arg(p.code));
  }
  QString text = p.text;
  if (alarm && p.needsReset) text += QLatin1Char('\n') + tr("The board waits for a reset first: press Reset, then Unlock.");
  message_->setText(text);
  labelHomeButton();
  reset_->setVisible(alarm);
  unlock_->setVisible(alarm);
  unlock_->setEnabled(!p.needsReset);
  home_->setVisible(alarm);
  home_->setEnabled(!p.needsReset);
  dismiss_->setVisible(!alarm);
}

// Home with switches, else Set reference pose, with what each does.
void MachineBanner::labelHomeButton() {
  const bool homing = view_.profile().hasHomingSwitches;
  home_->setText(homing ? tr("Home ($H)") : tr("Set reference pose"));
  home_->setToolTip(homing ? tr("Run the homing cycle; the machine moves to its switches.")
                           : tr("Declare that the machine now stands at the profile's home pose "
                                "(G10 L20)."));
}

void MachineBanner::showPoseUnknown(const QString& why) {
  setVisible(true);
  setStyleSheet(QStringLiteral("#machineBanner { background: #fef3c7; border: 1px solid #d97706; "
                               "border-radius: 4px; }"));
  title_->setText(tr("Position unknown: nothing moves until it is set"));
  message_->setText(why);
  labelHomeButton();
  reset_->setVisible(false);
  unlock_->setVisible(false);
  home_->setVisible(true);
  home_->setEnabled(true);
  dismiss_->setVisible(false);
}

}  // namespace fivebar::widgets
