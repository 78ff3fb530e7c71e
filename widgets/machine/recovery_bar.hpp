// SPDX-License-Identifier: GPL-3.0-or-later
// The recovery bar: Reset, Unlock ($X) and Set reference pose (Home ($H) on a machine with
// homing switches) with the machine's state, always at hand while a machine is connected
// (MachinePanels puts it in the window's status bar), whichever panel is in front. Hidden while
// no machine is connected. It shows the session's state (MachineView) and may only recover
// (RecoveryPort); the questions are those of the alarm banner (machine_dialogs.hpp).
#pragma once

#include <QWidget>

#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"

class QLabel;
class QPushButton;

namespace fivebar::widgets {

class RecoveryBar : public QWidget {
  Q_OBJECT
 public:
  RecoveryBar(session::MachineView& view, session::RecoveryPort& recovery, QWidget* parent = nullptr);

  QLabel* stateLabel() const { return state_; }
  QPushButton* resetButton() const { return reset_; }
  QPushButton* unlockButton() const { return unlock_; }
  QPushButton* referenceButton() const { return reference_; }

 public slots:
  void refresh();

 private:
  session::MachineView& view_;
  session::RecoveryPort& recovery_;
  QLabel* state_ = nullptr;
  QPushButton* reset_ = nullptr;
  QPushButton* unlock_ = nullptr;
  QPushButton* reference_ = nullptr;
};

}  // namespace fivebar::widgets
