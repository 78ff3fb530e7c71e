// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/backlash_compensation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/planning/feeds.hpp"

namespace fivebar {
namespace {

enum class Direction { Up, Down };

struct MotorState {
  double play = 0.0;
  Direction dir = Direction::Up;
  double offset() const { return dir == Direction::Up ? 0.0 : -play; }
  // Updates the direction for a planned motion of `delta`; true when the motor reverses.
  bool reverses(double delta) const {
    if (!(play > 0.0) || std::abs(delta) <= kReversalThresholdRad) return false;
    return (delta > 0.0) != (dir == Direction::Up);
  }
};

}  // namespace

BacklashPass compensateBacklash(PlannedJob& job, const MachineProfile& profile, const MotorPlay& play) {
  BacklashPass pass;
  if (play.none()) return pass;
  const FeedLimits limits = feedLimitsOf(profile);
  const double topSpeed = std::min(limits.maxSpeedRadPerS1, limits.maxSpeedRadPerS2);
  MotorState m1{std::max(0.0, play.motor1Rad)}, m2{std::max(0.0, play.motor2Rad)};
  JointAngles planned = job.start;     // the planned (arm) pose reached so far
  JointAngles commanded = job.start;   // what the motors were told
  std::vector<JobMove> out;
  out.reserve(job.moves.size() + job.moves.size() / 8 + 4);
  std::vector<int> newIndex(job.moves.size() + 1, 0);
  auto takeUp = [&](const JobMove& like, const JointAngles& to) {
    JobMove t = like;
    const double d = std::hypot(to.theta1 - commanded.theta1, to.theta2 - commanded.theta2);
    const double duration = std::max(d / topSpeed, limits.minSegmentDurationS);
    t.target = to;
    t.feedMmPerS = 0.0;  // the arm stands still while the motor crosses its play
    t.jointFeedRadPerS = d / duration;
    t.maxDeviationMm = 0.0;
    t.feedLimited = false;
    t.dwellS = 0.0;
    out.push_back(t);
    commanded = to;
    ++pass.takeUpMoves;
    if (t.kind == JobMoveKind::Draw) job.summary.segments += 1;
    if (t.kind == JobMoveKind::Travel) job.summary.travelMoves += 1;
  };
  JobMove preamble;
  preamble.kind = JobMoveKind::Travel;
  preamble.target = job.start;
  preamble.targetXY = job.startXY;
  takeUp(preamble, {job.start.theta1 - m1.play, job.start.theta2 - m2.play});
  takeUp(preamble, job.start);
  // The take-up a motion move from `planned` to `target` needs, if it reverses a motor: added as
  // a move of the kind of `like`, standing at the planned pose.
  auto takeUpFor = [&](const JobMove& like, const JointAngles& target) {
    const bool r1 = m1.reverses(target.theta1 - planned.theta1);
    const bool r2 = m2.reverses(target.theta2 - planned.theta2);
    if (r1) m1.dir = m1.dir == Direction::Up ? Direction::Down : Direction::Up;
    if (r2) m2.dir = m2.dir == Direction::Up ? Direction::Down : Direction::Up;
    if (!r1 && !r2) return;
    JobMove at = like;
    at.targetXY = out.empty() ? job.startXY : out.back().targetXY;
    takeUp(at, {planned.theta1 + m1.offset(), planned.theta2 + m2.offset()});
  };
  for (size_t j = 0; j < job.moves.size(); ++j) {
    JobMove m = job.moves[j];
    if (m.kind == JobMoveKind::PenDown) {
      // A stroke whose first move reverses a motor: its take-up runs before the pen goes down
      // (a travel: pen up, laser off), not as a standstill with the pen on the paper.
      size_t k = j + 1;
      while (k < job.moves.size() && !isMotion(job.moves[k].kind)) ++k;
      if (k < job.moves.size() && job.moves[k].kind == JobMoveKind::Draw) {
        JobMove like = job.moves[k];
        like.kind = JobMoveKind::Travel;
        takeUpFor(like, job.moves[k].target);
      }
    }
    newIndex[j] = static_cast<int>(out.size());
    if (isMotion(m.kind)) {
      takeUpFor(m, m.target);
      planned = m.target;
      m.target = {planned.theta1 + m1.offset(), planned.theta2 + m2.offset()};
      commanded = m.target;
    } else {
      m.target = commanded;
    }
    out.push_back(m);
  }
  newIndex[job.moves.size()] = static_cast<int>(out.size());
  if (m1.dir == Direction::Down || m2.dir == Direction::Down) {
    JobMove last;
    last.kind = JobMoveKind::Travel;
    last.targetXY = out.back().targetXY;
    m1.dir = m2.dir = Direction::Up;
    takeUp(last, planned);
  }
  for (PlannedStroke& s : job.strokes) {
    const int end = newIndex[static_cast<size_t>(s.firstMove + s.moveCount)];
    s.firstMove = newIndex[static_cast<size_t>(s.firstMove)];
    s.moveCount = end - s.firstMove;
  }
  job.moves = std::move(out);
  // The commanded joint path, as a checked stream sees it.
  std::vector<JointAngles> poses{job.start};
  for (const JobMove& m : job.moves)
    if (isMotion(m.kind)) poses.push_back(m.target);
  const PathCheck check = checkJointPath(profile, poses);
  if (!check.ok()) {
    pass.ok = false;
    pass.problem = check.problems.front().check;
    pass.message = FB_TR("Planner", "backlash compensation: a compensated move %1").arg(describeMove(pass.problem));
  }
  return pass;
}

}  // namespace fivebar
