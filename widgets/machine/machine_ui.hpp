// The machine side of the studio, composed in one place so the main window needs only a few
// lines: the MachineSession (the only door to the machine), the run controller, the canvas layer
// of the executed job, the keyboard jog and go-to on the canvas, the machine pose on the canvas,
// and the panels (machine, jog, run, console, profile editor) handed to the window's docks.
#pragma once

#include <QObject>
#include <functional>

#include "widgets/machine/machine_session.hpp"
#include "widgets/machine/run_controller.hpp"

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
class RunLayer;
class RunPanel;

class MachineUi : public QObject {
  Q_OBJECT
 public:
  // Docks a panel in the window: (panel, title, objectName, area) -> the dock.
  using AddDock = std::function<QDockWidget*(QWidget*, const QString&, const QString&, Qt::DockWidgetArea)>;

  MachineUi(StudioDocument& doc, PreviewController& preview, CanvasView& canvas,
            MachineLayer& machineLayer, QWidget* window);

  // Creates the panels and hands them to addDock.
  void addPanels(const AddDock& addDock);
  // Connects the built-in simulated machine (the --demo start); false with a console message.
  bool connectSimulated(double speedup = 1.0);

  MachineSession& session() { return session_; }
  RunController& run() { return run_; }
  JogPanel* jogPanel() const { return jog_; }
  RunPanel* runPanel() const { return runPanel_; }
  MachinePanel* machinePanel() const { return machinePanel_; }
  // "Machine settings...": opens the dialog comparing the board's $$ with the profile (created
  // by addPanels; the window puts it in its Machine menu).
  QAction* settingsAction() const { return settingsAction_; }
  MachineSettingsDialog* openSettingsDialog();

  // Asked before the window closes: while a job runs, "Hold, stop and quit" (the run is stopped
  // cleanly and its progress saved, then true) or "Keep running" (false). True when no job runs.
  bool confirmClose();
  static constexpr int kStopWaitMs = 8000;  // longest wait for the stop sequence on quit

 private:
  StudioDocument& doc_;
  CanvasView& canvas_;
  MachineLayer& machineLayer_;
  QWidget* window_;
  MachineSession session_;
  RunController run_;
  RunLayer* runLayer_ = nullptr;
  MachinePanel* machinePanel_ = nullptr;
  JogPanel* jog_ = nullptr;
  RunPanel* runPanel_ = nullptr;
  ConsolePanel* console_ = nullptr;
  ProfileEditor* profile_ = nullptr;
  QAction* settingsAction_ = nullptr;
  MachineSettingsDialog* settingsDialog_ = nullptr;
};

}  // namespace fivebar::widgets
