// SPDX-License-Identifier: GPL-3.0-or-later
// The `fivebar workspace --png` image, painted with widgets/workspace_painter when the CLI is
// built with Qt (FIVEBAR_BUILD_GUI=ON). Separate so that the command itself needs only the core.
#pragma once

#include <string>

#include "core/machine/profile.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar::cli {

// Writes a PNG of the analysis: machine in its home pose, regions, type II curves, rectangle,
// legend and scale bar. Returns an error message, or an empty string on success.
std::string writeWorkspacePng(const std::string& path, const MachineProfile& profile,
                              const WorkspaceMap& map, const WorkspaceAnalysis& analysis);

}  // namespace fivebar::cli
