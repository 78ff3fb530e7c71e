// SPDX-License-Identifier: GPL-3.0-or-later
// The time-optimal reference (core/planning/time_optimal.hpp): the phase-plane parameterisation
// against closed forms (huge limits: length / speed; one motor alone: its rest-to-rest time),
// its grid convergence, rest at sharp corners, and the job-level split.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/machine/profile.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/time_optimal.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

std::vector<Vec2> line(const Vec2& a, const Vec2& b) { return {a, b}; }

TEST(TimeOptimal, RestToRestIsBangBangOrTrapezoid) {
  EXPECT_DOUBLE_EQ(restToRestS(0.0, 2.0, 10.0), 0.0);
  EXPECT_NEAR(restToRestS(0.1, 2.0, 10.0), 2.0 * std::sqrt(0.1 / 10.0), 1e-15);  // triangle
  EXPECT_NEAR(restToRestS(-1.0, 2.0, 10.0), 1.0 / 2.0 + 2.0 / 10.0, 1e-15);     // trapezoid
}

TEST(TimeOptimal, HugeMotorLimitsLeaveLengthOverTheAskedSpeed) {
  const MachineProfile p = *preset("maker-plotter");
  MotorLimits huge;
  for (int i = 0; i < 2; ++i) huge.maxSpeedRadPerS[i] = huge.maxAccelRadPerS2[i] = 1e9;
  const auto path = line({-40, 150}, {40, 190});
  const double t = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, path, 50.0, huge);
  EXPECT_NEAR(t, std::sqrt(80.0 * 80.0 + 40.0 * 40.0) / 50.0, 1e-3);
}

TEST(TimeOptimal, NeverFasterThanEachMotorAloneAndNotFarFromIt) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> x(-80, 80), y(130, 220);
  const MachineProfile p = *preset("maker-plotter");
  const MotorLimits lim = motorLimitsOf(p);
  for (int k = 0; k < 40; ++k) {
    const Vec2 a(x(rng), y(rng)), b(x(rng), y(rng));
    const auto qa = inverse(p.geometry, a, WorkingMode::PlusPlus).angles;
    const auto qb = inverse(p.geometry, b, WorkingMode::PlusPlus).angles;
    const double motors = std::max(
        restToRestS(std::remainder(qb.theta1 - qa.theta1, 2 * kPi), lim.maxSpeedRadPerS[0], lim.maxAccelRadPerS2[0]),
        restToRestS(std::remainder(qb.theta2 - qa.theta2, 2 * kPi), lim.maxSpeedRadPerS[1], lim.maxAccelRadPerS2[1]));
    const double t = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, line(a, b), 1e6, lim);
    EXPECT_GE(t, motors * (1 - 2e-2)) << k;  // the grid's first-order error, at most 2 %
    EXPECT_LE(t, 4.0 * motors + 0.05) << k;  // a straight line is not a detour
  }
}

TEST(TimeOptimal, GridConverges) {
  const MachineProfile p = *preset("maker-plotter");
  std::vector<Vec2> circle;
  for (int i = 0; i <= 200; ++i)
    circle.emplace_back(30 * std::cos(2 * kPi * i / 200), 170 + 30 * std::sin(2 * kPi * i / 200));
  TimeOptimalOptions fine, coarse;
  fine.gridStepMm = 0.1;
  coarse.gridStepMm = 2.0;
  const double tf = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, circle, 200, motorLimitsOf(p), fine);
  const double tc = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, circle, 200, motorLimitsOf(p), coarse);
  EXPECT_GT(tf, 2 * kPi * 30 / 200);  // never faster than the asked speed all the way
  EXPECT_NEAR(tc / tf, 1.0, 0.01);
}

TEST(TimeOptimal, TheMachineStopsAtSharpCornersOnly) {
  const MachineProfile p = *preset("maker-plotter");
  const MotorLimits lim = motorLimitsOf(p);
  const Vec2 a(-40, 150), b(40, 150), c(40, 210), d(60, 150 + 5);
  const double legs = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, line(a, b), 150, lim) +
                      timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, line(b, c), 150, lim);
  const std::vector<Vec2> corner{a, b, c};
  EXPECT_NEAR(timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, corner, 150, lim), legs, 1e-9);
  // A gentle bend (14 deg) is driven through, faster than stopping there.
  const std::vector<Vec2> bend{a, b, d};
  const double stopped = timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, line(a, b), 150, lim) +
                         timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, line(b, d), 150, lim);
  EXPECT_LT(timeOptimalPathS(p.geometry, WorkingMode::PlusPlus, bend, 150, lim), stopped);
}

TEST(TimeOptimal, PlannedJobCarriesTheReferenceAndIsNotFarBelowIt) {
  MachineProfile p = *preset("maker-plotter");
  p.drawSpeedMmPerS = 150;
  Drawing d;
  Layer l;
  l.paths.push_back({{{-60, -40}, {60, -40}, {60, 40}, {-60, 40}, {-60, -40}}, true});
  l.paths.push_back({{{-60, -40}, {60, 40}}, false});
  d.layers.push_back(l);
  PlanOptions o;
  o.atMm = Vec2(0, 170);
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  const TimeOptimalJob b = timeOptimalJob(r.job, p);
  EXPECT_NEAR(r.job.summary.timeOptimalS, b.totalS(), 1e-12);
  EXPECT_NEAR(r.report.timeOptimalS, b.totalS(), 1e-12);
  EXPECT_GT(b.drawS, 0.0);
  EXPECT_GT(b.travelS, 0.0);
  double dwells = 0.0;
  for (const JobMove& m : r.job.moves) dwells += m.dwellS;
  EXPECT_NEAR(b.dwellS, dwells, 1e-12);
  EXPECT_GT(dwells, 0.0);
  const double ratio = r.job.summary.estimatedTimeS / b.totalS();
  EXPECT_GT(ratio, 0.95);
  EXPECT_LT(ratio, 1.15);
}

}  // namespace
}  // namespace fivebar
