// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/recovery_bar.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include "widgets/machine/machine_dialogs.hpp"
#include "widgets/machine/machine_panel.hpp"

namespace fivebar::widgets {

RecoveryBar::RecoveryBar(session::MachineView& view, session::RecoveryPort& recovery, QWidget* parent)
    : QWidget(parent), view_(view), recovery_(recovery) {
  setObjectName(QStringLiteral("recoveryBar"));
  state_ = new QLabel(this);
  state_->setObjectName(QStringLiteral("recoveryState"));
  reset_ = new QPushButton(tr("Reset"), this);
  reset_->setObjectName(QStringLiteral("recoveryReset"));
  reset_->setToolTip(tr("Soft reset (Ctrl-X): stops everything; the machine keeps its position "
                        "unless it was moving."));
  unlock_ = new QPushButton(tr("Unlock ($X)"), this);
  unlock_->setObjectName(QStringLiteral("recoveryUnlock"));
  unlock_->setToolTip(tr("Leave the alarm state without homing. Only when you know the machine "
                         "stands where the studio shows it."));
  reference_ = new QPushButton(this);
  reference_->setObjectName(QStringLiteral("recoveryReference"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(state_);
  layout->addWidget(reset_);
  layout->addWidget(unlock_);
  layout->addWidget(reference_);

  connect(reset_, &QPushButton::clicked, this, [this] { recovery_.softReset(); });
  connect(unlock_, &QPushButton::clicked, this, [this] { recovery_.unlock(); });
  connect(reference_, &QPushButton::clicked, this, [this] { requestHome(this, view_.profile(), recovery_); });
  connect(&view_, &session::MachineView::problemChanged, this, &RecoveryBar::refresh);
  connect(&view_, &session::MachineView::statusUpdated, this, &RecoveryBar::refresh);
  connect(&view_, &session::MachineView::poseKnownChanged, this, &RecoveryBar::refresh);
  connect(&view_, &session::MachineView::jobActiveChanged, this, &RecoveryBar::refresh);
  connect(&view_, &session::MachineView::connectionChanged, this, &RecoveryBar::refresh);
  refresh();
}

void RecoveryBar::refresh() {
  const bool connected = view_.isConnected();
  setVisible(connected);
  if (!connected) return;
  const session::MachineProblem& p = view_.problem();
  const bool alarm = view_.state() == grbl::MachineState::Alarm || p.kind == session::MachineProblem::Kind::Alarm;
  const bool homing = view_.profile().hasHomingSwitches;
  state_->setText(alarm && p.code > 0 ? tr("Alarm %1").arg(p.code) : stateName(view_.state()));
  state_->setStyleSheet(alarm ? QStringLiteral("color: #dc2626; font-weight: bold") : QString());
  unlock_->setEnabled(alarm && !p.needsReset);
  reference_->setText(homing ? tr("Home ($H)") : tr("Set reference pose"));
  reference_->setToolTip(homing ? tr("Run the homing cycle; the machine moves to its switches.")
                                : tr("Declare that the machine now stands at the profile's home pose "
                                     "(G10 L20)."));
  const grbl::MachineState s = view_.state();
  reference_->setEnabled(!view_.jobActive() && !p.needsReset &&
                         (s == grbl::MachineState::Idle || s == grbl::MachineState::Alarm));
}

}  // namespace fivebar::widgets
