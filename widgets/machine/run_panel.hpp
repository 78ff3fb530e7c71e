// SPDX-License-Identifier: GPL-3.0-or-later
// The run panel: start, hold, continue and stop the planned job on the machine, feed and rapid
// overrides (override_controls.hpp), a progress bar with the executed lines and the time left
// (under the reported overrides), what happened when a run ended, and the offer to
// resume an interrupted run (also after a restart: the progress file beside the job); an alarm
// strip on top while the machine is in alarm.
#pragma once

#include <QWidget>

#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"
#include "session/run_controller.hpp"

#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;

namespace fivebar::widgets {

class AlarmStrip;
class OverrideControls;

class RunPanel : public QWidget {
  Q_OBJECT
 public:
  // Runs through the RunController; sees the session's state (view) and may ask it to read the
  // board's settings before Start (settings).
  RunPanel(session::RunController& run, session::MachineView& view, session::BoardSettingsPort& settings,
           QWidget* parent = nullptr);

  QPushButton* startButton() const { return start_; }
  QPushButton* holdButton() const { return hold_; }
  QPushButton* continueButton() const { return continue_; }
  QPushButton* stopButton() const { return stop_; }
  QPushButton* resumeButton() const { return resume_; }
  QProgressBar* progressBar() const { return progress_; }
  QLabel* messageLabel() const { return message_; }
  QLabel* etaLabel() const { return eta_; }
  QLabel* stateLabel() const { return state_; }
  QLabel* resumeLabel() const { return resumeInfo_; }
  // Shown while the machine is in alarm (widgets/machine/alarm_strip.hpp).
  AlarmStrip* alarmStrip() const { return alarm_; }
  OverrideControls* overrideControls() const { return overrides_; }
  // What "Write the profile's settings..." in the settings question opens.
  void setOpenSettings(std::function<void()> open) { openSettings_ = std::move(open); }

 public slots:
  void refresh();
  void refreshProgress();

 private:
  void startClicked();
  void resumeClicked();
  // The questions before Start; false when the user (or the board's state) says no.
  bool confirmDiscardResume();
  bool confirmSettings();

  session::RunController& run_;
  session::MachineView& view_;
  session::BoardSettingsPort& settings_;
  QPushButton* start_ = nullptr;
  QPushButton* hold_ = nullptr;
  QPushButton* continue_ = nullptr;
  QPushButton* stop_ = nullptr;
  QPushButton* resume_ = nullptr;
  QLabel* resumeInfo_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* eta_ = nullptr;
  QLabel* message_ = nullptr;
  AlarmStrip* alarm_ = nullptr;
  OverrideControls* overrides_ = nullptr;
  std::function<void()> openSettings_;
};

// "1 h 02 min", "3 min 05 s", "42 s" (translated units); "–" when unknown (< 0).
QString formatTimeLeft(double seconds);

}  // namespace fivebar::widgets
