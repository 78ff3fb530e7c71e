// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated machine driving a real, imperfect five-bar (issue 13): SimConfig::trueMachine
// and SimMachine::drawnTrace (pen_trace.hpp). A planned job is run on the simulated board
// (instant, set up and referenced) and what the true machine's pen drew is compared with the
// plan: equal machines draw the plan within a step; a link 0.5 mm long moves every corner of a
// square where the true geometry's forward kinematics puts it; backlash leaves a circle open by
// the gap the motors' last directions predict.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/calibration/backlash.hpp"
#include "core/calibration/pattern.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "drivers/sim/sim_machine.hpp"

namespace fivebar::test {
namespace {

constexpr double kToleranceMm = 0.05;
const Vec2 kCentreMm(0.0, 170.0);

MachineProfile makerPlotter() { return preset("maker-plotter").value_or(MachineProfile{}); }

std::string plannedJob(const MachineProfile& p, const Polyline& path) {
  Layer l;
  l.id = l.name = "ink";
  l.paths.push_back(path);
  Drawing d;
  d.widthMm = d.heightMm = 60.0;
  d.layers.push_back(l);
  PlanOptions o;
  o.atMm = kCentreMm;
  o.toleranceMm = kToleranceMm;
  o.flatteningToleranceMm = 0.4 * kToleranceMm;
  const PlanResult r = planJob(d, p, o);
  EXPECT_TRUE(r.ok()) << r.message;
  return writeGcode(r.job, p);
}

Polyline square(double halfMm) {
  const double h = halfMm;
  Polyline s;
  s.points = {{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
  return s;
}

Polyline circle(double rMm) {
  Polyline c;
  for (int i = 0; i <= 360; ++i)
    c.points.emplace_back(rMm * std::cos(kPi * i / 180.0), rMm * std::sin(kPi * i / 180.0));
  return c;
}

// The job's motion targets (commanded degrees, rounded to whole steps as GRBL plans them) and
// whether each was drawn with the pen down.
struct Target {
  std::array<double, 2> deg;
  bool penDown;
};
std::vector<Target> targetsOf(const MachineProfile& p, const std::string& gcode) {
  std::vector<Target> out{{{degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2)}, false}};
  std::istringstream in(gcode);
  bool down = false;
  for (std::string line; std::getline(in, line);) {
    double x = 0, y = 0;
    if (line.rfind("M3 S1000", 0) == 0) down = true;
    if (line.rfind("M5", 0) == 0) down = false;
    if (std::sscanf(line.c_str(), "G1 X%lf Y%lf", &x, &y) == 2)
      out.push_back({{std::round(x * p.motors.stepsPerDeg1) / p.motors.stepsPerDeg1,
                      std::round(y * p.motors.stepsPerDeg2) / p.motors.stepsPerDeg2},
                     down});
  }
  return out;
}

Vec2 fk(const MachineProfile& m, const std::array<double, 2>& deg) {
  const FkResult r = forward(m.geometry, {radFromDeg(deg[0]), radFromDeg(deg[1])}, m.assembly);
  EXPECT_TRUE(r.ok());
  return r.p;
}

// Runs the job on a set-up, referenced simulated board driving `trueMachine`; returns the trace.
std::vector<std::vector<Vec2>> drawOn(const MachineProfile& profile, const MachineProfile& trueMachine,
                                      const std::string& gcode) {
  sim::SimConfig config;  // instant, set up and referenced at the home pose
  config.profile = profile;
  config.instant = config.setUp = config.referenced = true;
  config.trueMachine = trueMachine;
  sim::SimMachine m(config);
  std::istringstream in(gcode);
  for (std::string line; std::getline(in, line);) {
    m.receive(line + "\n");
    std::string answer;
    for (int i = 0; i < 1000 && answer.find('\n') == std::string::npos; ++i) {
      m.advance(0.01);
      answer += m.takeOutput();
    }
    EXPECT_TRUE(answer.rfind("ok", 0) == 0 || answer.find("[MSG:Pgm End]") != std::string::npos)
        << line << " -> " << answer;
  }
  return m.drawnTrace();
}

double distanceToPolyline(const Vec2& q, const std::vector<Vec2>& line) {
  double d = 1e9;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 ab = line[i + 1] - line[i];
    const double u = std::clamp((q - line[i]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    d = std::min(d, (q - (line[i] + u * ab)).norm());
  }
  return d;
}

TEST(TrueMachine, EqualToTheProfileDrawsThePlanWithinAStep) {
  const MachineProfile p = makerPlotter();
  const Polyline sq = square(30.0);
  const auto drawn = drawOn(p, p, plannedJob(p, sq));
  ASSERT_EQ(drawn.size(), 1u);
  std::vector<Vec2> intended;
  for (const Vec2& v : sq.points) intended.push_back(kCentreMm + v);
  // One motor step moves the pen at most about 0.06 mm here (arms 100 mm, 1/35.6 deg).
  const double stepMm = 0.06;
  for (const Vec2& q : drawn.front()) ASSERT_LE(distanceToPolyline(q, intended), kToleranceMm + stepMm);
  for (const Vec2& corner : intended) EXPECT_LE(distanceToPolyline(corner, drawn.front()), kToleranceMm + stepMm);
}

// A true machine with a link 0.5 mm long, and one with motor 1's zero 1 deg off: every move ends
// where the true machine's forward kinematics (pen_trace.hpp: commanded + zero offset, true
// geometry) puts the pen, visibly away from the plan.
TEST(TrueMachine, ALongLinkOrAZeroOffsetMovesTheSquareAsTheTrueKinematicsSay) {
  const MachineProfile p = makerPlotter();
  MachineProfile longLink = p, offZero = p;
  longLink.geometry.b1 += 0.5;
  MachineCalibration c;
  c.zeroOffsetRad1 = radFromDeg(1.0);
  offZero.calibration = c;
  const std::string job = plannedJob(p, square(30.0));
  for (const MachineProfile* real : {&longLink, &offZero}) {
    const auto drawn = drawOn(p, *real, job);
    ASSERT_EQ(drawn.size(), 1u);
    double worstOff = 0.0;
    for (const Target& t : targetsOf(p, job)) {
      if (!t.penDown) continue;
      const std::array<double, 2> trueDeg{t.deg[0] + (real == &offZero ? 1.0 : 0.0), t.deg[1]};
      const Vec2 expected = fk(*real, trueDeg), planned = fk(p, t.deg);
      EXPECT_LE(distanceToPolyline(expected, drawn.front()), 1e-6);
      worstOff = std::max(worstOff, (expected - planned).norm());
      EXPECT_GT(distanceToPolyline(planned, drawn.front()), 0.05) << "drawn where the plan meant: no error";
    }
    std::printf("%s: the square's corners drawn up to %.3f mm off the plan\n",
                real == &longLink ? "link b1 +0.5 mm" : "motor 1 zero +1 deg", worstOff);
    EXPECT_GT(worstOff, 0.3) << "the error should be visible";
  }
}

TEST(TrueMachine, BacklashLeavesACircleOpenByTheExpectedGap) {
  const MachineProfile p = makerPlotter();
  MachineProfile real = p;
  MachineCalibration c;
  c.backlashRad1 = c.backlashRad2 = radFromDeg(0.5);
  real.calibration = c;
  const std::string job = plannedJob(p, circle(20.0));
  const auto drawn = drawOn(p, real, job);
  ASSERT_EQ(drawn.size(), 1u);
  const std::vector<Target> targets = targetsOf(p, job);
  // Each drive output stands at its motor after moving up and a backlash above it after moving
  // down (core's PlayState): at the touch-down by the direction of the travel there, at the end
  // by the stroke's last one.
  std::array<double, 2> before{0, 0}, last{0, 0};
  size_t first = 0;
  while (!targets[first + 1].penDown) ++first;
  for (size_t k = 1; k < targets.size(); ++k)
    for (size_t i = 0; i < 2; ++i) {
      const double d = targets[k].deg[i] - targets[k - 1].deg[i];
      if (d == 0.0) continue;
      if (k <= first) before[i] = d > 0 ? 1 : -1;
      else if (targets[k].penDown) last[i] = d > 0 ? 1 : -1;
    }
  const auto trailing = [&](const std::array<double, 2>& m, const std::array<double, 2>& dir) {
    return std::array<double, 2>{m[0] + (dir[0] < 0 ? 0.5 : 0.0), m[1] + (dir[1] < 0 ? 0.5 : 0.0)};
  };
  const std::array<double, 2> closeAt = targets[first].deg;
  const double expectedGap = (fk(p, trailing(closeAt, last)) - fk(p, trailing(closeAt, before))).norm();
  const double gap = (drawn.front().back() - drawn.front().front()).norm();
  std::printf("backlash 0.5 deg per motor: the circle stays open by %.3f mm (expected %.3f mm)\n", gap, expectedGap);
  EXPECT_GT(expectedGap, 0.3) << "the motors reverse during the circle: a visible gap";
  EXPECT_NEAR(gap, expectedGap, 0.02);
  // Without backlash the same circle closes.
  const auto closed = drawOn(p, p, job);
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_LT((closed.front().back() - closed.front().front()).norm(), 1e-6);
}

// The check on the simulated machine: a true machine with play 0.5 deg on motor 1 and
// 0.3 deg on motor 2, and a profile calibrated for it (that play; the simulator's drive follows
// core's PlayState, the model the compensation assumes, so no zero shift). With the planner's compensation a circle
// closes and a square's corners meet, within 0.05 mm (the drawn line within the plan's tolerance
// plus one motor step); without compensation they miss by about half a millimetre.
TEST(TrueMachine, BacklashCompensationClosesACircleAndASquaresCornersMeet) {
  const MachineProfile p = makerPlotter();
  const double play1Deg = 0.5, play2Deg = 0.3;
  MachineProfile real = p;
  MachineCalibration truth;
  truth.backlashRad1 = radFromDeg(play1Deg);
  truth.backlashRad2 = radFromDeg(play2Deg);
  real.calibration = truth;
  MachineProfile calibrated = p;
  calibrated.calibration = truth;  // the simulator's play is core's PlayState: no zero shift
  MachineProfile uncompensated = calibrated;
  uncompensated.calibration->backlashRad1 = uncompensated.calibration->backlashRad2 = 0.0;
  const double stepMm = 0.06;  // one motor step at the pen, at most (see above)
  for (const Polyline& shape : {circle(20.0), square(30.0)}) {
    std::vector<Vec2> intended;
    for (const Vec2& v : shape.points) intended.push_back(kCentreMm + v);
    const auto drawn = drawOn(calibrated, real, plannedJob(calibrated, shape));
    ASSERT_EQ(drawn.size(), 1u);
    const double gap = (drawn.front().back() - drawn.front().front()).norm();
    double worstVertex = 0.0;
    for (const Vec2& v : intended) worstVertex = std::max(worstVertex, distanceToPolyline(v, drawn.front()));
    double worstDrawn = 0.0;
    for (const Vec2& q : drawn.front()) worstDrawn = std::max(worstDrawn, distanceToPolyline(q, intended));
    std::printf("%s with play %.1f/%.1f deg, compensated: gap %.4f mm, vertices within %.4f mm, drawn within %.4f mm\n",
                shape.points.size() == 5 ? "60 mm square" : "40 mm circle", play1Deg, play2Deg, gap, worstVertex,
                worstDrawn);
    const bool isSquare = shape.points.size() == 5;
    EXPECT_LT(gap, 0.05);
    // The square's corners are move ends; the circle's vertices may lie inside moves, which the
    // plan keeps within its tolerance.
    EXPECT_LT(worstVertex, isSquare ? 0.05 : kToleranceMm + stepMm);
    EXPECT_LT(worstDrawn, kToleranceMm + stepMm);
    const auto raw = drawOn(uncompensated, real, plannedJob(uncompensated, shape));
    ASSERT_EQ(raw.size(), 1u);
    double rawWorst = 0.0;
    for (const Vec2& v : intended) rawWorst = std::max(rawWorst, distanceToPolyline(v, raw.front()));
    std::printf("  the same without compensation: gap %.4f mm, vertices within %.4f mm\n",
                (raw.front().back() - raw.front().front()).norm(), rawWorst);
    EXPECT_GT(std::max(rawWorst, (raw.front().back() - raw.front().front()).norm()), 0.2);
  }
}

// The backlash fit on the simulated machine: the calibration pattern drawn by a true machine
// with play (0.5 and 0.3 deg) and links and zeros off; each dot's drawn place (the pen's
// touch-down, drawnTrace) as the measurement; the rows give each motor's play back within
// 0.03 deg, about one motor step (1/35.6 deg): GRBL puts each mark on a whole step.
TEST(TrueMachine, BacklashFittedFromThePatternDrawnOnTheSimulatedMachine) {
  const MachineProfile p = makerPlotter();
  const PatternResult pr = makeCalibrationPattern(p);
  ASSERT_TRUE(pr.pattern) << pr.error;
  const PlanResult plan = planCalibrationPattern(*pr.pattern, p);
  ASSERT_TRUE(plan.ok()) << plan.message;
  const std::string gcode = writeGcode(plan.job, p);
  for (const auto& [play1Deg, play2Deg] : {std::pair{0.5, 0.3}, std::pair{0.3, 0.5}}) {
    MachineProfile real = p;
    real.geometry.a1 += 0.3;
    real.geometry.b2 -= 0.4;
    MachineCalibration truth;
    truth.zeroOffsetRad1 = radFromDeg(0.8);
    truth.zeroOffsetRad2 = radFromDeg(-0.6);
    truth.backlashRad1 = radFromDeg(play1Deg);
    truth.backlashRad2 = radFromDeg(play2Deg);
    real.calibration = truth;
    const auto drawn = drawOn(p, real, gcode);
    // Each dot is a one-point polyline; it belongs to the mark whose nominal place is nearest.
    std::map<int, Vec2> measured;
    for (const auto& line : drawn) {
      if (line.size() != 1) continue;
      const PatternMark* best = nullptr;
      for (const PatternMark& m : pr.pattern->marks)
        if (!best || (m.nominalMm - line[0]).norm() < (best->nominalMm - line[0]).norm()) best = &m;
      ASSERT_LT((best->nominalMm - line[0]).norm(), 5.0) << "a dot far from every mark";
      EXPECT_EQ(measured.count(best->id), 0u) << "two dots for mark " << best->id;
      measured[best->id] = line[0];
    }
    EXPECT_EQ(measured.size(), pr.pattern->marks.size());
    const BacklashEstimate e = estimateBacklash(pr.pattern->marks, measured);
    ASSERT_TRUE(e.ok()) << e.error;
    std::printf("true play %.2f / %.2f deg: fitted %.4f / %.4f deg\n", play1Deg, play2Deg,
                degFromRad(e.play.motor1Rad), degFromRad(e.play.motor2Rad));
    EXPECT_NEAR(degFromRad(e.play.motor1Rad), play1Deg, 0.03);
    EXPECT_NEAR(degFromRad(e.play.motor2Rad), play2Deg, 0.03);
  }
}

}  // namespace
}  // namespace fivebar::test
