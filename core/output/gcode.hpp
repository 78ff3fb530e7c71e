// SPDX-License-Identifier: GPL-3.0-or-later
// G-code for stock GRBL 1.1 with host-side kinematics (conventions.md): X = theta1 deg,
// Y = theta2 deg (continuous), F = joint-space vector rate in deg/min recomputed per move, G90 G94,
// lines of at most 80 characters, a header naming the profile and the $ settings it expects.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "core/planning/job.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {

inline constexpr int kGcodeMaxLineLength = 80;  // GRBL's line buffer (incl. no terminator)

struct GcodeOptions {
  int angleDecimals = 4;  // 1e-4 deg: far below a step (1 / $100 deg) on any sane machine
  int feedDecimals = 1;   // deg/min
  bool strokeComments = true;  // "; stroke N" before each stroke (for resume and people)
};

// The GRBL $ lines the profile expects ($100..$132, $11, $20, $21, $22, $32), one per line,
// each with a short comment.
std::string grblSettings(const MachineProfile& profile);

// The job as G-code text (lines end with '\n').
std::string writeGcode(const PlannedJob& job, const MachineProfile& profile,
                       const GcodeOptions& options = {});

// The same text handed to `sink` in consecutive pieces of about a megabyte (written by up to two
// threads, handed over in order on the calling thread), so that a large job never needs the
// whole text in memory. On an error (a line too long) the exception is thrown, and the sink may
// have received part of the text before it: discard what it got.
void writeGcode(const PlannedJob& job, const MachineProfile& profile,
                const std::function<void(std::string_view)>& sink,
                const GcodeOptions& options = {});

}  // namespace fivebar
