// SPDX-License-Identifier: GPL-3.0-or-later
#include "jog.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/machine/pen_kinematics.hpp"
#include "core/planning/safety.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::jog {
namespace {

Message noLinkage() { return FB_TR("Jog", "the current motor angles do not close the linkage"); }

std::string deg3(double rad) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", degFromRad(rad));
  return buf;
}

std::string jogLine(const JointAngles& q, double feedDegPerMin) {
  char f[32];
  std::snprintf(f, sizeof f, "%.1f", std::max(feedDegPerMin, 1.0));
  return "$J=G90X" + deg3(q.theta1) + "Y" + deg3(q.theta2) + "F" + f;
}

// M4 at kFrameLaserPowerShare of the drawing power (at least S1, so that the spot shows).
std::string frameLaserOn(const ToolSettings& tool) {
  char s[32];
  std::snprintf(s, sizeof s, "M4S%.0f", std::max(1.0, std::round(tool.laserPowerS * kFrameLaserPowerShare)));
  return s;
}

// Joint feed (deg/min) that moves the pen `lengthMm` in lengthMm / speed seconds.
double jointFeed(const JointAngles& a, const JointAngles& b, double lengthMm, double speedMmPerS) {
  const double jointDeg = degFromRad(std::hypot(b.theta1 - a.theta1, b.theta2 - a.theta2));
  return jointDeg / std::max(lengthMm / speedMmPerS, 1e-6) * 60.0;
}

// The pen (pen_kinematics.hpp: the calibrated pen offset) and the working mode at kinematic
// angles q; nullopt when the loop does not close.
struct PenAt {
  Vec2 pen = Vec2::Zero();
  WorkingMode mode = WorkingMode::PlusPlus;
};
std::optional<PenAt> penAt(const MachineProfile& p, const JointAngles& q) {
  const FkResult fk = forward(p.geometry, q, p.assembly);
  if (!fk.ok()) return std::nullopt;
  return PenAt{penFromDistal(calibratedPenOffset(p), p.geometry, elbow1(p.geometry, q.theta1), fk.p),
               workingModeOf(p.geometry, makePose(p.geometry, q, fk.p))};
}

// Kinematic angles that put the pen at xy, unwrapped near `near` (kinematic).
std::optional<JointAngles> ikNear(const MachineProfile& p, const Vec2& xy, WorkingMode mode,
                                  const JointAngles& near) {
  const IkResult ik = penInverse(p, xy, mode);
  if (!ik.ok()) return std::nullopt;
  return JointAngles{unwrapNear(ik.angles.theta1, near.theta1), unwrapNear(ik.angles.theta2, near.theta2)};
}

// Largest deviation (mm) of the joint-linear move a->b from the straight XY segment pa->pb.
double deviationMm(const MachineProfile& p, const JointAngles& a, const JointAngles& b,
                   const Vec2& pa, const Vec2& pb) {
  double worst = 0.0;
  const Vec2 d = pb - pa;
  for (double t : {0.25, 0.5, 0.75}) {
    const FkResult fk = penForward(p, {a.theta1 + t * (b.theta1 - a.theta1), a.theta2 + t * (b.theta2 - a.theta2)});
    if (!fk.ok()) return 1e9;
    const double len = d.norm();
    const double off = len > 0 ? std::abs(cross(d, fk.p - pa)) / len : (fk.p - pa).norm();
    worst = std::max(worst, off);
  }
  return worst;
}

