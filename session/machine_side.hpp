// SPDX-License-Identifier: GPL-3.0-or-later
// MachineSide: the machine side of the studio composed in one place, without widgets: the
// MachineSession (the only door to the machine), the RunController streaming jobs through it and
// the JogController behind the jog panel and the keyboard, and the ConsolePort (the console's view). The studio creates one next to its
// document (app/studio/main_window.cpp) and hands its parts to the panels; tests and a future
// headless front end use it the same way.
#pragma once

#include <QObject>

#include "session/board_preflight.hpp"
#include "session/console_port.hpp"
#include "session/jog_controller.hpp"
#include "session/machine_session.hpp"
#include "session/machine_view.hpp"
#include "session/run_controller.hpp"
#include "session/studio_inputs.hpp"

namespace fivebar::session {

class MachineSide : public QObject {
  Q_OBJECT
 public:
  static constexpr int kStopWaitMs = 8000;  // longest wait for the stop sequence on quit

  // inputs must outlive this object.
  explicit MachineSide(const StudioInputs& inputs, QObject* parent = nullptr);

  MachineSession& session() { return session_; }
  // The narrow doors the panels are handed (session/machine_ports.hpp): the read-only view and
  // one port per kind of command.
  MachineView& view() { return view_; }
  ConnectionPort& connection() { return session_; }
  RecoveryPort& recovery() { return session_; }
  JogPort& jogPort() { return session_; }
  BoardSettingsPort& boardSettings() { return session_; }
  RunController& run() { return run_; }
  JogController& jog() { return jog_; }
  // The console panel's narrow view of the session.
  ConsolePort& console() { return console_; }
  // The planned job against the board's soft limits, for the pre-flight problem list.
  BoardPreflight& boardPreflight() { return preflight_; }

  // Connects the built-in simulated machine and declares the pose it stands in the profile's home
  // pose (the --demo start, like a user pressing "Set reference pose"); false with the reason in
  // *error (and in the console).
  bool connectSimulated(double speedup = 1.0, QString* error = nullptr);

  // Quitting while a job runs: hold, stop (the runner's stop sequence saves the progress) and
  // wait on the event loop until the run has ended, at most kStopWaitMs. True when no job runs
  // any more.
  bool stopRunForQuit();

 private:
  MachineSession session_;
  MachineView view_;
  RunController run_;
  JogController jog_;
  ConsolePort console_;
  BoardPreflight preflight_;
};

}  // namespace fivebar::session
