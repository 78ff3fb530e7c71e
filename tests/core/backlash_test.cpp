// SPDX-License-Identifier: GPL-3.0-or-later
// Backlash: the play model, host compensation (a circle closes, a square's corners meet), and the
// estimate from the pattern's backlash rows.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/calibration/backlash.hpp"
#include "core/calibration/pattern.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/backlash_compensation.hpp"
#include "core/planning/planner.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const MotorPlay kPlay{radFromDeg(0.5), radFromDeg(0.3)};

TEST(PlayState, ArmFollowsInsideTheDeadBand) {
  PlayState s(MotorPlay{0.1, 0.2}, {1.0, 2.0});
  EXPECT_DOUBLE_EQ(s.arm().theta1, 1.0);
  s.moveTo({0.95, 2.0});  // down by half the play: the arm stays
  EXPECT_DOUBLE_EQ(s.arm().theta1, 1.0);
  s.moveTo({0.8, 2.0});   // further down: pulled, at motor + play
  EXPECT_DOUBLE_EQ(s.arm().theta1, 0.9);
  s.moveTo({0.85, 2.0});  // up again: inside the band
  EXPECT_DOUBLE_EQ(s.arm().theta1, 0.9);
  s.moveTo({1.0, 2.0});   // pushed
  EXPECT_DOUBLE_EQ(s.arm().theta1, 1.0);
  PlayState lag(MotorPlay{0.1, 0.2}, {0.0, 0.0}, {0.5, 0.15});
  EXPECT_DOUBLE_EQ(lag.arm().theta1, 0.1);  // clamped to the play
  EXPECT_DOUBLE_EQ(lag.arm().theta2, 0.15);
}

PlannedJob planOne(const std::vector<Vec2>& stroke, const MachineProfile& p) {
  Stroke s;
  s.points = stroke;
  PlanOptions o;
  o.optimise = false;
  const PlanResult r = planStrokes({s}, {}, p, p.defaultMode, o);
  EXPECT_TRUE(r.ok()) << r.message;
  return r.job;
}

// Largest distance between where the machine with play has the pen at the end of each drawing
// move and where the plan has it (every corner and vertex of the stroke), and the gap between the
// pen's first and last position of the drawn stroke.
struct DrawnErrors {
  double worstVertexMm = 0.0;
  double closureGapMm = 0.0;
};
DrawnErrors drawnErrors(const PlannedJob& job, const MachineProfile& p, const MotorPlay& play,
                        const JointAngles& lag = {}) {
  DrawnErrors e;
  PlayState s(play, job.start, lag);
  bool down = false;
  Vec2 first = Vec2::Zero(), last = Vec2::Zero();
  for (const JobMove& m : job.moves) {
    if (m.kind == JobMoveKind::PenDown) {
      down = true;
      first = forward(p.geometry, s.arm(), p.assembly).p;
    }
    if (m.kind == JobMoveKind::PenUp) down = false;
    if (!isMotion(m.kind)) continue;
    s.moveTo(m.target);  // each motor moves monotonically along a joint-linear move
    const Vec2 pen = forward(p.geometry, s.arm(), p.assembly).p;
    if (down && m.kind == JobMoveKind::Draw) {
      e.worstVertexMm = std::max(e.worstVertexMm, (pen - m.targetXY).norm());
      last = pen;
    }
  }
  e.closureGapMm = (last - first).norm();
  return e;
}

std::vector<Vec2> circle(const Vec2& c, double r, int n) {
  std::vector<Vec2> pts;
  for (int k = 0; k <= n; ++k) pts.push_back(c + r * Vec2(std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n)));
  return pts;
}

TEST(BacklashCompensation, CircleClosesAndSquareCornersMeet) {
  const MachineProfile p = *preset("maker-plotter");
  const Vec2 c(0.0, 180.0);
  const std::vector<Vec2> square{c + Vec2(-30, -30), c + Vec2(30, -30), c + Vec2(30, 30), c + Vec2(-30, 30),
                                 c + Vec2(-30, -30)};
  for (const auto& shape : {circle(c, 30.0, 180), square}) {
    PlannedJob job = planOne(shape, p);
    const DrawnErrors before = drawnErrors(job, p, kPlay);
    EXPECT_GT(before.worstVertexMm, 0.3);  // visibly off without compensation
    const BacklashPass pass = compensateBacklash(job, p, kPlay);
    ASSERT_TRUE(pass.ok) << pass.message;
    EXPECT_GT(pass.takeUpMoves, 2u);
    // Whatever the arms' lag before the job (the preamble takes it up).
    for (const JointAngles lag : {JointAngles{0, 0}, JointAngles{kPlay.motor1Rad, kPlay.motor2Rad},
                                  JointAngles{0.5 * kPlay.motor1Rad, 0}}) {
      const DrawnErrors after = drawnErrors(job, p, kPlay, lag);
      EXPECT_LT(after.worstVertexMm, 0.05);
      EXPECT_LT(after.closureGapMm, 0.05);
    }
  }
  // The circle without compensation does not close.
  const PlannedJob raw = planOne(circle(c, 30.0, 180), p);
  EXPECT_GT(drawnErrors(raw, p, kPlay).closureGapMm, 0.3);
}

