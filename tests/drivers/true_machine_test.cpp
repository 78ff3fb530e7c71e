// The simulated machine driving a real, imperfect five-bar (issue 13): SimConfig::trueMachine
// and SimMachine::drawnTrace (pen_trace.hpp). A planned job is run on the simulated board
// (instant, set up and referenced) and what the true machine's pen drew is compared with the
// plan: equal machines draw the plan within a step; a link 0.5 mm long moves every corner of a
// square where the true geometry's forward kinematics puts it; backlash leaves a circle open by
// the gap the motors' last directions predict.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "drivers/sim_machine.hpp"

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
  sim::SimConfig config{profile, {}, true, true, true};
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

}  // namespace
}  // namespace fivebar::test
