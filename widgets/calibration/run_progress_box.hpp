// SPDX-License-Identifier: GPL-3.0-or-later
// The progress of a pattern drawn by the wizard, shown as the Run panel shows a job: a bar with
// "N % (line N of M)", the time left by the planned time line, and Stop (the same clean stop:
// feed hold, reset with the position kept, pen up). It watches a session::RunController and
// never stores the run's state.
#pragma once

#include <QPointer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace fivebar::session {
class RunController;
}

namespace fivebar::widgets::calibration {

class RunProgressBox : public QWidget {
  Q_OBJECT
 public:
  explicit RunProgressBox(QWidget* parent = nullptr);
  // Follows `run` from now on (shown while it runs and after it ended; hidden before).
  void watch(session::RunController* run);

  QProgressBar* bar() const { return bar_; }
  QLabel* timeLeft() const { return eta_; }
  QPushButton* stopButton() const { return stop_; }

 private:
  void refresh();
  QPointer<session::RunController> run_;
  QProgressBar* bar_ = nullptr;
  QLabel* eta_ = nullptr;
  QPushButton* stop_ = nullptr;
};

}  // namespace fivebar::widgets::calibration
