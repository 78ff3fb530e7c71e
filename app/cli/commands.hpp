// SPDX-License-Identifier: GPL-3.0-or-later
// The fivebar CLI's subcommands. Each takes the arguments after its name, reads stdin and writes
// stdout/stderr, and returns the process exit code (0 ok, 1 failure, 2 usage error).
#pragma once

#include <string>
#include <vector>

namespace fivebar::cli {

using Args = std::vector<std::string>;

int runIk(const Args& args);             // cmd_kinematics.cpp
int runFk(const Args& args);             // cmd_kinematics.cpp
int runWorkspace(const Args& args);      // cmd_workspace.cpp
int runDesign(const Args& args);         // cmd_design.cpp
int runProfile(const Args& args);        // cmd_profile.cpp
int runPlan(const Args& args);           // cmd_plan.cpp
int runGrblSettings(const Args& args);   // cmd_plan.cpp
int runText(const Args& args);           // cmd_text.cpp
int runStream(const Args& args);         // cmd_machine.cpp (Qt builds only)
int runSend(const Args& args);           // cmd_send.cpp (Qt builds only)
int runSetup(const Args& args);          // cmd_machine.cpp (Qt builds only)
int runReference(const Args& args);      // cmd_reference.cpp (Qt builds only)
int runHome(const Args& args);           // cmd_reference.cpp (Qt builds only)
int runFrame(const Args& args);          // cmd_frame.cpp (Qt builds only)
int runCalibrate(const Args& args);      // cmd_calibrate.cpp (dispatches to the subcommands)
int runCalibrateFit(const Args& args);   // cmd_calibrate_fit.cpp
int runCalibratePattern(const Args& args);  // cmd_calibrate_pattern.cpp
int runCalibrateScan(const Args& args);     // cmd_calibrate_scan.cpp (Qt builds only: reads images)
int runCalibrateLines(const Args& args);    // cmd_calibrate_lines.cpp (Qt builds only: reads images)
// Further commands are declared here as they land (plan, grbl-settings, stream, send).

}  // namespace fivebar::cli
