#include "widgets/jog_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "core/safety.hpp"
#include "core/units.hpp"

namespace fivebar::widgets {
namespace {

// Samples per joint-linear leg for the path preview and the leg length estimate.
constexpr int kLegSamples = 24;

std::optional<Vec2> penAt(const MachineProfile& profile, const JointAngles& q) {
  const FkResult fk = forward(profile.geometry, q, profile.assembly);
  if (!fk.ok()) return std::nullopt;
  return fk.p;
}

JointAngles lerp(const JointAngles& a, const JointAngles& b, double t) {
  return {a.theta1 + (b.theta1 - a.theta1) * t, a.theta2 + (b.theta2 - a.theta2) * t};
}

double jointDistanceDeg(const JointAngles& a, const JointAngles& b) {
  return degFromRad(std::hypot(b.theta1 - a.theta1, b.theta2 - a.theta2));
}

// Feed (deg/min) that makes a joint-linear move of pen length lengthMm last lengthMm / speed.
double feedFor(const JointAngles& from, const JointAngles& to, double lengthMm, double speedMmPerS) {
  const double timeS = std::max(lengthMm, 1e-6) / std::max(speedMmPerS, 1e-6);
  return jointDistanceDeg(from, to) / timeS * 60.0;
}

// Distance from point p to the segment a-b (mm).
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + ab * t)).norm();
}

// A sub-move may be sent when it is fully safe, or when it starts inside a margin band and
// leaves it no worse than it started (so the user can always jog out of a band).
bool acceptable(const MachineProfile& profile, const JointAngles& from, const JointAngles& to,
                MoveCheck* failed) {
  const MoveCheck check = checkJointMove(profile, from, to);
  if (check.ok()) return true;
  *failed = check;
  if (int(check.status) < 0) return false;
  const MoveCheck start = checkPose(profile, from);
  if (start.ok()) return false;
  const MoveCheck end = checkPose(profile, to);
  return int(end.status) >= 0 && end.minTypeIIMarginRad >= start.minTypeIIMarginRad;
}

JogPlan refuse(std::string reason, const Vec2& start) {
  JogPlan plan;
  plan.status = JogStatus::Refused;
  plan.reason = std::move(reason);
  plan.pathMm = {start};
  return plan;
}

void finish(JogPlan& plan, bool complete, std::string reason) {
  if (plan.moves.empty()) {
    plan.status = JogStatus::Refused;
  } else {
    plan.status = complete ? JogStatus::Full : JogStatus::Clipped;
  }
  if (!complete) plan.reason = std::move(reason);
}

// Appends the FK samples of the joint-linear leg from -> to (excluding `from`) to the path.
void appendLeg(const MachineProfile& profile, const JointAngles& from, const JointAngles& to,
               std::vector<Vec2>& path, int samples) {
  for (int i = 1; i <= samples; ++i) {
    if (auto p = penAt(profile, lerp(from, to, double(i) / samples))) path.push_back(*p);
  }
}

}  // namespace

JogPlan planCartesianJog(const MachineProfile& profile, const JointAngles& current, Vec2 deltaMm,
                         double speedMmPerS) {
  const auto startP = penAt(profile, current);
  if (!startP) return refuse("the current pose does not close the loop", Vec2::Zero());
  const double total = deltaMm.norm();
  if (!(total > 0.0)) return refuse("zero-length jog", *startP);
  const Vec2 dir = deltaMm / total;
  const WorkingMode mode = workingModeOf(profile.geometry, makePose(profile.geometry, current, *startP));

  JogPlan plan;
  plan.pathMm = {*startP};
  JointAngles q = current;
  Vec2 p = *startP;
  double done = 0.0;
  double step = kJogMaxSubMoveMm;
  while (done < total - 1e-9) {
    const double next = std::min(done + step, total);
    const Vec2 target = *startP + dir * next;
    const IkResult ik = inverse(profile.geometry, target, mode);
    if (!ik.ok()) {
      finish(plan, false, "the workspace edge is reached");
      return plan;
    }
    const JointAngles qn{unwrapNear(ik.angles.theta1, q.theta1), unwrapNear(ik.angles.theta2, q.theta2)};
    const auto mid = penAt(profile, lerp(q, qn, 0.5));
    if (!mid || distanceToSegment(*mid, p, target) > kJogChordToleranceMm) {
      if (step <= kJogMinSubMoveMm) {
        finish(plan, false, "the straight line cannot be followed here");
        return plan;
      }
      step *= 0.5;
      continue;
    }
    MoveCheck failed;
    if (!acceptable(profile, q, qn, &failed)) {
      finish(plan, false, describe(failed));
      return plan;
    }
    plan.moves.push_back({qn, feedFor(q, qn, next - done, speedMmPerS)});
    plan.pathMm.push_back(target);
    q = qn;
    p = target;
    done = next;
    step = std::min(step * 2.0, kJogMaxSubMoveMm);
  }
  finish(plan, true, {});
  return plan;
}

