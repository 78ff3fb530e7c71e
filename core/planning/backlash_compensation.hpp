// SPDX-License-Identifier: GPL-3.0-or-later
// Host-side backlash compensation (GRBL 1.1 has none): when a motor reverses, a take-up move
// turns that motor alone through its play before the reversing move, so the arm leaves the pose
// it was at in the new direction without lag. Model and derivation: docs/calibration-pattern.md
// "Backlash". Radians.
//
// Play model (per motor, play b >= 0): the arm angle a follows the motor angle m inside a dead
// band, m <= a <= m + b: moving the motor up pushes the arm (a = m), moving it down pulls it
// (a = m + b). A motor's zero offset is measured with the motor last moving up (the calibration
// pattern approaches every fit mark so), where a = m. Compensation commands m = planned when the
// motor last moved up and m = planned - b when it last moved down.
#pragma once

#include <cstddef>
#include <string>

#include "core/machine/profile.hpp"
#include "core/planning/job.hpp"
#include "core/planning/safety.hpp"

namespace fivebar {

struct MotorPlay {
  double motor1Rad = 0.0;  // play of motor 1, rad (>= 0)
  double motor2Rad = 0.0;
  bool none() const { return !(motor1Rad > 0.0) && !(motor2Rad > 0.0); }
};

// A motor component of a move smaller than this (rad) keeps the motor's direction: far below the
// G-code's 1e-4 deg, so whatever such a move does is below what the G-code can say.
inline constexpr double kReversalThresholdRad = 1e-9;

struct BacklashPass {
  std::size_t takeUpMoves = 0;  // inserted moves (job start and end included)
  bool ok = true;               // false: a compensated command fails the safety check
  MoveCheck problem;            // the first failing move's check when !ok
  Message message;
};

// Rewrites `job` in place for a machine with this play: a take-up preamble at the start pose
// (each motor down by its play and back up: afterwards every arm is at its commanded angle,
// whatever it was before), a take-up move before every reversing motion move, commanded targets
// shifted by -b while a motor last moved down, and a last take-up that ends the job at its start
// pose with every motor last moving up. Non-motion moves carry the commanded pose. targetXY keeps
// the planned (arm) position. Take-up moves are of the kind of the move they precede (Draw with
// the pen down inside a stroke, where the arm stands still while the motor crosses its play),
// except that a stroke's first draw move gets its take-up before the pen goes down, as a Travel
// (pen up, laser at S0); they run at the slower motor's top speed and belong to its stroke. The commanded
// joint path is checked with checkJointPath (what a checked stream sees). No play: unchanged.
// Move times are not refilled (the caller runs fillJobTimes).
BacklashPass compensateBacklash(PlannedJob& job, const MachineProfile& profile, const MotorPlay& play);

}  // namespace fivebar
