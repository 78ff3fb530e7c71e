// SPDX-License-Identifier: GPL-3.0-or-later
// The narrow doors of the machine session, one per kind of panel (the house of issue 11): a panel
// is handed only the ports it needs by the composition root (widgets/machine/machine_panels.cpp
// over session::MachineSide), so it cannot reach the rest of the MachineSession (transport, link,
// console, other panels' commands). MachineSession implements every port; the read-only state
// and its signals are MachineView (session/machine_view.hpp); the console has ConsolePort.
//   machine panel:      MachineView + ConnectionPort + RecoveryPort
//   alarm banner:       MachineView + RecoveryPort
//   jog panel, go-to:   MachineView + JogPort + RecoveryPort (reference / home), JogController
//   run panel:          RunController + MachineView + BoardSettingsPort
//   run layer:          RunController + MachineView
//   settings dialog:    MachineView + BoardSettingsPort
#pragma once

#include <QString>
#include <memory>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/sim/sim_machine.hpp"

namespace fivebar::session {

// Opening and closing the link (MachineSession::connectSimulated and friends).
class ConnectionPort {
 public:
  virtual ~ConnectionPort() = default;
  virtual bool connectSimulated(double speedup, const sim::Fault& fault, QString* error) = 0;
  virtual bool connectSerial(const QString& portPath, int baudRate, QString* error) = 0;
  virtual void disconnectMachine() = 0;
};

// Getting out of an alarm or error, and declaring where the machine stands.
class RecoveryPort {
 public:
  virtual ~RecoveryPort() = default;
  virtual void unlock() = 0;
  virtual void softReset() = 0;
  virtual void home() = 0;
  virtual void setReferencePose() = 0;
  virtual void dismissProblem() = 0;
};

// Host-planned moves: jogs, go-to, go to home pose, frame, pen up / down; every move through the one
// motion check (MachineSession::boardChecked, sendJog).
class JogPort {
 public:
  virtual ~JogPort() = default;
  virtual bool canJog() const = 0;
  virtual std::optional<JointAngles> jogStart() const = 0;
  virtual jog::JogPlan boardChecked(jog::JogPlan plan, bool clip) const = 0;
  virtual bool sendJog(const jog::JogPlan& plan) = 0;
  virtual bool goToHomePose(QString* why = nullptr) = 0;
  // The planned job's outline traced pen up (session/frame.hpp); canFrame: connected, the pose
  // known, the machine idle and a job planned.
  virtual bool canFrame() const = 0;
  virtual bool frameJob(QString* why = nullptr) = 0;
  virtual bool penUp() = 0;
  virtual bool penDown() = 0;
};

// The board's $ settings: read them (the session keeps them, MachineView shows the differences),
// or a SettingsSync on the link to read and write them one at a time (nullptr when not connected).
class BoardSettingsPort {
 public:
  virtual ~BoardSettingsPort() = default;
  virtual void readBoardSettings() = 0;
  virtual std::unique_ptr<setup::SettingsSync> makeSettingsSync() = 0;
};

}  // namespace fivebar::session
