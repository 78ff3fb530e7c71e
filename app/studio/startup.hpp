// SPDX-License-Identifier: GPL-3.0-or-later
// Start-up helpers of fivebar-studio: resolving the machine profile argument, connecting a port
// named on the command line, and the --screenshot mode (wait until the window shows a planned
// job, grab it, quit).
#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>
#include <string>

#include "core/machine/profile.hpp"

namespace fivebar::studio {

class MainWindow;

// A preset name or a profile file; on failure `error` says why (field names included).
std::optional<MachineProfile> resolveProfile(const std::string& presetOrPath, std::string& error);

// The machine the studio starts with: --machine when given, else the profile of the last
// session (edits included, QSettings), else the maker-plotter preset.
std::optional<MachineProfile> startupProfile(const std::optional<QString>& machineArg,
                                             std::string& error);

// --port PORT [--baud N]: once the event loop runs, the machine panel connects PORT (at N baud,
// else the baud box's rate: the profile's) exactly as its Connect button does, messages
// included. `port` empty: no --port. Returns the error for a --baud that is not a positive whole
// number or comes without --port (nothing is connected then), empty when fine.
QString connectAtStart(MainWindow& window, const QString& port, const QString& baud);

// Once the workspace is computed, the import (if `expectDrawing`) has finished and the first
// plan is done, calls `beforeGrab` (to set up what the picture shows), grabs the window into
// `path` (PNG) and quits the application with 0, or with 1 when saving fails or nothing got
// ready within the time limit.
void screenshotWhenReady(MainWindow& window, const QString& path, bool expectDrawing,
                         std::function<void()> beforeGrab = {});

// Documentation helpers for screenshots: "--overlay legend|transmission|conditioning|resolution"
// (repeatable) shows the workspace legend or that map; "--at-time F" puts the simulation at fraction F (0..1) of the job. Returns
// an error message for a bad value, empty when fine.
QString applyViewOptions(MainWindow& window, const QStringList& overlays, const QString& atTime);

}  // namespace fivebar::studio
