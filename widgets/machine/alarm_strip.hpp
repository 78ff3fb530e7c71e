// SPDX-License-Identifier: GPL-3.0-or-later
// The alarm strip: a red line saying that the machine is in alarm, what happened (the drivers'
// code table) and where the way out is (Reset, Unlock, Set reference pose in the status bar and
// the Machine panel's banner); shown only while the session reports an alarm. For panels that
// do not recover themselves (the Run panel). It shows the session's state and has no command.
#pragma once

#include <QFrame>

#include "session/machine_view.hpp"

class QLabel;

namespace fivebar::widgets {

class AlarmStrip : public QFrame {
  Q_OBJECT
 public:
  explicit AlarmStrip(session::MachineView& view, QWidget* parent = nullptr);
  QLabel* message() const { return message_; }

 public slots:
  void refresh();

 private:
  session::MachineView& view_;
  QLabel* message_ = nullptr;
};

}  // namespace fivebar::widgets