JogPlan planMotorJog(const MachineProfile& profile, const JointAngles& current, int motorIndex,
                     double deltaRad, double speedRadPerS) {
  const auto startP = penAt(profile, current);
  if (!startP) return refuse("the current pose does not close the loop", Vec2::Zero());
  if (deltaRad == 0.0 || (motorIndex != 1 && motorIndex != 2)) return refuse("zero-length jog", *startP);
  JogPlan plan;
  plan.pathMm = {*startP};
  const int pieces = std::max(1, int(std::ceil(std::abs(deltaRad) / kMotorJogPieceRad)));
  JointAngles q = current;
  bool complete = true;
  std::string reason;
  for (int i = 1; i <= pieces; ++i) {
    JointAngles qn = current;
    (motorIndex == 1 ? qn.theta1 : qn.theta2) += deltaRad * double(i) / pieces;
    MoveCheck failed;
    if (!acceptable(profile, q, qn, &failed)) {
      complete = false;
      reason = describe(failed);
      break;
    }
    appendLeg(profile, q, qn, plan.pathMm, 4);
    q = qn;
  }
  if (!(q == current)) plan.moves.push_back({q, degFromRad(std::abs(speedRadPerS)) * 60.0});
  finish(plan, complete, reason);
  return plan;
}

JogPlan planGoTo(const MachineProfile& profile, const JointAngles& current, Vec2 targetMm,
                 double speedMmPerS) {
  const auto startP = penAt(profile, current);
  if (!startP) return refuse("the current pose does not close the loop", Vec2::Zero());
  const WorkingMode mode = workingModeOf(profile.geometry, makePose(profile.geometry, current, *startP));
  const IkResult ik = inverse(profile.geometry, targetMm, mode);
  char where[96];
  std::snprintf(where, sizeof where, "(%.1f, %.1f) mm", targetMm.x(), targetMm.y());
  if (!ik.ok())
    return refuse(std::string(where) + " is out of reach in working mode " +
                      std::string(toString(mode)), *startP);
  const JointAngles target{unwrapNear(ik.angles.theta1, current.theta1),
                           unwrapNear(ik.angles.theta2, current.theta2)};
  const MoveCheck atTarget = checkPose(profile, target);
  if (!atTarget.ok())
    return refuse(std::string(where) + ": " + describe(atTarget), *startP);
  const auto legs = planSafeTravel(profile, current, target);
  if (!legs || legs->empty())
    return refuse("no safe travel to " + std::string(where), *startP);
  JogPlan plan;
  plan.pathMm = {*startP};
  JointAngles from = current;
  for (const JointAngles& to : *legs) {
    const std::size_t first = plan.pathMm.size();
    appendLeg(profile, from, to, plan.pathMm, kLegSamples);
    double lengthMm = 0.0;
    for (std::size_t i = first; i < plan.pathMm.size(); ++i)
      lengthMm += (plan.pathMm[i] - plan.pathMm[i - 1]).norm();
    plan.moves.push_back({to, feedFor(from, to, lengthMm, speedMmPerS)});
    from = to;
  }
  plan.status = JogStatus::Full;
  return plan;
}

std::string jogLine(const JogTarget& target) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "$J=G90 X%.3f Y%.3f F%.1f", degFromRad(target.q.theta1),
                degFromRad(target.q.theta2), std::max(target.feedDegPerMin, 0.1));
  return buf;
}

}  // namespace fivebar::widgets
