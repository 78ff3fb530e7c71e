// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration feature's place in the studio (installed through the shell, like every feature:
// widgets/shell/studio_shell.hpp): the simulated machine's true build (its menu entry, status badge
// and canvas trace) and Machine > Calibrate..., whose wizard is made on first use.
#pragma once

#include <QPointer>

#include "widgets/shell/studio_shell.hpp"

class QAction;

namespace fivebar::session {
class MachineSession;
}

namespace fivebar::widgets::calibration {

class CalibrationWizard;
class SimulatedTruth;

struct CalibrationFeature {
  SimulatedTruth* simulatedTruth = nullptr;  // the machine session's child
  QAction* calibrateAction = nullptr;
};

// `wizard` receives the wizard when it is first opened (owned by the caller, which outlives the
// window's menus).
CalibrationFeature installCalibration(const StudioShell& shell, session::MachineSession& session,
                                      QPointer<CalibrationWizard>& wizard);

}  // namespace fivebar::widgets::calibration
