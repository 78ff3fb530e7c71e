// SPDX-License-Identifier: GPL-3.0-or-later
// The questions the machine side asks before an action that cannot be undone on the machine:
// setting the reference pose (the studio then believes the arms stand at the profile's home
// pose), and the home button that, without homing switches, sets that reference. Each asks
// with a modal QMessageBox whose object name tests and screenshots find.
#pragma once

#include <QString>

class QWidget;

namespace fivebar {
struct MachineProfile;
}

namespace fivebar::session {
class RecoveryPort;
}

namespace fivebar::widgets {


// The confirmation text for the reference pose of this profile (home angles in degrees).
QString referencePoseQuestion(const MachineProfile& profile);
// Asks; true when the user confirmed. Object name of the box: "referencePoseQuestion".
bool confirmReferencePose(QWidget* parent, const MachineProfile& profile);
// The home button: $H with homing switches; otherwise the reference pose after confirmation.
void requestHome(QWidget* parent, const MachineProfile& profile, session::RecoveryPort& recovery);
// "Set reference pose" after confirmation.
void requestReferencePose(QWidget* parent, const MachineProfile& profile, session::RecoveryPort& recovery);

}  // namespace fivebar::widgets
