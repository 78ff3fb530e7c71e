#include "widgets/machine/machine_ui.hpp"

#include <QAction>
#include <QDir>
#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QMessageBox>
#include <QPushButton>
#include <QThread>
#include <QStandardPaths>

#include "widgets/canvas/canvas_view.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"
#include "widgets/panels/profile_editor.hpp"
#include "widgets/machine/run_layer.hpp"
#include "widgets/machine/run_panel.hpp"

namespace fivebar::widgets {

MachineUi::MachineUi(StudioDocument& doc, PreviewController& preview, CanvasView& canvas,
                     MachineLayer& machineLayer, QWidget* window)
    : QObject(window),
      doc_(doc),
      canvas_(canvas),
      machineLayer_(machineLayer),
      window_(window),
      session_(doc),
      run_(doc, preview, session_) {
  setObjectName(QStringLiteral("machineUi"));
  runLayer_ = new RunLayer(run_, session_, this);
  canvas_.addLayer(runLayer_);
  connect(runLayer_, &RunLayer::changed, &canvas_, qOverload<>(&QWidget::update));
  // The machine drawn on the canvas follows the connected machine's reported pose.
  connect(&session_, &MachineSession::statusUpdated, this,
          [this] { machineLayer_.setExternalAngles(session_.motorAngles()); });
  connect(&session_, &MachineSession::connectionChanged, this, [this](bool connected) {
    if (!connected) machineLayer_.setExternalAngles(std::nullopt);
  });
}

void MachineUi::addPanels(const AddDock& addDock) {
  machinePanel_ = new MachinePanel(session_, window_);
  jog_ = new JogPanel(session_, window_);
  jog_->attachCanvas(&canvas_);
  runPanel_ = new RunPanel(run_, session_, window_);
  console_ = new ConsolePanel(session_, window_);
  profile_ = new ProfileEditor(doc_, window_);
  addDock(machinePanel_, tr("Machine"), QStringLiteral("dockMachine"), Qt::RightDockWidgetArea);
  addDock(runPanel_, tr("Run"), QStringLiteral("dockRun"), Qt::RightDockWidgetArea);
  addDock(jog_, tr("Jog"), QStringLiteral("dockJog"), Qt::RightDockWidgetArea);
  addDock(console_, tr("Console"), QStringLiteral("dockConsole"), Qt::BottomDockWidgetArea);
  addDock(profile_, tr("Machine profile"), QStringLiteral("dockProfile"), Qt::LeftDockWidgetArea);
  machinePanel_->setOpenSettings([this] { openSettingsDialog(); });
  runPanel_->setOpenSettings([this] { openSettingsDialog(); });
  settingsAction_ = new QAction(tr("Machine &settings..."), this);
  settingsAction_->setObjectName(QStringLiteral("actionMachineSettings"));
  connect(settingsAction_, &QAction::triggered, this, [this] { openSettingsDialog(); });
}

// Shows the (single) settings dialog and reads the board when connected. Backups go to the
// application's data folder, "settings-backups".
MachineSettingsDialog* MachineUi::openSettingsDialog() {
  if (settingsDialog_ == nullptr) {
    const QString dir = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                            .filePath(QStringLiteral("settings-backups"));
    settingsDialog_ = new MachineSettingsDialog(session_, dir, window_);
  }
  settingsDialog_->show();
  settingsDialog_->raise();
  if (session_.isConnected()) settingsDialog_->readBoard();
  return settingsDialog_;
}

bool MachineUi::confirmClose() {
  if (!run_.running()) return true;
  QMessageBox box(QMessageBox::Warning, tr("A job is running"),
                  tr("The machine is drawing \"%1\". Quitting the studio would leave it without "
                     "its stream of lines.\n\nHold, stop and quit: the machine stops cleanly and "
                     "the progress is saved, so you can resume later.")
                      .arg(run_.drawingName()),
                  QMessageBox::NoButton, window_);
  box.setObjectName(QStringLiteral("quitWhileRunning"));
  QPushButton* stop = box.addButton(tr("Hold, stop and quit"), QMessageBox::DestructiveRole);
  stop->setObjectName(QStringLiteral("stopAndQuit"));
  QPushButton* keep = box.addButton(tr("Keep running"), QMessageBox::RejectRole);
  keep->setObjectName(QStringLiteral("keepRunning"));
  box.setDefaultButton(keep);
  box.exec();
  if (box.clickedButton() != stop) return false;
  run_.hold();
  run_.stop();
  // The stop sequence (hold, reset, unlock) runs on the event loop; its end saves the progress.
  QElapsedTimer clock;
  clock.start();
  while (run_.running() && clock.elapsed() < kStopWaitMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QThread::msleep(5);
  }
  return true;
}

bool MachineUi::connectSimulated(double speedup) {
  QString error;
  if (!session_.connectSimulated(speedup, sim::Fault{}, &error)) return false;
  // The simulated board starts at MPos 0,0 like a real one after power-up: the demo declares
  // the pose it stands in the home pose (G10 L20, shown in the machine console).
  session_.setReferencePose();
  return true;
}

}  // namespace fivebar::widgets
