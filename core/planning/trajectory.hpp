// A planned job sampled by time, for the studio's animation: core computes the timing once
// (GRBL time model), the GUI asks for the pose at any time. Play, pause, scrub and speed are UI
// state and do not belong here.
#pragma once

#include <optional>
#include <memory>
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
  // Times the job with the GRBL model (also fills the job copy's durations).
  Trajectory(const PlannedJob& job, const MachineProfile& profile);
  // A job the planner timed already: `timings` are its per-move GRBL timings
  // (PlanOptions::keepBlockTimings, or estimateJobTime); the job is shared, not copied.
  Trajectory(std::shared_ptr<const PlannedJob> job, std::vector<GrblBlockTiming> timings,
             const MachineProfile& profile);

  double durationS() const { return durationS_; }
  const PlannedJob& job() const { return *job_; }
  // Pose at time t (clamped to [0, durationS()]). Continuous in t.
  TrajectorySample at(double timeS) const;

 private:
  void index();  // from_ and penDownAfter_
  std::shared_ptr<const PlannedJob> job_ = std::make_shared<const PlannedJob>();
  Geometry geometry_;
  std::optional<PenOffset> pen_;  // the profile's calibrated pen offset
  std::vector<GrblBlockTiming> timings_;
  std::vector<JointAngles> from_;   // pose before each move
  std::vector<bool> penDownAfter_;  // tool state after each move
  double durationS_ = 0.0;
};

}  // namespace fivebar
