// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/trajectory.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/machine/pen_kinematics.hpp"

namespace fivebar {

Trajectory::Trajectory(const PlannedJob& job, const MachineProfile& profile)
    : profile_(std::make_shared<const MachineProfile>(profile)), pen_(calibratedPenOffset(profile)) {
  auto timed = std::make_shared<PlannedJob>(job);
  fillJobTimes(*timed, profile);
  job_ = std::move(timed);
  durationS_ = job_->summary.estimatedTimeS;
}

Trajectory::Trajectory(std::shared_ptr<const PlannedJob> job, const MachineProfile& profile)
    : job_(std::move(job)), profile_(std::make_shared<const MachineProfile>(profile)),
      pen_(calibratedPenOffset(profile)), durationS_(job_->summary.estimatedTimeS) {}

std::shared_ptr<const Trajectory::Chain> Trajectory::chainAround(std::size_t moveIndex) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (chain_ && chain_->timed.begin <= moveIndex && moveIndex < chain_->timed.end) return chain_;
  }
  const PlannedJob& job = *job_;
  auto chain = std::make_shared<Chain>();
  chain->timed = timeChainAround(job, *profile_, moveIndex);
  const std::size_t begin = chain->timed.begin, end = chain->timed.end;
  // Where the moves before the chain left the joints and the tool.
  JointAngles at = job.start;
  bool down = false;
  bool haveAt = false, haveTool = false;
  for (std::size_t i = begin; i-- > 0 && !(haveAt && haveTool);) {
    const JobMove& m = job.moves[i];
    if (!haveAt && isMotion(m.kind)) at = m.target, haveAt = true;
    if (!haveTool && (m.kind == JobMoveKind::PenDown || m.kind == JobMoveKind::PenUp))
      down = m.kind == JobMoveKind::PenDown, haveTool = true;
  }
  chain->from.reserve(end - begin);
  chain->downAfter.reserve(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    const JobMove& m = job.moves[i];
    chain->from.push_back(at);
    if (isMotion(m.kind)) at = m.target;
    if (m.kind == JobMoveKind::PenDown) down = true;
    if (m.kind == JobMoveKind::PenUp) down = false;
    chain->downAfter.push_back(down ? 1 : 0);
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  chain_ = chain;
  return chain;
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
    const std::shared_ptr<const Chain> chain = chainAround(i);
    const std::size_t k = i - chain->timed.begin;
    const GrblBlockTiming& timing = chain->timed.timings[k];
    const JointAngles& a = chain->from[k];
    s.moveIndex = static_cast<int>(i);
    s.penDown = chain->downAfter[k] != 0;
    if (isMotion(m.kind) && timing.lengthUnits > 0.0) {
      const double u = distanceAt(timing, s.timeS - m.startTimeS) / timing.lengthUnits;
      s.q = {a.theta1 + u * (m.target.theta1 - a.theta1), a.theta2 + u * (m.target.theta2 - a.theta2)};
    } else {
      s.q = isMotion(m.kind) ? m.target : a;
    }
  }
  const FkResult fk = penForward(profile_->geometry, pen_, s.q, job.assembly);
  s.p = fk.ok() ? fk.p : job.startXY;
  return s;
}

}  // namespace fivebar
