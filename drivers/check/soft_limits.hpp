// SPDX-License-Identifier: GPL-3.0-or-later
// The board's soft limits seen from the host, so pre-flight agrees with the board: GRBL 1.1
// (limits.c limits_soft_check, homing direction mask 0, HOMING_FORCE_SET_ORIGIN off) refuses, with
// $20=1, every motion target outside -$130..0 (X, motor 1) and -$131..0 (Y, motor 2) in MACHINE
// coordinates, and stops the job with ALARM:2. Machine = work + WCO: after "set reference pose"
// (G10 L20) the work coordinates the job is written in are shifted against the machine's, so a job
// inside the profile's joint limits can still leave the board's travel box. Pure, no I/O.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "core/support/message.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/check/machine_setup.hpp"

namespace fivebar::setup {

struct SoftLimitHit {
  std::size_t lineIndex = 0;  // index into GcodeJob::lines
  int fileLine = 0;           // 1-based line of the G-code file
  int axis = 0;               // 0: X (motor 1), 1: Y (motor 2)
  double machineDeg = 0.0;    // the line's target in machine coordinates
  double travelDeg = 0.0;     // the board's $130 / $131
};

// Whether the board's settings turn soft limits on ($20=1).
bool softLimitsOn(const Settings& board);

// The board's soft-limit travel ($130, $131 in deg) when soft limits are on; nullopt otherwise
// (off, or the settings not known).
std::optional<std::array<double, 2>> softLimitTravelDeg(const Settings& board);

// The first axis (0: X, 1: Y) of a target in machine coordinates (deg) that lies outside the
// travel -travelDeg..0, as GRBL's limits_soft_check decides; nullopt when inside.
std::optional<int> axisOutsideTravel(const std::array<double, 2>& machineDeg,
                                     const std::array<double, 2>& travelDeg);

// The first motion line of `job` whose X/Y target (work coordinates, deg) plus the board's work
// offset wcoDeg lies outside the board's soft-limit travel (GRBL checks targets only); nullopt
// when soft limits are off or every target is inside.
std::optional<SoftLimitHit> firstSoftLimitHit(const stream::GcodeJob& job, const Settings& board,
                                              const std::array<double, 2>& wcoDeg);

// "line 12 moves motor 1 to 4.500 deg in machine coordinates, outside the board's soft-limit
// travel -180.000..0 ($130=180.000)": translatable (context "SoftLimits"), describe its English.
Message describeHit(const SoftLimitHit& hit);
std::string describe(const SoftLimitHit& hit);

}  // namespace fivebar::setup