// Walks the straight line from `from` along unit `dir` for up to distanceMm.
JogPlan walkLine(const MachineProfile& p, const JointAngles& start, const Vec2& from, const Vec2& dir,
                 double distanceMm, double speedMmPerS, double maxDeviationMm, WorkingMode mode,
                 bool asJog) {
  JogPlan plan;
  JointAngles q = start;
  Vec2 here = from;
  double done = 0.0, step = std::min(distanceMm, 5.0);
  while (distanceMm - done > 1e-9) {
    step = std::min(step * 2.0, distanceMm - done);
    std::optional<JointAngles> next;
    Message why;
    while (step >= kMinSubMoveMm || step >= distanceMm - done - 1e-12) {
      const Vec2 target = here + dir * step;
      next = ikNear(p, target, mode, q);
      if (!next) { why = FB_TR("Jog", "the line leaves the workspace"); }
      else if (deviationMm(p, q, *next, here, target) > maxDeviationMm) {
        next.reset();
        why = FB_TR("Jog", "the arms cannot follow the straight line closely enough");
      } else if (const MoveCheck c = checkJointMove(p, q, *next); !c.ok()) { next.reset(); why = describeMove(c); }
      if (next) break;
      step *= 0.5;
      if (step < kMinSubMoveMm) break;
    }
    if (!next) {
      plan.status = plan.lines.empty() ? JogStatus::Blocked : JogStatus::Clipped;
      plan.reason = FB_TR("Jog", "stopped after %1 mm: %2").arg(done, 2).arg(why);
      return plan;
    }
    const Vec2 target = here + dir * step;
    const JointAngles commanded = commandedFromKinematic(p.calibration, *next);  // what GRBL counts
    plan.lines.push_back(asJog ? jogLine(commanded, jointFeed(q, *next, step, speedMmPerS))
                               : stream::moveTo({degFromRad(commanded.theta1), degFromRad(commanded.theta2)}, false,
                                             jointFeed(q, *next, step, speedMmPerS)));
    plan.targets.push_back(commanded);
    q = *next;
    here = target;
    done += step;
    plan.lengthMm = done;
  }
  return plan;
}

}  // namespace

JogPlan planCartesianJog(const MachineProfile& p, const JointAngles& currentCommanded, const Vec2& direction,
                         double distanceMm, double speedMmPerS, double maxDeviationMm) {
  const JointAngles current = kinematicFromCommanded(p.calibration, currentCommanded);
  const auto here = penAt(p, current);
  if (!here || direction.norm() == 0.0) {
    JogPlan plan;
    plan.status = JogStatus::NoPosition;
    plan.reason = here ? FB_TR("Jog", "no jog direction") : noLinkage();
    return plan;
  }
  return walkLine(p, current, here->pen, direction.normalized(), distanceMm, speedMmPerS, maxDeviationMm,
                  here->mode, true);
}

JogPlan planMotorJog(const MachineProfile& p, const JointAngles& currentCommanded, int motor, double deltaDeg,
                     double feedDegPerMin) {
  JogPlan plan;
  const JointAngles current = kinematicFromCommanded(p.calibration, currentCommanded);
  JointAngles target = current;
  (motor == 1 ? target.theta1 : target.theta2) += radFromDeg(deltaDeg);
  MoveCheck c = checkJointMove(p, current, target);
  if (!c.ok()) {
    // Clip just short of the first problem.
    const double f = std::max(0.0, c.atFraction - 0.02);
    plan.reason = describeMove(c);
    target = {current.theta1 + f * (target.theta1 - current.theta1),
              current.theta2 + f * (target.theta2 - current.theta2)};
    if (f <= 0.0 || !checkJointMove(p, current, target).ok()) {
      plan.status = JogStatus::Blocked;
      return plan;
    }
    plan.status = JogStatus::Clipped;
  }
  const JointAngles commanded = commandedFromKinematic(p.calibration, target);
  plan.lines.push_back(jogLine(commanded, feedDegPerMin));
  plan.targets.push_back(commanded);
  return plan;
}

std::vector<Vec2> penPathMm(const MachineProfile& p, const JointAngles& currentCommanded, const JogPlan& plan,
                            int samplesPerLeg) {
  std::vector<Vec2> path;
  JointAngles from = kinematicFromCommanded(p.calibration, currentCommanded);
  const FkResult start = forward(p.geometry, from, p.assembly);
  if (!start.ok()) return path;
  path.push_back(start.p);
  for (const JointAngles& commanded : plan.targets) {
    const JointAngles to = kinematicFromCommanded(p.calibration, commanded);
    for (int i = 1; i <= samplesPerLeg; ++i) {
      const double t = double(i) / samplesPerLeg;
      const FkResult fk = forward(p.geometry, {from.theta1 + (to.theta1 - from.theta1) * t,
                                               from.theta2 + (to.theta2 - from.theta2) * t}, p.assembly);
      if (fk.ok()) path.push_back(fk.p);
    }
    from = to;
  }
  return path;
}

