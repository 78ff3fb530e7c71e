// SPDX-License-Identifier: GPL-3.0-or-later
// MotionPlanner (motion_planner.hpp): the pen-up travel between strokes and the tool moves.
#include "core/planning/motion_planner.hpp"

#include <cmath>

#include "core/kinematics/move_samples.hpp"

namespace fivebar::motion {

// FK samples per travel move for its XY length.
constexpr int kTravelLengthSamples = 16;

// The travel from `from` to `to` (thread-safe: reads the profile only).
MotionPlanner::TravelPlan MotionPlanner::planTravel(const JointAngles& from, const JointAngles& to) const {
  TravelPlan t;
  t.from = from;
  t.to = to;
  const auto path = planSafeTravel(p_, from, to);
  if (!path) return t;
  t.found = true;
  const FkResult start = forward(g_, from, p_.assembly);
  t.chain.push_back({from, start.ok() ? penOf(from, start.p) : Vec2::Zero(), 0.0, 0.0});
  for (const JointAngles& q : *path) {
    const auto [length, end] = travelLength(t.chain.back().q, q);
    t.chain.push_back({q, penOf(q, end), 0.0, length});
  }
  t.feeds = planFeeds(g_, p_.assembly, t.chain, p_.travelSpeedMmPerS, limits_);
  return t;
}

// Adds the travel from the current pose to `target` (the one planned ahead when it starts
// here); `what` names it in a problem.
bool MotionPlanner::travelTo(const JointAngles& target, int stroke, int layer, const TravelPlan* ahead,
              const std::function<Message()>& what) {
  if (std::abs(target.theta1 - at_.theta1) < 1e-12 && std::abs(target.theta2 - at_.theta2) < 1e-12)
    return true;
  const bool reuse = ahead && ahead->from.theta1 == at_.theta1 &&
                     ahead->from.theta2 == at_.theta2 && ahead->to.theta1 == target.theta1 &&
                     ahead->to.theta2 == target.theta2;
  const TravelPlan fresh = reuse ? TravelPlan{} : planTravel(at_, target);
  const TravelPlan& t = reuse ? *ahead : fresh;
  if (!t.found) {
    const FkResult fk = forward(g_, target, p_.assembly);
    problem(what(), fk.ok() ? fk.p : atXY_, FB_TR("Planner", "no safe pen-up travel reaches it"),
            {PlanFix{FixKind::AwayFromSingular}, PlanFix{FixKind::TryAnotherMode}});
    return false;
  }
  for (size_t i = 0; i < t.feeds.size(); ++i) {
    JobMove& m = push(JobMoveKind::Travel, stroke, layer);
    m.target = t.chain[i + 1].q;
    m.targetXY = t.chain[i + 1].p;
    m.feedMmPerS = t.feeds[i].feedMmPerS;
    m.jointFeedRadPerS = t.feeds[i].jointFeedRadPerS;
    m.feedLimited = t.feeds[i].limited();
    moved(m.target, m.targetXY);
    job_.summary.travelMm += t.chain[i + 1].pathLengthMm;
    job_.summary.travelMoves += 1;
  }
  return true;
}

// XY length (mm) of the joint-linear move a -> b by FK samples, and where it ends.
std::pair<double, Vec2> MotionPlanner::travelLength(const JointAngles& a, const JointAngles& b) const {
  Vec2 p[kTravelLengthSamples + 1];
  double length = 0.0;
  if (sampleJointMove(g_, p_.assembly, a, b, kTravelLengthSamples, p)) {
    for (int k = 1; k <= kTravelLengthSamples; ++k) length += (p[k] - p[k - 1]).norm();
    return {length, p[kTravelLengthSamples]};
  }
  // Some sample does not close (a travel that passed the safety check always does): the
  // samples that do.
  Vec2 prev = forward(g_, a, p_.assembly).p;
  for (int k = 1; k <= kTravelLengthSamples; ++k) {
    const double u = static_cast<double>(k) / kTravelLengthSamples;
    const FkResult fk = forward(g_, {a.theta1 + u * (b.theta1 - a.theta1),
                                     a.theta2 + u * (b.theta2 - a.theta2)}, p_.assembly);
    if (!fk.ok()) continue;
    length += (fk.p - prev).norm();
    prev = fk.p;
  }
  return {length, prev};
}

void MotionPlanner::penDown(int stroke, int layer) {
  JobMove& m = push(JobMoveKind::PenDown, stroke, layer);
  m.toolValue = toolDownValue(layer);
  m.dwellS = p_.tool.kind == ToolKind::PenServo ? p_.tool.penDownDelayS : 0.0;
  penDown_ = true;
}

void MotionPlanner::penUp() {
  JobMove& m = push(JobMoveKind::PenUp, -1, lastLayer_);
  m.toolValue = p_.tool.kind == ToolKind::ZAxis ? p_.tool.zUpMm
                : p_.tool.kind == ToolKind::Laser ? 0.0 : p_.tool.penUpS;
  m.dwellS = p_.tool.kind == ToolKind::PenServo ? p_.tool.penUpDelayS : 0.0;
  penDown_ = false;
}

}  // namespace fivebar::motion
