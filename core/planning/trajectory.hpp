// SPDX-License-Identifier: GPL-3.0-or-later
// A planned job sampled by time, for the studio's animation: core computes the timing once
// (GRBL time model), the GUI asks for the pose at any time. Play, pause, scrub and speed are UI
// state and do not belong here.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "core/planning/job.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/time_estimate.hpp"

namespace fivebar {

struct TrajectorySample {
  double timeS = 0.0;
  JointAngles q;           // continuous motor angles (rad)
  Vec2 p = Vec2::Zero();   // the pen (mm): FK of q in the job's assembly mode, with the
                           // profile's calibrated pen offset (pen_kinematics.hpp)
  int moveIndex = -1;      // move executing at timeS (-1 before the first)
  bool penDown = false;    // tool down (drawing) at timeS
};

class Trajectory {
 public:
  Trajectory() = default;
  // Copies the job and times it with the GRBL model (fills the copy's start times and durations).
  Trajectory(const PlannedJob& job, const MachineProfile& profile);
  // A job timed already (planJob fills every move's start time and duration): shared, not
  // copied. Built at once: the GRBL timing inside each move (trapezoid speeds) is computed chain
  // by chain as the trajectory is sampled (timeChainAround), not for the whole job up front.
  Trajectory(std::shared_ptr<const PlannedJob> job, const MachineProfile& profile);

  double durationS() const { return durationS_; }
  const PlannedJob& job() const { return *job_; }
  // Pose at time t (clamped to [0, durationS()]). Continuous in t. Thread-safe.
  TrajectorySample at(double timeS) const;

 private:
  // One chain of moves timed (time_estimate.hpp), with the pose before each move and the tool
  // state after it.
  struct Chain {
    TimedChain timed;
    std::vector<JointAngles> from;      // from[i - begin]: pose before move i
    std::vector<std::uint8_t> downAfter;  // downAfter[i - begin]: tool down after move i
  };
  std::shared_ptr<const Chain> chainAround(std::size_t moveIndex) const;

  std::shared_ptr<const PlannedJob> job_ = std::make_shared<const PlannedJob>();
  std::shared_ptr<const MachineProfile> profile_ = std::make_shared<const MachineProfile>();
  std::optional<PenOffset> pen_;  // the profile's calibrated pen offset
  double durationS_ = 0.0;
  // The chain sampled last (an animation samples one chain many times in a row).
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const Chain> chain_;
};

}  // namespace fivebar
