// SPDX-License-Identifier: GPL-3.0-or-later
// Jog planning as the studio uses it (drivers/jog/jog.hpp): checked sub-moves along the straight XY
// line, clipping at the safe edge, go-to with the pen's path for the canvas preview.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/planning/safety.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "drivers/jog/jog.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

using jog::JogPlan;
using jog::JogStatus;

MachineProfile makerPlotter() { return *preset("maker-plotter"); }

Vec2 penOf(const MachineProfile& p, const JointAngles& q) {
  const FkResult fk = forward(p.geometry, q, p.assembly);
  EXPECT_TRUE(fk.ok());
  return fk.p;
}

double distanceToLine(const Vec2& p, const Vec2& a, const Vec2& dir) {
  const Vec2 d = p - a;
  return std::abs(cross(dir, d));
}

// Every sub-move is checked and stays on the straight line within the chord tolerance.
void expectFollowsLine(const MachineProfile& profile, const JointAngles& start, const JogPlan& plan,
                       const Vec2& dir) {
  const Vec2 p0 = penOf(profile, start);
  JointAngles from = start;
  ASSERT_EQ(plan.lines.size(), plan.targets.size());
  for (std::size_t i = 0; i < plan.targets.size(); ++i) {
    const JointAngles& to = plan.targets[i];
    EXPECT_EQ(plan.lines[i].rfind("$J=", 0), 0u) << plan.lines[i];
    EXPECT_TRUE(checkJointMove(profile, from, to).ok());
    for (double t : {0.25, 0.5, 0.75, 1.0}) {
      const JointAngles q{from.theta1 + (to.theta1 - from.theta1) * t,
                          from.theta2 + (to.theta2 - from.theta2) * t};
      EXPECT_LT(distanceToLine(penOf(profile, q), p0, dir), jog::kDefaultDeviationMm + 1e-6);
    }
    from = to;
  }
}

TEST(JogPlanner, RandomCartesianJogsFollowTheStraightLine) {
  const MachineProfile profile = makerPlotter();
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  std::uniform_real_distribution<double> length(0.1, 40.0);
  for (int i = 0; i < 30; ++i) {
    const double a = angle(rng);
    const Vec2 dir(std::cos(a), std::sin(a));
    const double len = length(rng);
    const JogPlan plan = jog::planCartesianJog(profile, profile.homeAngles, dir, len, 20.0);
    ASSERT_TRUE(plan.ok()) << plan.reason;
    expectFollowsLine(profile, profile.homeAngles, plan, dir);
    if (plan.status == JogStatus::Ok) {
      const Vec2 end = penOf(profile, plan.targets.back());
      EXPECT_NEAR((end - (penOf(profile, profile.homeAngles) + dir * len)).norm(), 0.0, 1e-6);
    }
  }
}

TEST(JogPlanner, JogTowardTheEdgeStopsAtTheLastSafePoint) {
  const MachineProfile profile = makerPlotter();
  const Vec2 dir(0.0, 1.0);  // away from the motors: the legs stretch out
  const JogPlan plan = jog::planCartesianJog(profile, profile.homeAngles, dir, 1000.0, 20.0);
  ASSERT_EQ(plan.status, JogStatus::Clipped);
  EXPECT_FALSE(plan.reason.empty());
  expectFollowsLine(profile, profile.homeAngles, plan, dir);
  // The end lies short of the reach (a1 + b1 from the motors) and passes the pose check.
  const Vec2 end = penOf(profile, plan.targets.back());
  EXPECT_LT((end - profile.geometry.motor1()).norm(), profile.geometry.a1 + profile.geometry.b1);
  EXPECT_TRUE(checkPose(profile, plan.targets.back()).ok());
}

TEST(JogPlanner, MotorJogBeyondItsLimitIsClippedWithTheReason) {
  MachineProfile profile = makerPlotter();
  const double room = profile.limits.theta1Max - profile.homeAngles.theta1;
  const JogPlan plan = jog::planMotorJog(profile, profile.homeAngles, 1, degFromRad(room + 0.5), degFromRad(0.3) * 60.0);
  ASSERT_NE(plan.status, JogStatus::Ok);
  if (plan.status == JogStatus::Clipped) {
    EXPECT_LE(plan.targets.back().theta1, profile.limits.theta1Max + 1e-9);
    EXPECT_DOUBLE_EQ(plan.targets.back().theta2, profile.homeAngles.theta2);
  }
  EXPECT_FALSE(plan.reason.empty());
}

TEST(JogPlanner, GoToReachesThePointOrSaysWhyNot) {
  const MachineProfile profile = makerPlotter();
  const Vec2 target = penOf(profile, profile.homeAngles) + Vec2(25.0, -15.0);
  const JogPlan plan = jog::planGoTo(profile, profile.homeAngles, target);
  ASSERT_EQ(plan.status, JogStatus::Ok) << plan.reason;
  EXPECT_NEAR((penOf(profile, plan.targets.back()) - target).norm(), 0.0, 1e-6);
  const std::vector<Vec2> path = jog::penPathMm(profile, profile.homeAngles, plan);
  ASSERT_GT(path.size(), 2u);
  EXPECT_NEAR((path.front() - penOf(profile, profile.homeAngles)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((path.back() - target).norm(), 0.0, 1e-6);
  JointAngles from = profile.homeAngles;
  for (const JointAngles& to : plan.targets) {
    EXPECT_TRUE(checkJointMove(profile, from, to).ok());
    from = to;
  }
  const JogPlan far = jog::planGoTo(profile, profile.homeAngles, Vec2(0.0, 900.0));
  EXPECT_EQ(far.status, JogStatus::Blocked);
  EXPECT_NE(far.reason.text().find("out of reach"), std::string::npos) << far.reason;
}

}  // namespace
}  // namespace fivebar
