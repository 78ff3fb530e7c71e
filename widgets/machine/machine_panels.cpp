// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/machine_panels.hpp"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>

#include "widgets/canvas/canvas_view.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"
#include "widgets/machine/recovery_bar.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/panels/profile_editor.hpp"
#include "widgets/machine/run_layer.hpp"
#include "widgets/machine/run_panel.hpp"

namespace fivebar::widgets {

MachinePanels::MachinePanels(session::MachineSide& machine, StudioDocument& doc, CanvasView& canvas,
                             MachineLayer& machineLayer, QWidget* window)
    : QObject(window), machine_(machine), doc_(doc), canvas_(canvas), machineLayer_(machineLayer), window_(window) {
  session::MachineView& view = machine_.view();
  runLayer_ = new RunLayer(machine_.run(), view, this);
  canvas_.addLayer(runLayer_);
  connect(runLayer_, &RunLayer::changed, &canvas_, qOverload<>(&QWidget::update));
  // The machine drawn on the canvas follows the connected machine's reported pose.
  const auto follow = [this] {
    const session::MachineView& v = machine_.view();
    if (v.isConnected() && !v.poseKnown() && v.lastStatus() != nullptr) machineLayer_.setExternalPoseUnknown();
    else machineLayer_.setExternalAngles(v.motorAngles());
  };
  connect(&view, &session::MachineView::statusUpdated, this, follow);
  connect(&view, &session::MachineView::poseKnownChanged, this, follow);
  connect(&view, &session::MachineView::connectionChanged, this, [this](bool connected) {
    if (!connected) machineLayer_.setExternalAngles(std::nullopt);
  });
}

void MachinePanels::install(const StudioShell& shell) {
  // Each panel gets the session's read-only view and only the ports it needs.
  session::MachineView& view = machine_.view();
  machinePanel_ = new MachinePanel(view, machine_.connection(), machine_.recovery(), window_);
  jog_ = new JogPanel(view, machine_.jogPort(), machine_.recovery(), machine_.jog(), window_);
  jog_->attachCanvas(&canvas_);
  runPanel_ = new RunPanel(machine_.run(), view, machine_.boardSettings(), window_);
  console_ = new ConsolePanel(machine_.console(), window_);
  profile_ = new ProfileEditor(doc_, window_);
  shell.addPanel(machinePanel_, tr("Machine"), QStringLiteral("dockMachine"), Qt::RightDockWidgetArea, shell.machineMenu);
  shell.addPanel(runPanel_, tr("Run"), QStringLiteral("dockRun"), Qt::RightDockWidgetArea, shell.machineMenu);
  shell.addPanel(jog_, tr("Jog"), QStringLiteral("dockJog"), Qt::RightDockWidgetArea, shell.machineMenu);
  shell.addPanel(console_, tr("Console"), QStringLiteral("dockConsole"), Qt::BottomDockWidgetArea, shell.machineMenu);
  shell.addPanel(profile_, tr("Machine profile"), QStringLiteral("dockProfile"), Qt::LeftDockWidgetArea, shell.machineMenu);
  recovery_ = new RecoveryBar(view, machine_.recovery(), window_);
  if (shell.statusBar != nullptr) shell.statusBar->addPermanentWidget(recovery_);
  machinePanel_->setOpenSettings([this] { openSettingsDialog(); });
  runPanel_->setOpenSettings([this] { openSettingsDialog(); });
  settingsAction_ = new QAction(tr("Machine &settings..."), this);
  settingsAction_->setObjectName(QStringLiteral("actionMachineSettings"));
  connect(settingsAction_, &QAction::triggered, this, [this] { openSettingsDialog(); });
  shell.machineMenu->addSeparator();
  shell.machineMenu->addAction(settingsAction_);
}

// Shows the (single) settings dialog and reads the board when connected. Backups go to the
// application's data folder, "settings-backups".
MachineSettingsDialog* MachinePanels::openSettingsDialog() {
  if (settingsDialog_ == nullptr) {
    const QString dir = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                            .filePath(QStringLiteral("settings-backups"));
    settingsDialog_ = new MachineSettingsDialog(machine_.view(), machine_.boardSettings(), dir, window_);
  }
  settingsDialog_->show();
  settingsDialog_->raise();
  if (machine_.view().isConnected()) settingsDialog_->readBoard();
  return settingsDialog_;
}

bool MachinePanels::confirmClose() {
  if (!machine_.run().running()) return true;
  QMessageBox box(QMessageBox::Warning, tr("A job is running"),
                  tr("The machine is drawing \"%1\". Quitting the studio would leave it without "
                     "its stream of lines.\n\nHold, stop and quit: the machine stops cleanly and "
                     "the progress is saved, so you can resume later.")
                      .arg(machine_.run().drawingName()),
                  QMessageBox::NoButton, window_);
  box.setObjectName(QStringLiteral("quitWhileRunning"));
  QPushButton* stop = box.addButton(tr("Hold, stop and quit"), QMessageBox::DestructiveRole);
  stop->setObjectName(QStringLiteral("stopAndQuit"));
  QPushButton* keep = box.addButton(tr("Keep running"), QMessageBox::RejectRole);
  keep->setObjectName(QStringLiteral("keepRunning"));
  box.setDefaultButton(keep);
  // The job may end while the question is open: the question then says so.
  const QMetaObject::Connection ended = connect(&machine_.run(), &session::RunController::runChanged, &box, [&] {
    if (machine_.run().running()) return;
    box.setIcon(QMessageBox::Question);
    box.setWindowTitle(tr("The job has ended"));
    box.setText(tr("The job \"%1\" has ended. Quit FiveBar Studio?").arg(machine_.run().drawingName()));
    stop->setText(tr("Quit"));
    keep->setText(tr("Cancel"));
  });
  box.exec();
  disconnect(ended);
  if (box.clickedButton() != stop) return false;
  if (machine_.run().running()) machine_.stopRunForQuit();
  return true;
}

}  // namespace fivebar::widgets
