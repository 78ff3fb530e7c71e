// The alarm / error banner: shown while MachineSession reports a problem, it says what happened
// and what to do (the drivers' code tables) and offers the way out: Reset (when the board
// demands one), Unlock ($X), Home ($H) or Set reference pose, and Dismiss for an error answer.
#pragma once

#include <QFrame>

#include "session/machine_session.hpp"

class QLabel;
class QPushButton;

namespace fivebar::widgets {

class MachineBanner : public QFrame {
  Q_OBJECT
 public:
  explicit MachineBanner(session::MachineSession& session, QWidget* parent = nullptr);

  QLabel* message() const { return message_; }
  QPushButton* unlockButton() const { return unlock_; }
  QPushButton* homeButton() const { return home_; }
  QPushButton* resetButton() const { return reset_; }
  QPushButton* dismissButton() const { return dismiss_; }

 public slots:
  void refresh();

 private:
  session::MachineSession& session_;
  QLabel* title_ = nullptr;
  QLabel* message_ = nullptr;
  QPushButton* unlock_ = nullptr;
  QPushButton* home_ = nullptr;
  QPushButton* reset_ = nullptr;
  QPushButton* dismiss_ = nullptr;
};

}  // namespace fivebar::widgets
