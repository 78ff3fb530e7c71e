// SPDX-License-Identifier: GPL-3.0-or-later
// A machine as it really is, for the simulated machine and sheet: the geometry it was built from
// changed by small amounts, zero offsets and play in each drive. Machine frame, mm and rad.
#pragma once

#include "core/kinematics/geometry.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/backlash_compensation.hpp"

namespace fivebar {

// A machine as it really is: `builtFrom` (the profile's geometry when the wizard opened; it stays
// the same when a calibration is applied, as the real machine does) changed by these amounts,
// true motor angle = commanded + zero offset, and play in each drive.
struct TrueMachine {
  Geometry builtFrom;
  double da1Mm = 0.0, db1Mm = 0.0, da2Mm = 0.0, db2Mm = 0.0, dwMm = 0.0;
  double zeroOffsetRad1 = 0.0, zeroOffsetRad2 = 0.0;
  MotorPlay play;
  Geometry geometry() const;
  bool perfect() const;
};

// The true machine as a profile for the simulated machine (sim::SimConfig::trueMachine):
// `nominal` with truth.geometry() and a calibration section holding only the true zero offsets
// and backlash (no pen offset).
MachineProfile trueMachineProfile(const MachineProfile& nominal, const TrueMachine& truth);

}  // namespace fivebar
