// SPDX-License-Identifier: GPL-3.0-or-later
// The calibrated pen offset in the pen's kinematics (core/machine/pen_kinematics.hpp) and in the
// planner: a pen fixed to link b1 off the distal joint draws the planned points; and the joint
// limits (on commanded angles) judged in one convention when the calibration has zero offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/Geometry>

#include "core/calibration/model.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/planning/feasibility.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/trajectory.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

MachineProfile makerPlotter() { return preset("maker-plotter").value_or(MachineProfile{}); }

MachineProfile withPenOffset(MachineProfile p, double alongMm, double normalMm) {
  MachineCalibration c;
  c.penOffset = PenOffset{alongMm, normalMm};
  p.calibration = c;
  return p;
}

double distanceToPolyline(const Vec2& q, const std::vector<Vec2>& line) {
  double d = 1e18;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 ab = line[i + 1] - line[i];
    const double u = std::clamp((q - line[i]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    d = std::min(d, (q - (line[i] + u * ab)).norm());
  }
  return d;
}

TEST(PenKinematics, ForwardOfInverseIsThePenInEveryModeAndTheModeIsKept) {
  const Geometry g = makerPlotter().geometry;
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> offset(-6.0, 6.0), x(-200.0, 200.0), y(-50.0, 280.0);
  int solved = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::optional<PenOffset> pen = PenOffset{offset(rng), offset(rng)};
    const Vec2 target(x(rng), y(rng));
    for (WorkingMode mode : kAllWorkingModes) {
      Vec2 P = Vec2::Zero();
      const IkResult ik = penInverse(g, pen, target, mode, &P);
      if (!ik.ok()) {
        EXPECT_NE(unreachableLeg(g, pen, target, mode), 0);
        continue;
      }
      EXPECT_EQ(unreachableLeg(g, pen, target, mode), 0);
      ++solved;
      // The pose closes with P on both legs, the pen where asked, in the asked working mode.
      EXPECT_NEAR((P - elbow1(g, ik.angles.theta1)).norm(), g.b1, 1e-9);
      EXPECT_NEAR((P - elbow2(g, ik.angles.theta2)).norm(), g.b2, 1e-9);
      const AssemblyMode assembly = assemblyModeOf(makePose(g, ik.angles, P));
      const FkResult fk = penForward(g, pen, ik.angles, assembly);
      ASSERT_TRUE(fk.ok());
      EXPECT_LT((fk.p - target).norm(), 1e-8) << "trial " << trial;
      EXPECT_EQ(workingModeOf(g, makePose(g, ik.angles, P)), mode) << "trial " << trial;
    }
  }
  EXPECT_GT(solved, 2000);
}

TEST(PenKinematics, WithoutAnOffsetItIsThePlainKinematicsAndTheModelUsesTheSameFormula) {
  const Geometry g = makerPlotter().geometry;
  const Vec2 target(10.0, 170.0);
  const IkResult plain = inverse(g, target, WorkingMode::PlusPlus);
  const IkResult viaPen = penInverse(g, std::nullopt, target, WorkingMode::PlusPlus);
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain.angles, viaPen.angles);
  // calibration::penPosition (the fit's model, zero offsets applied) is penForward.
  calibration::MachineParameters m;
  m.geometry = g;
  m.zeroOffsetRad1 = 0.01;
  m.penOffset = PenOffset{2.0, -1.5};
  const JointAngles commanded{1.9, 1.2};
  const auto model = calibration::penPosition(m, AssemblyMode::Plus, commanded);
  const FkResult fk = penForward(g, m.penOffset, {commanded.theta1 + 0.01, commanded.theta2}, AssemblyMode::Plus);
  ASSERT_TRUE(model && fk.ok());
  EXPECT_EQ(*model, fk.p);
}

// The job's draw moves, run on the true machine (the profile's geometry and pen offset): where its
// pen is at each move's end and along each move.
struct PenErrors {
  double worstEndMm = 0.0;    // a move's end from the intended polyline
  double worstAlongMm = 0.0;  // samples along the moves from the intended polyline
  double worstVertexMm = 0.0; // an intended vertex from the drawn line (the samples)
  double worstTargetXYMm = 0.0;  // a move's end from its targetXY
};
PenErrors penErrors(const PlannedJob& job, const MachineProfile& truth, const std::vector<Vec2>& intended) {
  calibration::MachineParameters m;
  m.geometry = truth.geometry;
  m.penOffset = truth.calibration ? truth.calibration->penOffset : std::nullopt;
  PenErrors e;
  std::vector<Vec2> drawn;
  JointAngles at = job.start;
  for (const JobMove& mv : job.moves) {
    if (!isMotion(mv.kind)) continue;
    if (mv.kind == JobMoveKind::Draw) {
      for (int k = 1; k <= 8; ++k) {
        const double u = k / 8.0;
        const auto pen = calibration::penPosition(m, truth.assembly,
                                                  {at.theta1 + u * (mv.target.theta1 - at.theta1),
                                                   at.theta2 + u * (mv.target.theta2 - at.theta2)});
        EXPECT_TRUE(pen.has_value());
        if (!pen) continue;
        e.worstAlongMm = std::max(e.worstAlongMm, distanceToPolyline(*pen, intended));
        drawn.push_back(*pen);
        if (k == 8) {
          e.worstEndMm = std::max(e.worstEndMm, distanceToPolyline(*pen, intended));
          e.worstTargetXYMm = std::max(e.worstTargetXYMm, (*pen - mv.targetXY).norm());
        }
      }
    }
    at = mv.target;
  }
  for (const Vec2& v : intended) e.worstVertexMm = std::max(e.worstVertexMm, distanceToPolyline(v, drawn));
  return e;
}

