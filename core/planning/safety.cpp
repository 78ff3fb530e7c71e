// SPDX-License-Identifier: GPL-3.0-or-later
// Move checks (samples spaced by a Lipschitz bound). Contract: safety.hpp; the travel detour
// search is in travel_detour.cpp. The sampling step bound is derived next to nextStepRad below.
#include "core/planning/safety.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/kinematics/singularity.hpp"

namespace fivebar {
namespace {

// Joint step (max over motors) between two samples of a move within this distance of a joint
// limit, and the resolution of the reported smallest margin, rad. Elsewhere the step is set by
// the Lipschitz bound alone (nextStepRad), which is what makes the check safe.
constexpr double kFineJointStepRad = radFromDeg(0.1);
// Bracket width (joint rad) at which the search for the smallest margin of a move stops: the
// resolution of sampling every 0.1 deg, at the cost of a few samples.
constexpr double kMarginSearchRad = kFineJointStepRad;
// Smallest step the adaptive rule may take, so a move always ends, rad.
constexpr double kMinJointStepRad = 1e-5;
// Type II margin below which the forward-kinematics branch is ambiguous: a move that gets this
// close may leave in the other assembly mode, rad.
constexpr double kAssemblyFlipMarginRad = radFromDeg(0.05);
const double kSinAssemblyFlipMargin = std::sin(kAssemblyFlipMarginRad);

struct Sample {
  MoveStatus status = MoveStatus::Ok;
  Vec2 p = Vec2::Zero();  // end-effector (or best estimate when the loop does not close), mm
  double sinTypeII = 0.0;  // sin of the type II margin (the margin is asin of it, <= pi/2)
  double sinTypeI = 0.0;   // sin of the smaller type I margin
  double typeIIRad() const { return std::asin(sinTypeII); }
  bool closes = false;
};

// sin of a threshold angle, memoised (two slots: the type II and type I margins alternate).
double sinOfThreshold(double angleRad) {
  thread_local double angle[2] = {0.0, 0.0}, sine[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i)
    if (angle[i] == angleRad) return sine[i];
  angle[1] = angle[0], sine[1] = sine[0];
  angle[0] = angleRad, sine[0] = std::sin(angleRad);
  return sine[0];
}

bool withinLimits(const JointLimits& l, const JointAngles& q) {
  return q.theta1 >= l.theta1Min && q.theta1 <= l.theta1Max && q.theta2 >= l.theta2Min &&
         q.theta2 <= l.theta2Max;
}

// Forward kinematics from the elbows, as forward() in kinematics.cpp (product form of the
// half-chord); nullopt when the floating links cannot close.
std::optional<Vec2> closeLoop(const Geometry& g, const Vec2& R1, const Vec2& R2, AssemblyMode m) {
  const Vec2 r = R2 - R1;
  const double d = r.norm();
  if (d < 1e-12 || d > g.b1 + g.b2 + kReachToleranceMm ||
      d < std::abs(g.b1 - g.b2) - kReachToleranceMm)
    return std::nullopt;
  const Vec2 u = r / d;
  const double along = (g.b1 * g.b1 - g.b2 * g.b2 + d * d) / (2.0 * d);
  const double sum = g.b1 + g.b2, diff = g.b1 - g.b2;
  const double h2 = (sum - d) * (sum + d) * (d - diff) * (d + diff) / (4.0 * d * d);
  const double h = std::sqrt(std::max(0.0, h2)) * (m == AssemblyMode::Plus ? 1.0 : -1.0);
  return Vec2(R1 + along * u + h * Vec2(-u.y(), u.x()));
}

// Evaluates one pose: limits, closure (in profile.assembly), margins from
// sin(typeII) = |cross(P-R1, P-R2)| / (b1 b2), sin(typeIi) = |cross(Ri-Mi, P-Ri)| / (ai bi).
Sample evaluate(const MachineProfile& pr, const JointAngles& q) {
  const Geometry& g = pr.geometry;
  Sample s;
  const Vec2 R1 = elbow1(g, q.theta1), R2 = elbow2(g, q.theta2);
  const auto p = closeLoop(g, R1, R2, pr.assembly);
  if (!p) {
    s.p = 0.5 * (R1 + R2);
    s.status = withinLimits(pr.limits, commandedFromKinematic(pr.calibration, q)) ? MoveStatus::CannotClose
                                                                                 : MoveStatus::BeyondJointLimit;
    return s;
  }
  s.closes = true;
  s.p = *p;
  const Vec2 d1 = s.p - R1, d2 = s.p - R2;
  s.sinTypeII = std::min(1.0, std::abs(cross(d1, d2)) / (g.b1 * g.b2));
  s.sinTypeI = std::min(std::abs(cross(R1 - g.motor1(), d1)) / (g.a1 * g.b1),
                        std::abs(cross(R2 - g.motor2(), d2)) / (g.a2 * g.b2));
  if (!withinLimits(pr.limits, commandedFromKinematic(pr.calibration, q)))
    s.status = MoveStatus::BeyondJointLimit;
  else if (s.sinTypeII < kSinAssemblyFlipMargin)
    s.status = MoveStatus::AssemblyChange;
  else if (s.sinTypeII < sinOfThreshold(pr.typeIIMarginRad))
    s.status = MoveStatus::NearTypeII;
  else if (s.sinTypeI < sinOfThreshold(pr.typeIMarginRad))
    s.status = MoveStatus::NearTypeI;
  return s;
}

// Next joint step (max over motors, rad) from a safe sample. With mu the angle between the
// floating links, the passive link rates obey |phi_i'| <= (a1 + a2) delta' / (b_i sin mu), so
// the type II margin changes at most L2 = (a1 + a2)(1/b1 + 1/b2) / sin(mu) per radian of joint
// step and the type I margin at most L1 = 1 + (a1 + a2) / (min b sin mu). Taking half of the
// remaining distance to each threshold, evaluated with the margin the step can at worst reach,
// keeps every excursion between two samples above the thresholds. Distances are taken in
// sines, which never exceed the distances in angles (d asin / dx >= 1); the worst margin is
// the one whose sine is midway, below the angle midway since asin is convex.
// Joint limits need no interior samples (the limit box is convex and the move is linear in joint
// space); steps are only kept fine (kFineJointStepRad) within that distance of a limit, so the
// first sample beyond it is reported as precisely as with dense sampling.
double nextStepRad(const MachineProfile& pr, const JointAngles& q, const Sample& s) {
  const Geometry& g = pr.geometry;
  const JointLimits& l = pr.limits;  // commanded angles
  const JointAngles c = commandedFromKinematic(pr.calibration, q);
  const double toLimit = std::min({c.theta1 - l.theta1Min, l.theta1Max - c.theta1,
                                   c.theta2 - l.theta2Min, l.theta2Max - c.theta2});
  const double sinThrII = std::max(sinOfThreshold(pr.typeIIMarginRad), kSinAssemblyFlipMargin);
  const double gapII = s.sinTypeII - sinThrII;
  const double sinWorst = std::max(sinThrII + 0.5 * gapII, 1e-9);
  const double reach = g.a1 + g.a2;
  const double rateII = reach * (1.0 / g.b1 + 1.0 / g.b2) / sinWorst;
  double step = std::min(std::max(toLimit, kFineJointStepRad), 0.5 * gapII / rateII);
  if (pr.typeIMarginRad > 0.0) {
    const double rateI = 1.0 + reach / (std::min(g.b1, g.b2) * sinWorst);
    step = std::min(step, 0.5 * (s.sinTypeI - sinOfThreshold(pr.typeIMarginRad)) / rateI);
  }
  return std::max(step, kMinJointStepRad);
}

JointAngles lerp(const JointAngles& a, const JointAngles& b, double t) {
  return {a.theta1 + t * (b.theta1 - a.theta1), a.theta2 + t * (b.theta2 - a.theta2)};
}


// At a sample within kAssemblyFlipMarginRad of a type II singularity: looks ahead with fine
// steps. The move either leaves the closable region (CannotClose: the loop breaks) or passes the
// singular locus and continues (AssemblyChange: the branch may flip there).
MoveStatus throughOrOut(const MachineProfile& pr, const JointAngles& from, const JointAngles& to,
                        double t, double span) {
  constexpr int kLookAheadSteps = 4000;
  const double dt = span > 0.0 ? kMinJointStepRad / span : 1.0;
  for (int i = 1; i <= kLookAheadSteps && t < 1.0; ++i) {
    t = std::min(1.0, t + dt);
    const Sample s = evaluate(pr, lerp(from, to, t));
    if (s.status == MoveStatus::CannotClose) return MoveStatus::CannotClose;
    if (s.closes && s.sinTypeII >= kSinAssemblyFlipMargin) break;
  }
  return MoveStatus::AssemblyChange;
}

}  // namespace

MoveCheck checkPose(const MachineProfile& profile, const JointAngles& q) {
  const Sample s = evaluate(profile, q);
  MoveCheck out;
  out.status = s.status;
  out.where = s.p;
  out.minTypeIIMarginRad = s.typeIIRad();
  return out;
}

namespace {

// Smallest sin(type II margin) of the move on the bracket [lo, hi] of move fractions, by golden
// section search down to kMarginSearchRad of joint motion, starting from the known `best`
// (every evaluated sample is a real pose of the move, so the result never undershoots it).
double refineMinSin(const MachineProfile& pr, const JointAngles& from, const JointAngles& to,
                    double lo, double hi, double span, double best) {
  constexpr double kGolden = 0.6180339887498949;
  auto sinAt = [&](double t) {
    const Sample s = evaluate(pr, lerp(from, to, t));
    return s.closes ? s.sinTypeII : 0.0;
  };
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = sinAt(x1), f2 = sinAt(x2);
  best = std::min({best, f1, f2});
  while ((hi - lo) * span > kMarginSearchRad) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = sinAt(x1);
      best = std::min(best, f1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = sinAt(x2);
      best = std::min(best, f2);
    }
  }
  return best;
}

// The samples around the smallest type II margin of a walked move: where a finer search for the
// true minimum would look (move fractions lo..hi of the move from -> to).
struct MinBracket {
  JointAngles from, to;
  double lo = 0.0, hi = 0.0, span = 0.0;
  double minSin = 2.0;
  bool coarse() const { return (hi - lo) * span > kFineJointStepRad; }
};

// Walks one move from an evaluated start sample to an evaluated end sample; `out` gets the
// first problem after the start (the start itself is the caller's business) and the smallest
// sampled margin, `bracket` the samples around it. Samples are spaced by nextStepRad.
void walk(const MachineProfile& pr, const JointAngles& from, const JointAngles& to,
          const Sample& start, const Sample& end, MoveCheck& out, MinBracket& bracket) {
  const double span = std::max(std::abs(to.theta1 - from.theta1), std::abs(to.theta2 - from.theta2));
  double t = 0.0, prevT = 0.0;
  double minLo = 0.0, minHi = 0.0;  // the samples around the smallest one (move fractions)
  bool minOpen = true;              // the sample after the smallest one is not taken yet
  Sample s = start;
  double minSin = start.sinTypeII;
  while (t < 1.0) {
    const JointAngles q = lerp(from, to, t);
    prevT = t;
    t = span > 0.0 ? std::min(1.0, t + nextStepRad(pr, q, s) / span) : 1.0;
    s = t < 1.0 ? evaluate(pr, lerp(from, to, t)) : end;
    if (minOpen) minHi = t, minOpen = false;
    if (s.sinTypeII < minSin) minSin = s.sinTypeII, minLo = prevT, minHi = t, minOpen = true;
    if (s.status != MoveStatus::Ok) {
      out.minTypeIIMarginRad = std::min(out.minTypeIIMarginRad, std::asin(minSin));
      out.status = s.status == MoveStatus::AssemblyChange ? throughOrOut(pr, from, to, t, span)
                                                          : s.status;
      out.atFraction = t;
      out.where = s.p;
      return;
    }
  }
  bracket = {from, to, minLo, minHi, span, minSin};
  out.minTypeIIMarginRad = std::min(out.minTypeIIMarginRad, std::asin(minSin));
  out.atFraction = 1.0;
  out.where = end.p;
}

// The smallest margin (rad) of a safe move, refined around its smallest sample when the
// samples there are coarser than kFineJointStepRad (refineMinSin).
double refinedMargin(const MachineProfile& pr, const MinBracket& b) {
  const double minSin =
      b.coarse() ? refineMinSin(pr, b.from, b.to, b.lo, b.hi, b.span, b.minSin) : b.minSin;
  return std::asin(minSin);
}

MoveCheck startCheck(const Sample& s) {
  MoveCheck c;
  c.status = s.status;
  c.where = s.p;
  c.minTypeIIMarginRad = s.typeIIRad();
  return c;
}

}  // namespace

