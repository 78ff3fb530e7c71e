// SPDX-License-Identifier: GPL-3.0-or-later
// Jogging and the other manual moves, planned host-side (the board only sees joint space):
//  - Cartesian jog: a straight XY line streamed as short $J= joint moves, each short enough that
//    the pen stays within maxDeviationMm of the true line, every sub-move checked with
//    checkJointMove; the plan stops at the last safe point (workspace edge, joint limit,
//    singularity margin). Continuous jog = a long plan cancelled with 0x85 on release.
//  - per-motor jog, go-to point (planSafeTravel), home / reference pose, pen up/down;
//  - frame: the job's outline (convex hull or bounding box of its strokes) traced pen-up in the
//    job's working mode, every move checked.
// Pure: returns the lines to send; a JobRunner or the protocol streams them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/support/message.hpp"
#include "drivers/stream/gcode_job.hpp"

namespace fivebar::jog {

inline constexpr double kDefaultDeviationMm = 0.05;  // pen path vs. the straight XY line
inline constexpr double kMinSubMoveMm = 0.01;        // shorter steps are not worth sending

enum class JogStatus {
  Ok = 0,
  Clipped = 1,       // stopped early at the last safe point; reason says why
  Blocked = -1,      // not even a first step is safe
  NoPosition = -2,   // the current angles do not close the loop (FK failed)
};

struct JogPlan {
  JogStatus status = JogStatus::Ok;
  std::vector<std::string> lines;        // $J= or G-code lines, in order
  std::vector<JointAngles> targets;      // joint target of each motion line (rad, commanded)
  double lengthMm = 0.0;                 // XY length covered
  Message reason;                        // for Clipped / Blocked / NoPosition (context "Jog")
  bool ok() const { return status == JogStatus::Ok || status == JogStatus::Clipped; }
};

// `current` and the plan's targets and lines are commanded angles (what GRBL's MPos and $J= carry);
// the kinematics inside uses kinematic = commanded + the profile's zero offsets (docs/calibration.md).

// Straight XY jog from the current pose along `direction` (any non-zero vector, machine frame)
// for distanceMm at speedMmPerS, in the current pose's working mode.
JogPlan planCartesianJog(const MachineProfile& profile, const JointAngles& current, const Vec2& direction,
                         double distanceMm, double speedMmPerS,
                         double maxDeviationMm = kDefaultDeviationMm);

// One motor by deltaDeg at feedDegPerMin, checked; clipped to the last safe angle.
JogPlan planMotorJog(const MachineProfile& profile, const JointAngles& current, int motor,
                     double deltaDeg, double feedDegPerMin);

// Pen-up move to an XY point (machine frame, mm) in the current working mode by a safe travel.
JogPlan planGoTo(const MachineProfile& profile, const JointAngles& current, const Vec2& targetMm);

// The pen's path along a plan's joint-linear motion legs (machine frame, mm; first point = the
// pose at `current`), samplesPerLeg FK samples per leg: the canvas preview of a jog or go-to.
// Empty when `current` does not close the linkage.
std::vector<Vec2> penPathMm(const MachineProfile& profile, const JointAngles& current, const JogPlan& plan,
                            int samplesPerLeg = 24);

// "$H" on machines with homing switches; otherwise the reference-pose command that declares the
// current pose to be profile.homeAngles: "G10L20P0X<theta1>Y<theta2>" (deg).
std::string homeCommand(const MachineProfile& profile);
std::string referencePoseCommand(const MachineProfile& profile);

enum class FrameShape { ConvexHull, BoundingBox };
// A laser traces the frame at this share of the profile's laserPowerS (M4: GRBL's laser mode
// scales it with the speed), so that the spot is seen and nothing is burnt.
inline constexpr double kFrameLaserPowerShare = 0.01;
// The job's outline traced pen-up (a laser lit at kFrameLaserPowerShare along the outline only),
// starting with a safe travel from `current` to its first corner and ending back there.
JogPlan planFrame(const MachineProfile& profile, const JointAngles& current,
                  const stream::GcodeJob& gcodeJob, const stream::JobRules& rules, FrameShape shape,
                  double speedMmPerS);

// Convex hull (counter-clockwise, no repeated first point) of points; exposed for tests.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

}  // namespace fivebar::jog
