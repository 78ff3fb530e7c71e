// SPDX-License-Identifier: GPL-3.0-or-later
// The alarm / error banner: shown while the session (MachineView) reports a problem, it says what happened
// and what to do (the drivers' code tables) and offers the way out: Reset (when the board
// demands one), Unlock ($X), Home ($H) or Set reference pose, and Dismiss for an error answer.
#pragma once

#include <QFrame>

#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"

class QLabel;
class QPushButton;

namespace fivebar::widgets {

class MachineBanner : public QFrame {
  Q_OBJECT
 public:
  // Sees the session's state and may only recover (unlock, reset, home, reference, dismiss).
  MachineBanner(session::MachineView& view, session::RecoveryPort& recovery, QWidget* parent = nullptr);

  QLabel* message() const { return message_; }
  QPushButton* unlockButton() const { return unlock_; }
  QPushButton* homeButton() const { return home_; }
  QPushButton* resetButton() const { return reset_; }
  QPushButton* dismissButton() const { return dismiss_; }

 public slots:
  void refresh();

 private:
  void showPoseUnknown(const QString& why);
  void labelHomeButton();
  session::MachineView& view_;
  session::RecoveryPort& recovery_;
  QLabel* title_ = nullptr;
  QLabel* message_ = nullptr;
  QPushButton* unlock_ = nullptr;
  QPushButton* home_ = nullptr;
  QPushButton* reset_ = nullptr;
  QPushButton* dismiss_ = nullptr;
};

}  // namespace fivebar::widgets