MoveCheck checkJointMove(const MachineProfile& profile, const JointAngles& from,
                         const JointAngles& to) {
  const Sample start = evaluate(profile, from);
  MoveCheck out = startCheck(start);
  if (!out.ok()) return out;
  MinBracket bracket;
  walk(profile, from, to, start, evaluate(profile, to), out, bracket);
  if (out.ok()) out.minTypeIIMarginRad = std::min(out.minTypeIIMarginRad, refinedMargin(profile, bracket));
  return out;
}

PathCheck checkJointPath(const MachineProfile& profile, const std::vector<JointAngles>& poses) {
  PathCheck path;
  path.minTypeIIMarginRad = std::numeric_limits<double>::infinity();
  if (poses.empty()) return path;
  Sample prev = evaluate(profile, poses[0]);
  path.minTypeIIMarginRad = prev.typeIIRad();
  if (prev.status != MoveStatus::Ok) path.problems.push_back({0, startCheck(prev)});
  MinBracket smallest;  // of the safe moves: refined once, at the end
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const Sample end = evaluate(profile, poses[i + 1]);
    MoveCheck c = startCheck(prev);
    if (prev.status == MoveStatus::Ok) {
      MinBracket b;
      walk(profile, poses[i], poses[i + 1], prev, end, c, b);
      if (!c.ok()) path.problems.push_back({i, c});
      else if (b.minSin < smallest.minSin) smallest = b;
    } else if (end.status != MoveStatus::Ok) {  // starts at a reported pose: only its end counts
      c = startCheck(end);
      c.atFraction = 1.0;
      path.problems.push_back({i, c});
    }
    path.minTypeIIMarginRad = std::min(path.minTypeIIMarginRad, c.minTypeIIMarginRad);
    prev = end;
  }
  if (smallest.minSin <= 1.0)
    path.minTypeIIMarginRad = std::min(path.minTypeIIMarginRad, refinedMargin(profile, smallest));
  return path;
}