// The requirement: the planner applies the calibrated pen offset. A 60 mm square and a
// circle planned for a pen 3 mm ahead of P and 2 mm to its right are drawn by that machine's pen
// where they were meant; planned as if the pen were at P they land millimetres off.
TEST(PenOffsetPlanning, TheSimulatedPenLandsOnThePlannedPoints) {
  const MachineProfile p = withPenOffset(makerPlotter(), 3.0, -2.0);
  MachineProfile atP = p;
  atP.calibration->penOffset.reset();
  const Vec2 c(0.0, 170.0);
  std::vector<Vec2> square{c + Vec2(-30, -30), c + Vec2(30, -30), c + Vec2(30, 30), c + Vec2(-30, 30), c + Vec2(-30, -30)};
  std::vector<Vec2> circle;
  for (int k = 0; k <= 180; ++k) circle.push_back(c + 25.0 * Vec2(std::cos(kPi * k / 90), std::sin(kPi * k / 90)));
  for (const auto& shape : {square, circle}) {
    Stroke s;
    s.points = shape;
    PlanOptions o;
    o.optimise = false;
    const PlanResult r = planStrokes({s}, {}, p, p.defaultMode, o);
    ASSERT_TRUE(r.ok()) << r.message;
    const PenErrors e = penErrors(r.job, p, shape);
    std::printf("pen offset (3, -2) mm, %zu points: move ends within %.5f mm, along moves %.4f mm, vertices %.5f mm\n",
                shape.size(), e.worstEndMm, e.worstAlongMm, e.worstVertexMm);
    EXPECT_LT(e.worstEndMm, 0.01);
    EXPECT_LT(e.worstTargetXYMm, 1e-3) << "targetXY is the pen";
    EXPECT_LT(e.worstVertexMm, o.toleranceMm);
    EXPECT_LT(e.worstAlongMm, o.toleranceMm);
    EXPECT_LE(r.report.maxDeviationMm, o.toleranceMm);
    // The same shape planned for a pen at P, drawn by this pen: off by about the offset.
    const PlanResult naive = planStrokes({s}, {}, atP, p.defaultMode, o);
    ASSERT_TRUE(naive.ok());
    EXPECT_GT(penErrors(naive.job, p, shape).worstVertexMm, 2.0);
    // The simulation (trajectory) shows the pen: at each draw move's end, its targetXY.
    const Trajectory t(r.job, p);
    for (const JobMove& mv : t.job().moves)
      if (mv.kind == JobMoveKind::Draw) {
        EXPECT_LT((t.at(mv.startTimeS + mv.durationS).p - mv.targetXY).norm(), 1e-3);
      }
  }
}

// Pre-flight uses the pen's kinematics: a point only the pen (3 mm ahead of P along b1) reaches.
TEST(PenOffsetPlanning, PreflightJudgesReachForThePen) {
  const MachineProfile plain = makerPlotter();
  const MachineProfile ahead = withPenOffset(plain, 3.0, 0.0);
  const Geometry& g = plain.geometry;
  const Vec2 point = g.motor1() + (g.a1 + g.b1 + 1.0) * Vec2(std::cos(radFromDeg(75)), std::sin(radFromDeg(75)));
  Stroke s;
  s.points = {point};
  PreflightOptions o;
  o.includeHomeTravel = false;
  o.suggestFixes = false;
  const FeasibilityReport a = preflight({s}, plain, plain.defaultMode, o);
  ASSERT_FALSE(a.feasible);
  EXPECT_NE(a.problems.front().reason.text().find("out of reach of leg 1"), std::string::npos) << a.problems.front().reason.text();
  const FeasibilityReport b = preflight({s}, ahead, ahead.defaultMode, o);
  for (const PreflightProblem& pr : b.problems)
    EXPECT_EQ(pr.reason.text().find("out of reach"), std::string::npos) << pr.reason.text();
}

