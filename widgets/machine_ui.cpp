#include "widgets/machine_ui.hpp"

#include <QDockWidget>

#include "widgets/canvas_view.hpp"
#include "widgets/console_panel.hpp"
#include "widgets/jog_panel.hpp"
#include "widgets/machine_layer.hpp"
#include "widgets/machine_panel.hpp"
#include "widgets/profile_editor.hpp"
#include "widgets/run_layer.hpp"
#include "widgets/run_panel.hpp"

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
}

bool MachineUi::connectSimulated(double speedup) {
  QString error;
  return session_.connectSimulated(speedup, sim::Fault{}, &error);
}

}  // namespace fivebar::widgets