JogPlan planGoTo(const MachineProfile& p, const JointAngles& currentCommanded, const Vec2& targetMm) {
  JogPlan plan;
  const JointAngles current = kinematicFromCommanded(p.calibration, currentCommanded);
  const auto here = penAt(p, current);
  if (!here) {
    plan.status = JogStatus::NoPosition;
    plan.reason = noLinkage();
    return plan;
  }
  const auto q = ikNear(p, targetMm, here->mode, current);
  const auto travel = q ? planSafeTravel(p, current, *q) : std::nullopt;
  if (!travel) {
    plan.status = JogStatus::Blocked;
    plan.reason = q ? FB_TR("Jog", "no safe travel to that point") : FB_TR("Jog", "the point is out of reach");
    return plan;
  }
  // Absolute targets whatever the console left the board in (a G91 typed there would make
  // them relative).
  plan.lines.push_back("G90");
  for (const std::string& s : stream::penUpCommands(p.tool)) plan.lines.push_back(s);
  for (const JointAngles& kinematic : *travel) {
    const JointAngles w = commandedFromKinematic(p.calibration, kinematic);
    plan.lines.push_back(stream::moveTo({degFromRad(w.theta1), degFromRad(w.theta2)}, true));
    plan.targets.push_back(w);
  }
  plan.lengthMm = (targetMm - here->pen).norm();
  return plan;
}

std::string homeCommand(const MachineProfile& p) {
  return p.hasHomingSwitches ? "$H" : referencePoseCommand(p);
}

std::string referencePoseCommand(const MachineProfile& p) {
  return "G10L20P0X" + deg3(p.homeAngles.theta1) + "Y" + deg3(p.homeAngles.theta2);
}

std::vector<Vec2> convexHull(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<Vec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

JogPlan planFrame(const MachineProfile& p, const JointAngles& current, const stream::GcodeJob& gcodeJob,
                  const stream::JobRules& rules, FrameShape shape, double speedMmPerS) {
  JogPlan plan;
  std::vector<Vec2> xy;
  std::optional<WorkingMode> mode;
  for (const auto& stroke : stream::strokesOf(gcodeJob, rules))
    for (const auto& q : stroke) {  // G-code X, Y: commanded angles
      const JointAngles a = kinematicFromCommanded(p.calibration, {radFromDeg(q[0]), radFromDeg(q[1])});
      const auto at = penAt(p, a);
      if (!at) continue;
      if (!mode) mode = at->mode;
      xy.push_back(at->pen);
    }
  if (xy.empty() || !mode) {
    plan.status = JogStatus::Blocked;
    plan.reason = FB_TR("Jog", "the job has no pen-down strokes to frame");
    return plan;
  }
  std::vector<Vec2> corners = convexHull(xy);
  if (shape == FrameShape::BoundingBox) {
    Vec2 lo = xy[0], hi = xy[0];
    for (const Vec2& v : xy) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
    corners = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  }
  const auto first = ikNear(p, corners[0], *mode, kinematicFromCommanded(p.calibration, current));
  JogPlan travel;
  if (first) travel = planGoTo(p, current, corners[0]);
  else travel.status = JogStatus::Blocked;
  if (!travel.ok()) {
    plan.status = JogStatus::Blocked;
    plan.reason = FB_TR("Jog", "cannot reach the frame's first corner: %1").arg(travel.reason);
    return plan;
  }
  plan = travel;
  if (p.tool.kind == ToolKind::Laser) plan.lines.push_back(frameLaserOn(p.tool));
  JointAngles q = kinematicFromCommanded(p.calibration, travel.targets.back());  // walkLine: kinematic
  for (size_t i = 1; i <= corners.size(); ++i) {
    const Vec2 a = corners[i - 1], b = corners[i % corners.size()];
    const JogPlan edge = walkLine(p, q, a, (b - a).normalized(), (b - a).norm(), speedMmPerS,
                                  kDefaultDeviationMm, *mode, false);
    if (edge.status != JogStatus::Ok) {
      plan.status = JogStatus::Blocked;
      plan.reason = FB_TR("Jog", "frame edge %1: %2").arg(i).arg(edge.reason);
      return plan;
    }
    plan.lines.insert(plan.lines.end(), edge.lines.begin(), edge.lines.end());
    plan.targets.insert(plan.targets.end(), edge.targets.begin(), edge.targets.end());
    plan.lengthMm += edge.lengthMm;
    q = kinematicFromCommanded(p.calibration, edge.targets.back());
  }
  if (p.tool.kind == ToolKind::Laser) plan.lines.push_back("M5");
  return plan;
}

}  // namespace fivebar::jog