// Joint limits are on commanded angles (GRBL's soft limits count commanded steps). With motor 1's
// zero 1 deg off (kinematic = commanded + 1 deg), a point whose commanded angle is 0.5 deg inside
// the upper limit (its kinematic angle 0.5 deg beyond it) is feasible, unwrapped to the turn that
// keeps it inside (the kinematic angle would have picked the turn below, beyond the lower limit);
// with the offset the other way, a point 0.5 deg beyond is refused.
TEST(JointLimitConvention, AOneDegreeZeroOffsetNearTheLimitIsJudgedOnCommandedAngles) {
  MachineProfile p = makerPlotter();
  const Vec2 point(20.0, 180.0), next(20.2, 180.0);
  const IkResult ik = inverse(p.geometry, point, p.defaultMode);
  ASSERT_TRUE(ik.ok());
  for (const double offsetDeg : {1.0, -1.0}) {
    MachineCalibration c;
    c.zeroOffsetRad1 = radFromDeg(offsetDeg);
    p.calibration = c;
    const double commanded1 = ik.angles.theta1 - c.zeroOffsetRad1;
    // Upper limit 0.5 deg above (offset +1) or below (offset -1) the commanded angle. Offset +1:
    // the box a little wider than a turn, so that the kinematic angle a turn down would fit it;
    // offset -1: narrower than a turn, so that no turn of the commanded angle fits.
    p.limits.theta1Max = commanded1 + radFromDeg(offsetDeg > 0 ? 0.5 : -0.5);
    p.limits.theta1Min = p.limits.theta1Max - radFromDeg(offsetDeg > 0 ? 360.3 : 300.0);
    Stroke s;
    s.points = {point, next};
    PreflightOptions o;
    o.includeHomeTravel = false;
    o.suggestFixes = false;
    o.home = ik.angles;  // kinematic
    const FeasibilityReport r = preflight({s}, p, p.defaultMode, o);
    const JointAngles chosen = nearWithinLimits(p, ik.angles, ik.angles);
    if (offsetDeg > 0) {
      EXPECT_TRUE(r.feasible) << r.summary();
      EXPECT_DOUBLE_EQ(chosen.theta1, ik.angles.theta1) << "the turn inside the limits (commanded)";
    } else {
      ASSERT_FALSE(r.feasible);
      EXPECT_EQ(r.problems.front().status, MoveStatus::BeyondJointLimit) << r.summary();
    }
  }
  // The limit box of the kinematic angles is the commanded box moved by the offsets.
  MachineCalibration c;
  c.zeroOffsetRad1 = 0.02;
  c.zeroOffsetRad2 = -0.01;
  const JointLimits k = kinematicLimits(c, p.limits);
  EXPECT_DOUBLE_EQ(k.theta1Min, p.limits.theta1Min + 0.02);
  EXPECT_DOUBLE_EQ(k.theta2Max, p.limits.theta2Max - 0.01);
}

// The planner's turn for a stroke: the nearest turn from where the pen is, unless that takes the
// stroke beyond a joint limit and another turn keeps it inside. A coaxial machine (w = 0) turns
// rigidly when both motors turn alike, so a travel of most of a turn is safe; its limits allow
// 20 deg below the home pose and 350 deg above (commanded; zeros 1 deg off). A stroke 40 deg
// clockwise of the home pose is drawn 320 deg up, not 40 deg down beyond the lower limit.
TEST(JointLimitConvention, ThePlannerTurnsAStrokeIntoTheLimits) {
  MachineProfile p = makerPlotter();
  p.name = "coaxial";
  p.geometry = {60.0, 100.0, 60.0, 100.0, 0.0};
  const Vec2 home(0.0, 120.0);
  const IkResult ik = inverse(p.geometry, home, WorkingMode::PlusPlus);
  ASSERT_TRUE(ik.ok());
  p.defaultMode = WorkingMode::PlusPlus;
  p.assembly = assemblyModeOf(makePose(p.geometry, ik.angles, home));
  MachineCalibration c;
  c.zeroOffsetRad1 = c.zeroOffsetRad2 = radFromDeg(1.0);
  p.calibration = c;
  p.homeAngles = commandedFromKinematic(c, ik.angles);
  p.limits = {p.homeAngles.theta1 - radFromDeg(20), p.homeAngles.theta1 + radFromDeg(350),
              p.homeAngles.theta2 - radFromDeg(20), p.homeAngles.theta2 + radFromDeg(350)};
  const Eigen::Rotation2Dd clockwise40(radFromDeg(-40.0));
  Stroke s;
  s.points = {clockwise40 * home, clockwise40 * (home + Vec2(-5.0, 0.0))};
  PlanOptions o;
  o.optimise = false;
  const PlanResult r = planStrokes({s}, {}, p, p.defaultMode, o);
  ASSERT_TRUE(r.ok()) << r.message;
  bool drew = false;
  for (const JobMove& m : r.job.moves) {
    if (m.kind != JobMoveKind::Draw) continue;
    drew = true;
    const JointAngles commanded = commandedFromKinematic(p.calibration, m.target);
    EXPECT_GT(commanded.theta1, p.homeAngles.theta1 + radFromDeg(300));
    EXPECT_LE(commanded.theta1, p.limits.theta1Max);
    EXPECT_GT(commanded.theta2, p.homeAngles.theta2 + radFromDeg(300));
    EXPECT_LE(commanded.theta2, p.limits.theta2Max);
  }
  EXPECT_TRUE(drew);
}

}  // namespace
}  // namespace fivebar
