// SPDX-License-Identifier: GPL-3.0-or-later
// The pen as the board itself reports it: from the status report's spindle speed (FS:, GRBL's
// running spindle state: 0 after M5 or a reset) for a servo pen or a laser, from the work Z for
// a Z-axis pen. Not the last line the host sent: a stop, a reset or an M5 typed elsewhere show.
#pragma once

#include <optional>

#include "core/machine/profile.hpp"
#include "grbl_parser.hpp"

namespace fivebar::grbl {

enum class BoardPen { Unknown, Up, Down };

// workZ: the work position's Z (mm) when known.
BoardPen penFromStatus(const ToolSettings& tool, const StatusReport& report, std::optional<double> workZ);

}  // namespace fivebar::grbl
