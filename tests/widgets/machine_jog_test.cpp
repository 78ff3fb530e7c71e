// Jog planning (checked sub-moves along the straight XY line, clipping at the safe edge, go-to)
// and the jog panel driving the simulated machine.
#include <gtest/gtest.h>

#include <QLabel>
#include <QPushButton>
#include <cmath>
#include <random>

#include "core/planning/safety.hpp"
#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "test_support.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/machine/jog_planner.hpp"

namespace fivebar {
namespace {

using test::makerPlotter;
using test::MachineRig;
using test::waitUntil;
using widgets::JogPlan;
using widgets::JogStatus;

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
      EXPECT_LT(distanceToLine(penOf(profile, q), p0, dir), widgets::kJogChordToleranceMm + 1e-6);
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
    const JogPlan plan = widgets::planCartesianJog(profile, profile.homeAngles, dir * len, 20.0);
    ASSERT_TRUE(plan.ok()) << plan.reason;
    expectFollowsLine(profile, profile.homeAngles, plan, dir);
    if (plan.status == JogStatus::Full) {
      const Vec2 end = penOf(profile, plan.targets.back());
      EXPECT_NEAR((end - (penOf(profile, profile.homeAngles) + dir * len)).norm(), 0.0, 1e-6);
    }
  }
}

TEST(JogPlanner, JogTowardTheEdgeStopsAtTheLastSafePoint) {
  const MachineProfile profile = makerPlotter();
  const Vec2 dir(0.0, 1.0);  // away from the motors: the legs stretch out
  const JogPlan plan = widgets::planCartesianJog(profile, profile.homeAngles, dir * 1000.0, 20.0);
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
  const JogPlan plan = widgets::planMotorJog(profile, profile.homeAngles, 1, room + 0.5, 0.3);
  ASSERT_NE(plan.status, JogStatus::Full);
  if (plan.status == JogStatus::Clipped) {
    EXPECT_LE(plan.targets.back().theta1, profile.limits.theta1Max + 1e-9);
    EXPECT_DOUBLE_EQ(plan.targets.back().theta2, profile.homeAngles.theta2);
  }
  EXPECT_FALSE(plan.reason.empty());
}

TEST(JogPlanner, GoToReachesThePointOrSaysWhyNot) {
  const MachineProfile profile = makerPlotter();
  const Vec2 target = penOf(profile, profile.homeAngles) + Vec2(25.0, -15.0);
  const JogPlan plan = widgets::planGoTo(profile, profile.homeAngles, target);
  ASSERT_EQ(plan.status, JogStatus::Full) << plan.reason;
  EXPECT_NEAR((penOf(profile, plan.targets.back()) - target).norm(), 0.0, 1e-6);
  EXPECT_GT(plan.pathMm.size(), 2u);
  JointAngles from = profile.homeAngles;
  for (const JointAngles& to : plan.targets) {
    EXPECT_TRUE(checkJointMove(profile, from, to).ok());
    from = to;
  }
  const JogPlan far = widgets::planGoTo(profile, profile.homeAngles, Vec2(0.0, 900.0));
  EXPECT_EQ(far.status, JogStatus::Refused);
  EXPECT_NE(far.reason.find("out of reach"), std::string::npos) << far.reason;
}

TEST(JogPanel, ArrowStepMovesTheSimulatedMachine) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.session);
  const Vec2 before = *rig.session.penMm();
  // Step 10 mm, then a tap (press + release) on "+X".
  panel.controller().setStep(10.0);
  panel.arrowButton(1, 0)->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  const Vec2 after = *rig.session.penMm();
  // One motor step is about 0.028 deg: well under 0.2 mm at the pen.
  EXPECT_NEAR(after.x() - before.x(), 10.0, 0.2);
  EXPECT_NEAR(after.y() - before.y(), 0.0, 0.2);
  EXPECT_TRUE(panel.messageLabel()->text().isEmpty()) << panel.messageLabel()->text().toStdString();
}

TEST(JogPanel, MotorButtonTurnsOneMotor) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.session);
  const JointAngles before = *rig.session.motorAngles();
  panel.controller().setStep(1.0);
  panel.motorButton(2, -1)->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  const JointAngles after = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(after.theta2 - before.theta2), -1.0, 0.05);
  EXPECT_NEAR(degFromRad(after.theta1 - before.theta1), 0.0, 0.05);
}

TEST(JogPanel, HoldingStreamsAContinuousJogAndReleaseStopsIt) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(1.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.session);
  panel.controller().setStep(0.1);
  panel.controller().setSpeedMmPerS(20.0);
  const Vec2 before = *rig.session.penMm();
  QPushButton* down = panel.arrowButton(0, -1);
  emit down->pressed();
  waitUntil([] { return false; }, 1200);  // hold for 1.2 s
  EXPECT_TRUE(panel.controller().streaming());
  emit down->released();
  ASSERT_TRUE(rig.waitIdle());
  const Vec2 stopped = *rig.session.penMm();
  // Far more than one 0.1 mm step, at most the hold time at speed plus a short overshoot.
  EXPECT_LT(stopped.y() - before.y(), -5.0);
  EXPECT_GT(stopped.y() - before.y(), -40.0);
  EXPECT_NEAR(stopped.x(), before.x(), widgets::kJogChordToleranceMm + 0.2);
  // It stays stopped.
  waitUntil([] { return false; }, 500);
  EXPECT_NEAR((*rig.session.penMm() - stopped).norm(), 0.0, 1e-6);
}

TEST(JogPanel, GoToPreviewsThenMovesOnConfirm) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.session);
  const Vec2 start = *rig.session.penMm();
  const Vec2 target = start + Vec2(-20.0, 10.0);
  panel.goToTool().pick(QPointF(target.x(), target.y()));
  ASSERT_TRUE(panel.goToTool().pending().has_value());
  EXPECT_TRUE(panel.confirmButton()->isEnabled());
  // Nothing moves before the confirmation.
  waitUntil([] { return false; }, 300);
  EXPECT_NEAR((*rig.session.penMm() - start).norm(), 0.0, 1e-6);
  panel.confirmButton()->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_NEAR((*rig.session.penMm() - target).norm(), 0.0, 0.2);
}

}  // namespace
}  // namespace fivebar
