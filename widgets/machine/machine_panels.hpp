// SPDX-License-Identifier: GPL-3.0-or-later
// MachinePanels: the widgets of the machine side, built over a session::MachineSide (the session,
// run and jog controllers, app/studio composes both): the panels handed to the window's docks
// (machine, run, jog, console, profile editor), the canvas layer of the executed job, the canvas
// linkage following the machine's reported pose, the recovery bar in the status bar (Reset,
// Unlock, Set reference pose while connected), the machine settings dialog and the quit
// prompt while a job runs. It owns no machine state.
#pragma once

#include <QObject>
#include <functional>

#include "session/machine_side.hpp"
#include "widgets/shell/studio_shell.hpp"

class QAction;
class QDockWidget;

namespace fivebar::widgets {

class CanvasView;
class ConsolePanel;
class JogPanel;
class MachineLayer;
class MachinePanel;
class MachineSettingsDialog;
class ProfileEditor;
class RecoveryBar;
class RunLayer;
class RunPanel;
class StudioDocument;

class MachinePanels : public QObject {
  Q_OBJECT
 public:
  MachinePanels(session::MachineSide& machine, StudioDocument& doc, CanvasView& canvas,
                MachineLayer& machineLayer, QWidget* window);

  // Creates the panels and installs them through the shell (widgets/shell/studio_shell.hpp):
  // docks with their toggles in the Machine menu, then "Machine settings...".
  void install(const StudioShell& shell);

  JogPanel* jogPanel() const { return jog_; }
  RunPanel* runPanel() const { return runPanel_; }
  MachinePanel* machinePanel() const { return machinePanel_; }
  ConsolePanel* consolePanel() const { return console_; }
  ProfileEditor* profileEditor() const { return profile_; }
  // Reset, Unlock, Set reference pose: in the window's status bar while connected.
  RecoveryBar* recoveryBar() const { return recovery_; }
  // "Machine settings...": opens the dialog comparing the board's $$ with the profile (created
  // by install and put in the Machine menu).
  QAction* settingsAction() const { return settingsAction_; }
  MachineSettingsDialog* openSettingsDialog();

  // Asked before the window closes: while a job runs, "Hold, stop and quit" (the run is stopped
  // cleanly and its progress saved, then true) or "Keep running" (false). True when no job runs.
  bool confirmClose();

 private:
  session::MachineSide& machine_;
  StudioDocument& doc_;
  CanvasView& canvas_;
  MachineLayer& machineLayer_;
  QWidget* window_;
  RunLayer* runLayer_ = nullptr;
  MachinePanel* machinePanel_ = nullptr;
  JogPanel* jog_ = nullptr;
  RunPanel* runPanel_ = nullptr;
  ConsolePanel* console_ = nullptr;
  ProfileEditor* profile_ = nullptr;
  RecoveryBar* recovery_ = nullptr;
  QAction* settingsAction_ = nullptr;
  MachineSettingsDialog* settingsDialog_ = nullptr;
};

}  // namespace fivebar::widgets
