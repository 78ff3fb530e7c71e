// SPDX-License-Identifier: GPL-3.0-or-later
// Backlash (play) of the motors: a simulated machine with play (the model of
// core/planning/backlash_compensation.hpp) to test the compensation, and the estimate of each
// motor's play from the calibration pattern's backlash rows. docs/calibration-pattern.md.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/support/message.hpp"
#include "core/calibration/pattern.hpp"
#include "core/planning/backlash_compensation.hpp"
#include "core/planning/job.hpp"

namespace fivebar {

// Arm angles of motors with play: a in [m, m + b] per motor, pushed along by the motor.
class PlayState {
 public:
  // The motors at `motors`; arms at motors + initialLag (each clamped into [0, b]).
  PlayState(const MotorPlay& play, const JointAngles& motors, const JointAngles& initialLag = {});
  // The motors move monotonically to `motors` (one joint-linear move, or part of one).
  void moveTo(const JointAngles& motors);
  const JointAngles& arm() const { return arm_; }

 private:
  MotorPlay play_;
  JointAngles arm_;
};

// What a machine with this play (true geometry `g`, assembly mode) draws when it runs `job`'s
// commanded targets: one polyline of pen positions per pen-down run, each motion move sampled at
// `samplesPerMove` points (forward kinematics of the arm angles). The motors start at job.start,
// the arms at job.start + initialLag.
std::vector<std::vector<Vec2>> drawnWithPlay(const PlannedJob& job, const Geometry& g,
                                             AssemblyMode assembly, const MotorPlay& play,
                                             const JointAngles& initialLag = {},
                                             int samplesPerMove = 8);

struct BacklashRowEstimate {
  int group = 0;
  int motor = 0;
  double playRad = 0.0;
};
struct BacklashEstimate {
  MotorPlay play;                         // mean of each motor's rows (0 for a motor without)
  std::vector<BacklashRowEstimate> rows;  // every measured row
  int rowsMotor1 = 0;
  int rowsMotor2 = 0;
  Message error;                          // empty when ok (translatable)
  bool ok() const { return error.empty(); }
};

// Play per motor from the measured positions (any paper frame, mirrored or not) of the marks of
// the pattern's backlash rows. For a row q0, q1 = q0 + d e_k, q2 = q0 + 2d e_k with the middle mark
// approached with motor k moving down, the arm stood at q1 + b e_k there, so
//   P1 - (P0 + P2)/2 - c = J_k b,   J_k = (P2 - P0) / (2d),
// with c = N1 - (N0 + N2)/2 the row's nominal curvature (mapped to paper by the rigid fit of the
// grid marks); b is the projection onto J_k. No geometry is needed beyond the nominal positions.
// Rows missing a mark are skipped; an error when no row is complete or fewer than 3 grid marks
// place the sheet. A negative estimate (noise on a machine without play) is kept as measured.
BacklashEstimate estimateBacklash(const std::vector<PatternMark>& marks,
                                  const std::map<int, Vec2>& measuredById);

}  // namespace fivebar