TEST(BacklashCompensation, DrawnCurveFollowsThePlanAlongEveryMove) {
  // Between the vertices too: the pen path with play and compensation against the plan's own
  // path without play (same samples), a circle.
  const MachineProfile p = *preset("maker-plotter");
  const PlannedJob plan = planOne(circle(Vec2(20, 170), 25.0, 120), p);
  PlannedJob comp = plan;
  ASSERT_TRUE(compensateBacklash(comp, p, kPlay).ok);
  const auto ideal = drawnWithPlay(plan, p.geometry, p.assembly, MotorPlay{});
  const auto real = drawnWithPlay(comp, p.geometry, p.assembly, kPlay);
  ASSERT_EQ(ideal.size(), 1u);
  ASSERT_EQ(real.size(), 1u);
  double worst = 0.0;
  for (const Vec2& q : real[0]) {
    double best = 1e18;
    for (size_t i = 0; i + 1 < ideal[0].size(); ++i) {
      const Vec2 a = ideal[0][i], d = ideal[0][i + 1] - a;
      const double t = d.squaredNorm() > 0 ? std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * d - q).norm());
    }
    worst = std::max(worst, best);
  }
  EXPECT_LT(worst, 0.05);
}

TEST(BacklashCompensation, NoPlayLeavesTheJobAndItsGcodeUnchanged) {
  const MachineProfile p = *preset("maker-plotter");
  PlannedJob job = planOne(circle(Vec2(0, 170), 20.0, 60), p);
  const std::string before = writeGcode(job, p);
  const BacklashPass pass = compensateBacklash(job, p, MotorPlay{});
  EXPECT_EQ(pass.takeUpMoves, 0u);
  EXPECT_EQ(writeGcode(job, p), before);
}

TEST(BacklashCompensation, EndsAtTheStartPoseAndKeepsStrokesConsistent) {
  const MachineProfile p = *preset("maker-plotter");
  PlannedJob job = planOne(circle(Vec2(0, 170), 20.0, 60), p);
  ASSERT_TRUE(compensateBacklash(job, p, kPlay).ok);
  const JobMove* last = nullptr;
  for (const JobMove& m : job.moves)
    if (isMotion(m.kind)) last = &m;
  ASSERT_NE(last, nullptr);
  EXPECT_DOUBLE_EQ(last->target.theta1, job.start.theta1);
  EXPECT_DOUBLE_EQ(last->target.theta2, job.start.theta2);
  ASSERT_EQ(job.strokes.size(), 1u);
  const PlannedStroke& s = job.strokes[0];
  EXPECT_EQ(job.moves[static_cast<size_t>(s.firstMove - 1)].kind, JobMoveKind::PenDown);
  for (int i = s.firstMove; i < s.firstMove + s.moveCount; ++i)
    EXPECT_EQ(job.moves[static_cast<size_t>(i)].kind, JobMoveKind::Draw);
  EXPECT_EQ(job.moves[static_cast<size_t>(s.firstMove + s.moveCount)].kind, JobMoveKind::PenUp);
}

// A stroke whose first move reverses a motor gets its take-up before the pen goes down, as a
// travel (pen up, laser at S0): at no touch-down does the pen stand on the paper while a motor
// crosses its play (a blot, or a burn with a laser); the strokes are still drawn true.
TEST(BacklashCompensation, TakeUpBeforeATouchDownRunsWithThePenUp) {
  const MachineProfile p = *preset("maker-plotter");
  std::vector<Stroke> strokes;
  for (int k = 0; k < 8; ++k) {  // short strokes in eight directions around a circle
    const double a = kPi * k / 4.0;
    const Vec2 from = Vec2(0, 175) + 25.0 * Vec2(std::cos(a), std::sin(a));
    Stroke s;
    s.points = {from, from + 12.0 * Vec2(std::cos(a + 2.0), std::sin(a + 2.0))};
    s.pathIndex = k;
    strokes.push_back(s);
  }
  PlanOptions o;
  o.optimise = false;
  const PlanResult r = planStrokes(strokes, {}, p, p.defaultMode, o);
  ASSERT_TRUE(r.ok()) << r.message;
  PlannedJob job = r.job;
  ASSERT_TRUE(compensateBacklash(job, p, kPlay).ok);
  int beforeTouchDown = 0;
  PlayState s(kPlay, job.start);
  bool firstAfterDown = false;
  for (size_t i = 0; i < job.moves.size(); ++i) {
    const JobMove& m = job.moves[i];
    if (m.kind == JobMoveKind::PenDown) {
      firstAfterDown = true;
      if (i > 0 && job.moves[i - 1].kind == JobMoveKind::Travel && job.moves[i - 1].feedMmPerS == 0.0)
        ++beforeTouchDown;
    }
    if (!isMotion(m.kind)) continue;
    const JointAngles before = s.arm();
    s.moveTo(m.target);
    if (firstAfterDown) {
      EXPECT_EQ(m.kind, JobMoveKind::Draw);
      EXPECT_GT(std::hypot(s.arm().theta1 - before.theta1, s.arm().theta2 - before.theta2), 1e-6)
          << "move " << i << ": the pen stands still on the paper";
      firstAfterDown = false;
    }
  }
  EXPECT_GT(beforeTouchDown, 0) << "no stroke started by reversing a motor: the test shows nothing";
  EXPECT_LT(drawnErrors(job, p, kPlay).worstVertexMm, 0.05);
}