JointAngles nearWithinLimits(const MachineProfile& profile, const JointAngles& kinematic, const JointAngles& near) {
  const JointAngles q{unwrapNear(kinematic.theta1, near.theta1), unwrapNear(kinematic.theta2, near.theta2)};
  const JointAngles c = commandedFromKinematic(profile.calibration, q);  // limits are commanded
  const JointLimits& l = profile.limits;
  const auto turnInto = [](double commanded, double lo, double hi) {
    for (double shift : {0.0, 2.0 * kPi, -2.0 * kPi})
      if (commanded + shift >= lo && commanded + shift <= hi) return shift;
    return 0.0;
  };
  return {q.theta1 + turnInto(c.theta1, l.theta1Min, l.theta1Max),
          q.theta2 + turnInto(c.theta2, l.theta2Min, l.theta2Max)};
}

std::string_view toString(MoveStatus status) {
  switch (status) {
    case MoveStatus::Ok: return "ok";
    case MoveStatus::NearTypeII: return "near type II";
    case MoveStatus::NearTypeI: return "near type I";
    case MoveStatus::BeyondJointLimit: return "beyond joint limit";
    case MoveStatus::CannotClose: return "cannot close";
    case MoveStatus::AssemblyChange: return "assembly change";
  }
  return "unknown";
}

