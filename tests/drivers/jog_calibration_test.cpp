// SPDX-License-Identifier: GPL-3.0-or-later
// Jog and go-to with a calibrated profile (issue 13): the current pose and every line are
// commanded angles, the kinematics uses commanded + zero offset.
#include <gtest/gtest.h>

#include "core/calibration/model.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/safety.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/check/motion_check.hpp"

namespace fivebar {
namespace {

TEST(JogCalibration, GoToReachesThePointOnTheTrueMachine) {
  const MachineProfile plain = *preset("maker-plotter");
  MachineProfile calibrated = plain;
  calibrated.calibration.emplace();
  calibrated.calibration->zeroOffsetRad1 = radFromDeg(1.5);
  calibrated.calibration->zeroOffsetRad2 = radFromDeg(-1.0);
  const Vec2 target(20.0, 200.0);
  const jog::JogPlan a = jog::planGoTo(plain, plain.homeAngles, target);
  const jog::JogPlan b = jog::planGoTo(calibrated, plain.homeAngles, target);
  ASSERT_TRUE(a.ok()) << a.reason;
  ASSERT_TRUE(b.ok()) << b.reason;
  // The calibrated machine's commanded end = the plain one's minus the offsets.
  EXPECT_NEAR(b.targets.back().theta1, a.targets.back().theta1 - radFromDeg(1.5), 1e-9);
  EXPECT_NEAR(b.targets.back().theta2, a.targets.back().theta2 + radFromDeg(1.0), 1e-9);
  // And on the calibrated machine that commanded pose puts the pen on the target.
  const JointAngles k = kinematicFromCommanded(calibrated.calibration, b.targets.back());
  const FkResult fk = forward(calibrated.geometry, k, calibrated.assembly);
  ASSERT_TRUE(fk.ok());
  EXPECT_NEAR((fk.p - target).norm(), 0.0, 1e-6);
}

// With a calibrated pen offset (and zero offsets) go-to puts the PEN on the target and a Cartesian
// jog walks the pen along a straight line: checked on the true machine's model
// (calibration::penPosition of the commanded angles).
TEST(JogCalibration, GoToAndCartesianJogAimThePenOffTheDistalJoint) {
  MachineProfile p = *preset("maker-plotter");
  p.calibration.emplace();
  p.calibration->zeroOffsetRad1 = radFromDeg(0.7);
  p.calibration->penOffset = PenOffset{4.0, 2.5};
  calibration::MachineParameters truth;
  truth.geometry = p.geometry;
  truth.zeroOffsetRad1 = p.calibration->zeroOffsetRad1;
  truth.penOffset = p.calibration->penOffset;
  const Vec2 target(-15.0, 190.0);
  const jog::JogPlan go = jog::planGoTo(p, p.homeAngles, target);
  ASSERT_TRUE(go.ok()) << go.reason;
  const auto pen = calibration::penPosition(truth, p.assembly, go.targets.back());
  ASSERT_TRUE(pen.has_value());
  EXPECT_LT((*pen - target).norm(), 1e-6);
  // Without the pen offset in the profile the same go-to misses by about the offset.
  MachineProfile noPen = p;
  noPen.calibration->penOffset.reset();
  const jog::JogPlan miss = jog::planGoTo(noPen, p.homeAngles, target);
  ASSERT_TRUE(miss.ok());
  EXPECT_GT((*calibration::penPosition(truth, p.assembly, miss.targets.back()) - target).norm(), 4.0);
  // A 20 mm jog in +x from there: every line ends on the straight line through the pen.
  const jog::JogPlan j = jog::planCartesianJog(p, go.targets.back(), Vec2(1.0, 0.0), 20.0, 20.0);
  ASSERT_TRUE(j.ok()) << j.reason;
  EXPECT_NEAR(j.lengthMm, 20.0, 1e-9);
  for (const JointAngles& c : j.targets) {
    const auto q = calibration::penPosition(truth, p.assembly, c);
    ASSERT_TRUE(q.has_value());
    EXPECT_NEAR(q->y(), target.y(), 1e-3);  // the angles go out with 3 decimals of a degree
  }
  EXPECT_NEAR(calibration::penPosition(truth, p.assembly, j.targets.back())->x(), target.x() + 20.0, 1e-3);
}

TEST(JogCalibration, MotorJogLineCarriesCommandedAngles) {
  MachineProfile p = *preset("maker-plotter");
  p.calibration.emplace();
  p.calibration->zeroOffsetRad1 = radFromDeg(2.0);
  const jog::JogPlan j = jog::planMotorJog(p, p.homeAngles, 1, 1.0, 600.0);
  ASSERT_TRUE(j.ok()) << j.reason;
  EXPECT_NEAR(j.targets.back().theta1, p.homeAngles.theta1 + radFromDeg(1.0), 1e-12);
}

TEST(JogCalibration, MotionCheckAppliesTheOffsetBeforeTheWorkspaceCheck) {
  // The smallest motor-1 offset at which the home pose's kinematic angles are no longer safe.
  const MachineProfile plain = *preset("maker-plotter");
  double offsetDeg = 0.0;
  while (offsetDeg < 180.0 &&
         checkPose(plain, {plain.homeAngles.theta1 + radFromDeg(offsetDeg), plain.homeAngles.theta2}).ok())
    offsetDeg += 1.0;
  ASSERT_LT(offsetDeg, 180.0);
  MachineProfile shifted = plain;
  shifted.calibration.emplace();
  shifted.calibration->zeroOffsetRad1 = radFromDeg(offsetDeg);
  motion::BoardPose pose;
  pose.workDeg = {degFromRad(plain.homeAngles.theta1), degFromRad(plain.homeAngles.theta2), 0.0};
  const std::string line = "G1 X" + std::to_string(pose.workDeg[0] - 0.1) + " Y" + std::to_string(pose.workDeg[1]);
  EXPECT_TRUE(motion::checkLine(plain, line, pose).ok());
  const motion::LineCheck c = motion::checkLine(shifted, line, pose);
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.reason.text().find("is not a safe pose"), std::string::npos) << c.reason;
}

}  // namespace
}  // namespace fivebar