// The planner applies the compensation of the profile's calibration to every job.
TEST(BacklashCompensation, PlannerAppliesTheProfilesBacklash) {
  MachineProfile p = *preset("maker-plotter");
  const PlannedJob plain = planOne(circle(Vec2(0, 175), 30.0, 90), p);
  p.calibration = MachineCalibration{};
  EXPECT_EQ(writeGcode(planOne(circle(Vec2(0, 175), 30.0, 90), p), p), writeGcode(plain, p))
      << "a calibration without backlash changes nothing";
  p.calibration->backlashRad1 = kPlay.motor1Rad;
  p.calibration->backlashRad2 = kPlay.motor2Rad;
  const PlannedJob comp = planOne(circle(Vec2(0, 175), 30.0, 90), p);
  EXPECT_GT(comp.moves.size(), plain.moves.size());
  EXPECT_GT(comp.summary.estimatedTimeS, plain.summary.estimatedTimeS);  // times refilled
  const DrawnErrors e = drawnErrors(comp, p, kPlay);
  EXPECT_LT(e.worstVertexMm, 0.05);
  EXPECT_LT(e.closureGapMm, 0.05);
  EXPECT_GT(drawnErrors(plain, p, kPlay).closureGapMm, 0.3);
}

// Measured positions of the pattern's marks on a machine with play, in a turned and mirrored
// paper frame with noise: the rows give each motor's play back.
TEST(BacklashEstimate, FromThePatternsRows) {
  const MachineProfile p = *preset("maker-plotter");
  const PatternResult pr = makeCalibrationPattern(p);
  ASSERT_TRUE(pr.pattern) << pr.error;
  std::mt19937_64 rng = test::rng();
  std::normal_distribution<double> noise(0.0, 0.02);
  for (bool imperfect : {false, true}) {
    // The true machine: play, and (imperfect) links 0.4 mm off and zeros 0.8 deg off.
    Geometry g = p.geometry;
    JointAngles zero{0, 0};
    if (imperfect) {
      g.a1 += 0.4; g.b2 -= 0.3; g.w += 0.4;
      zero = {radFromDeg(0.8), radFromDeg(-0.6)};
    }
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(2.0).toRotationMatrix() * Eigen::Vector2d(1, -1).asDiagonal().toDenseMatrix();
    std::map<int, Vec2> measured;
    for (const PatternMark& m : pr.pattern->marks) {
      JointAngles arm{m.q.theta1 + zero.theta1, m.q.theta2 + zero.theta2};
      if (m.approach1 == Approach::Minus) arm.theta1 += kPlay.motor1Rad;
      if (m.approach2 == Approach::Minus) arm.theta2 += kPlay.motor2Rad;
      const FkResult fk = forward(g, arm, p.assembly);
      ASSERT_TRUE(fk.ok());
      measured[m.id] = R * fk.p + Vec2(150, 20) + Vec2(noise(rng), noise(rng));
    }
    const BacklashEstimate e = estimateBacklash(pr.pattern->marks, measured);
    ASSERT_TRUE(e.ok()) << e.error;
    EXPECT_EQ(e.rowsMotor1, 2);
    EXPECT_EQ(e.rowsMotor2, 2);
    EXPECT_NEAR(degFromRad(e.play.motor1Rad), 0.5, 0.03) << "imperfect " << imperfect;
    EXPECT_NEAR(degFromRad(e.play.motor2Rad), 0.3, 0.03) << "imperfect " << imperfect;
  }
  // Too few marks: a reason.
  EXPECT_NE(estimateBacklash(pr.pattern->marks, {{1, Vec2(0, 0)}}).error.text().find("at least 3"), std::string::npos);
}

}  // namespace
}  // namespace fivebar
