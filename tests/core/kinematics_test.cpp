// SPDX-License-Identifier: GPL-3.0-or-later
// Consistency tests of the exact scalar kinematics: round trips in every branch, branch
// identification, boundary robustness, asymmetric geometry. Conventions: conventions.md.
#include <gtest/gtest.h>

#include <cmath>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kAsymmetric{55.0, 130.0, 70.0, 110.0, 42.0};
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};

// A random point inside the reach of both legs (rejection sampling).
Vec2 reachablePoint(const Geometry& g, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> x(-300, 300), y(-300, 300);
  for (;;) {
    const Vec2 p(x(rng), y(rng));
    const double d1 = (p - g.motor1()).norm(), d2 = (p - g.motor2()).norm();
    if (d1 < g.a1 + g.b1 && d1 > std::abs(g.a1 - g.b1) && d2 < g.a2 + g.b2 &&
        d2 > std::abs(g.a2 - g.b2))
      return p;
  }
}

TEST(Kinematics, RoundTripEveryWorkingModeAsymmetric) {
  auto rng = test::rng();
  for (const Geometry& g : {kAsymmetric, kHoang}) {
    for (int i = 0; i < 2000; ++i) {
      const Vec2 p = reachablePoint(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const IkResult ik = inverse(g, p, m);
        ASSERT_TRUE(ik.ok());
        const Pose pose = makePose(g, ik.angles, p);
        EXPECT_EQ(workingModeOf(g, pose), m) << "mode " << toString(m);
        EXPECT_NEAR((pose.R1 - p).norm(), g.b1, 1e-9);
        EXPECT_NEAR((pose.R2 - p).norm(), g.b2, 1e-9);
        const FkResult fk = forward(g, ik.angles, assemblyModeOf(pose));
        ASSERT_TRUE(fk.ok());
        // FK is ill-conditioned at a type II singularity (error ~ rounding / sin(mu)): demand
        // 1e-9 mm everywhere at least 1e-4 rad away from one, and 1e-6 mm closer in.
        const double tol = singularityMargins(g, pose).typeII > 1e-4 ? 1e-9 : 1e-6;
        EXPECT_LT((fk.p - p).norm(), tol) << "at " << p.transpose() << " mode " << toString(m);
      }
    }
  }
}

TEST(Kinematics, SymmetricElbowsOutIsPlusPlus) {
  const Vec2 p(0.0, 150.0);
  const IkResult ik = inverse(kHoang, p, WorkingMode::PlusPlus);
  ASSERT_TRUE(ik.ok());
  const Pose pose = makePose(kHoang, ik.angles, p);
  EXPECT_LT(pose.R1.x(), kHoang.motor1().x());  // elbow 1 out to the left
  EXPECT_GT(pose.R2.x(), kHoang.motor2().x());  // elbow 2 out to the right
  EXPECT_NEAR(ik.angles.theta1, kPi - ik.angles.theta2, 1e-12);  // mirror symmetry
  EXPECT_EQ(assemblyModeOf(pose), AssemblyMode::Plus);
}

TEST(Kinematics, BoundaryGivesNoNaN) {
  const Geometry& g = kAsymmetric;
  // Points on the outer reach circle of leg 1, nudged by a rounding error outward.
  for (int k = 0; k < 360; ++k) {
    const double a = k * kPi / 180.0;
    const Vec2 p = g.motor1() + (g.a1 + g.b1) * (1.0 + 1e-16) * Vec2(std::cos(a), std::sin(a));
    const auto t = inverseArm1(g, p, ArmSign::Plus);
    ASSERT_TRUE(t.has_value());
    EXPECT_TRUE(std::isfinite(*t));
  }
  EXPECT_FALSE(inverseArm1(g, g.motor1() + Vec2(g.a1 + g.b1 + 1e-6, 0.0), ArmSign::Plus));
}

TEST(Kinematics, RightArmUsesItsOwnDistance) {
  // Off-centre target: each arm's elbow must sit exactly a_i from its own motor and b_i from P.
  const Geometry& g = kAsymmetric;
  const Vec2 p(60.0, 120.0);
  const IkResult ik = inverse(g, p, WorkingMode::PlusMinus);
  ASSERT_TRUE(ik.ok());
  EXPECT_NEAR((elbow2(g, ik.angles.theta2) - p).norm(), g.b2, 1e-9);
  EXPECT_NEAR((elbow1(g, ik.angles.theta1) - p).norm(), g.b1, 1e-9);
}

TEST(Kinematics, AssemblyModeIsChosenNotLargerY) {
  // Both assembly solutions are returned as asked, whichever has the larger y.
  const JointAngles q{2.2, 0.9};
  const FkResult plus = forward(kHoang, q, AssemblyMode::Plus);
  const FkResult minus = forward(kHoang, q, AssemblyMode::Minus);
  ASSERT_TRUE(plus.ok() && minus.ok());
  EXPECT_EQ(assemblyModeOf(makePose(kHoang, q, plus.p)), AssemblyMode::Plus);
  EXPECT_EQ(assemblyModeOf(makePose(kHoang, q, minus.p)), AssemblyMode::Minus);
}

TEST(Kinematics, CoaxialMotorsWork) {
  const Geometry g{60.0, 90.0, 60.0, 90.0, 0.0};
  const Vec2 p(20.0, 100.0);
  for (WorkingMode m : kAllWorkingModes) {
    const IkResult ik = inverse(g, p, m);
    ASSERT_TRUE(ik.ok());
    const Pose pose = makePose(g, ik.angles, p);
    const FkResult fk = forward(g, ik.angles, assemblyModeOf(pose));
    if (fk.ok()) {
      EXPECT_LT((fk.p - p).norm(), 1e-9);
    }
  }
}

TEST(Kinematics, ValidationNamesTheField) {
  const auto issues = validate(Geometry{-1.0, 10.0, 10.0, 10.0, 5.0});
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues.front().field, "a1");
  EXPECT_NE(issues.front().message.text().find("positive"), std::string::npos);
  const auto apart = validate(Geometry{10.0, 10.0, 10.0, 10.0, 100.0});
  ASSERT_FALSE(apart.empty());
  EXPECT_EQ(apart.front().field, "w");
}

}  // namespace
}  // namespace fivebar
