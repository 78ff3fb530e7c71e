// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration feature installed. Contract: calibration_install.hpp.
#include "widgets/calibration/calibration_install.hpp"

#include <QAction>
#include <QMenu>
#include <QStatusBar>

#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/simulated_machine.hpp"

namespace fivebar::widgets::calibration {

CalibrationFeature installCalibration(const StudioShell& shell, session::MachineSession& session,
                                      QPointer<CalibrationWizard>& wizard) {
  CalibrationFeature feature;
  // The simulated machine's true (imperfect) build, shared by the wizard and its own menu entry,
  // status badge and canvas trace.
  feature.simulatedTruth = new SimulatedTruth(*shell.doc, session);
  feature.calibrateAction = CalibrationWizard::createAction(*shell.doc, &session, feature.simulatedTruth,
                                                            shell.canvas, shell.window, wizard);
  shell.machineMenu->addAction(feature.calibrateAction);
  installSimulatedMachine(*feature.simulatedTruth, session, *shell.canvas, *shell.machineMenu,
                          *shell.statusBar, shell.window);
  return feature;
}

}  // namespace fivebar::widgets::calibration
