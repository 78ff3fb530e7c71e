#include "core/planning/trajectory.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/machine/pen_kinematics.hpp"

namespace fivebar {

Trajectory::Trajectory(const PlannedJob& job, const MachineProfile& profile)
    : geometry_(profile.geometry), pen_(calibratedPenOffset(profile)) {
  auto timed = std::make_shared<PlannedJob>(job);
  timings_ = estimateJobTime(*timed, profile);
  job_ = std::move(timed);
  index();
}

Trajectory::Trajectory(std::shared_ptr<const PlannedJob> job, std::vector<GrblBlockTiming> timings,
                       const MachineProfile& profile)
    : job_(std::move(job)), geometry_(profile.geometry), pen_(calibratedPenOffset(profile)),
      timings_(std::move(timings)) {
  if (timings_.size() != job_->moves.size())
    throw std::invalid_argument("Trajectory: one timing per move expected");
  index();
}

void Trajectory::index() {
  durationS_ = job_->summary.estimatedTimeS;
  from_.reserve(job_->moves.size());
  penDownAfter_.reserve(job_->moves.size());
  JointAngles at = job_->start;
  bool down = false;
  for (const JobMove& m : job_->moves) {
    from_.push_back(at);
    if (isMotion(m.kind)) at = m.target;
    if (m.kind == JobMoveKind::PenDown) down = true;
    if (m.kind == JobMoveKind::PenUp) down = false;
    penDownAfter_.push_back(down);
  }
}

TrajectorySample Trajectory::at(double timeS) const {
  TrajectorySample s;
  s.timeS = std::clamp(timeS, 0.0, durationS_);
  const PlannedJob& job = *job_;
  const auto& moves = job.moves;
  const auto it = std::upper_bound(moves.begin(), moves.end(), s.timeS,
                                   [](double t, const JobMove& m) { return t < m.startTimeS; });
  if (it == moves.begin()) {
    s.q = job.start;
  } else {
    const size_t i = static_cast<size_t>(it - moves.begin()) - 1;
    const JobMove& m = moves[i];
    s.moveIndex = static_cast<int>(i);
    s.penDown = penDownAfter_[i];
    if (isMotion(m.kind) && timings_[i].lengthUnits > 0.0) {
      const double u = distanceAt(timings_[i], s.timeS - m.startTimeS) / timings_[i].lengthUnits;
      const JointAngles& a = from_[i];
      s.q = {a.theta1 + u * (m.target.theta1 - a.theta1), a.theta2 + u * (m.target.theta2 - a.theta2)};
    } else {
      s.q = isMotion(m.kind) ? m.target : from_[i];
    }
  }
  const FkResult fk = penForward(geometry_, pen_, s.q, job.assembly);
  s.p = fk.ok() ? fk.p : job.startXY;
  return s;
}

}  // namespace fivebar