Message describeMove(const MoveCheck& check) {
  const auto at = [&](Message m) {
    return std::move(m.arg(check.where.x(), 1).arg(check.where.y(), 1).arg(100.0 * check.atFraction, 0));
  };
  switch (check.status) {
    case MoveStatus::Ok:
      return FB_TR("Safety", "safe; closest approach to a type II singularity %1 deg")
          .arg(degFromRad(check.minTypeIIMarginRad), 1);
    case MoveStatus::NearTypeII:
      return FB_TR("Safety", "passes within %1 deg of a type II singularity at (%2, %3) mm, %4% along the move")
          .arg(degFromRad(check.minTypeIIMarginRad), 1).arg(check.where.x(), 1).arg(check.where.y(), 1)
          .arg(100.0 * check.atFraction, 0);
    case MoveStatus::NearTypeI:
      return at(FB_TR("Safety", "a leg comes too close to full stretch or fold (type I) at (%1, %2) mm, %3% along the move"));
    case MoveStatus::BeyondJointLimit:
      return at(FB_TR("Safety", "goes beyond a motor's joint limit at (%1, %2) mm, %3% along the move"));
    case MoveStatus::CannotClose:
      return at(FB_TR("Safety", "leaves the reachable workspace (the linkage cannot close) at (%1, %2) mm, %3% along the move"));
    case MoveStatus::AssemblyChange:
      return at(FB_TR("Safety", "passes through a type II singularity, where the assembly mode can flip at (%1, %2) mm, %3% along the move"));
  }
  return FB_TR("Safety", "unknown move status");
}

std::string describe(const MoveCheck& check) { return describeMove(check).text(); }

}  // namespace fivebar
