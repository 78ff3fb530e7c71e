// SPDX-License-Identifier: GPL-3.0-or-later
// The safety rule: no move reaches the machine that leaves the workspace, breaks a joint limit,
// or passes through or near a type II singularity. Every joint-linear move, travel and jog
// included, is checked here before a byte goes to the port.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/support/message.hpp"

namespace fivebar {

enum class MoveStatus {
  Ok = 0,
  NearTypeII = 1,        // within the profile's type II margin
  NearTypeI = 2,         // a leg within its type I margin of full stretch / fold
  BeyondJointLimit = -1,
  CannotClose = -2,      // the loop does not close somewhere along the move (out of reach)
  AssemblyChange = -3,   // the move would pass through a type II singularity (assembly flips)
};

struct MoveCheck {
  MoveStatus status = MoveStatus::Ok;
  double atFraction = 0.0;     // where along the move (0..1) the first problem is
  Vec2 where = Vec2::Zero();   // machine-frame point of the first problem (mm)
  double minTypeIIMarginRad = 0.0;  // smallest type II margin along the move
  bool ok() const { return status == MoveStatus::Ok; }
};

// Checks one joint-linear move from `from` to `to` (continuous angles, rad) in the profile's
// assembly mode, by sampling it finely enough that no excursion between samples is missed: the
// step between samples comes from a Lipschitz bound on the margins (derivation in safety.cpp),
// so no margin can cross its threshold between two samples; within 0.1 deg of a joint limit
// samples are at most 0.1 deg apart. The smallest type II margin reported is refined to 0.1 deg
// of joint motion around the smallest sample (golden section search). Each sample: joint limits, loop closure (forward
// kinematics in profile.assembly), type II margin (below 0.05 deg the move touches the type II
// locus: AssemblyChange, or CannotClose when it goes on out of the closable region), type II
// and type I margins of the profile. Reports the first problem along the move.
MoveCheck checkJointMove(const MachineProfile& profile, const JointAngles& from,
                         const JointAngles& to);

// A safe travel (pen up) from `from` to `to` as a sequence of joint-space waypoints (excluding
// `from`, ending at `to`), each leg passing checkJointMove. A straight joint move when it is safe,
// a detour otherwise; nullopt when no safe travel exists.
std::optional<std::vector<JointAngles>> planSafeTravel(const MachineProfile& profile,
                                                       const JointAngles& from,
                                                       const JointAngles& to);

// One failing move of a joint path: move i runs from poses[i] to poses[i + 1].
struct PathProblem {
  std::size_t move = 0;
  MoveCheck check;
};
struct PathCheck {
  std::vector<PathProblem> problems;  // the first problem of each failing move, in path order
  double minTypeIIMarginRad = 0.0;    // smallest type II margin along the whole path
  bool ok() const { return problems.empty(); }
};

// Checks the chain of joint-linear moves through `poses` (continuous angles) as checkJointMove
// checks each move, evaluating every shared pose once (the fast path of job preflight). A bad
// pose is reported once: as the end (atFraction 1) of the move reaching it, or for poses[0] as
// move 0 at atFraction 0. A path of one pose is checked as that pose. The smallest margin is
// refined (as checkJointMove refines each move's) around the path's smallest sample only: a move
// whose samples all stay above it is not searched between its samples.
PathCheck checkJointPath(const MachineProfile& profile, const std::vector<JointAngles>& poses);

// Checks a single pose (continuous angles) exactly as checkJointMove checks each sample:
// joint limits, loop closure, type II (assembly ambiguity and margin), type I margin.
MoveCheck checkPose(const MachineProfile& profile, const JointAngles& q);

// Kinematic angles `kinematic` unwrapped near `near` (both kinematic), each motor shifted by a
// whole turn when that brings its COMMANDED angle (commandedFromKinematic) inside the profile's
// joint limits; unchanged from the nearest turn when no turn does.
JointAngles nearWithinLimits(const MachineProfile& profile, const JointAngles& kinematic, const JointAngles& near);

// Short name: "ok", "near type II", "near type I", "beyond joint limit", "cannot close",
// "assembly change".
std::string_view toString(MoveStatus status);

// Human-readable reason, e.g. "passes within 4.2 deg of a type II singularity at (1.0, 2.0) mm,
// 50% along the move": describeMove is the translatable message, describe its English text.
Message describeMove(const MoveCheck& check);
std::string describe(const MoveCheck& check);

}  // namespace fivebar
