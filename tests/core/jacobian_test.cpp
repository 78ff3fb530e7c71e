// SPDX-License-Identifier: GPL-3.0-or-later
// Jacobians and singularity measures (core/singularity.hpp): finite-difference checks of A, B
// and J = A^-1 B at random poses in every branch, singularity classification at constructed
// type I, II and III poses, continuity of the margins, and the range of inverseCondition.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kAsymmetric{55.0, 130.0, 70.0, 110.0, 42.0};
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};
const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};
const Geometry kMachines[] = {kAsymmetric, kHoang, kDai};

// Central-difference step (mm or rad): truncation error ~ h^2, rounding ~ eps / h.
constexpr double kStep = 1e-5;

// A random reachable pose in working mode m, at least minMarginRad from every singularity (so
// that finite differences are well conditioned).
Pose randomRegularPose(const Geometry& g, WorkingMode m, std::mt19937_64& rng,
                       double minMarginRad = 0.05) {
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + 0.5 * g.w;
  std::uniform_real_distribution<double> u(-reach, reach);
  for (;;) {
    const Vec2 p(u(rng), u(rng));
    const IkResult ik = inverse(g, p, m);
    if (!ik.ok()) continue;
    const Pose pose = makePose(g, ik.angles, p);
    const SingularityMargins sm = singularityMargins(g, pose);
    if (sm.typeI() > minMarginRad && sm.typeII > minMarginRad) return pose;
  }
}

// The loop-closure constraints f_i(P, theta) = (|P - R_i(theta_i)|^2 - b_i^2) / 2 = 0. Their
// derivatives are A (with respect to P) and -B (with respect to theta): A v = B thetaDot.
Eigen::Vector2d constraints(const Geometry& g, const Vec2& P, const JointAngles& q) {
  return {0.5 * ((P - elbow1(g, q.theta1)).squaredNorm() - g.b1 * g.b1),
          0.5 * ((P - elbow2(g, q.theta2)).squaredNorm() - g.b2 * g.b2)};
}

TEST(Jacobian, AAndBAreTheConstraintDerivatives) {
  auto rng = test::rng();
  for (const Geometry& g : kMachines) {
    for (WorkingMode m : kAllWorkingModes) {
      for (int i = 0; i < 50; ++i) {
        const Pose pose = randomRegularPose(g, m, rng);
        const Jacobians j = jacobians(g, pose);
        for (int c = 0; c < 2; ++c) {
          const Vec2 e = Vec2::Unit(c);
          const Eigen::Vector2d dP = (constraints(g, pose.P + kStep * e, pose.q) -
                                      constraints(g, pose.P - kStep * e, pose.q)) /
                                     (2 * kStep);
          EXPECT_LT((dP - j.A.col(c)).norm(), 1e-6 * j.A.norm()) << toString(m);
          JointAngles qp = pose.q, qm = pose.q;
          (c == 0 ? qp.theta1 : qp.theta2) += kStep;
          (c == 0 ? qm.theta1 : qm.theta2) -= kStep;
          const Eigen::Vector2d dTheta =
              (constraints(g, pose.P, qp) - constraints(g, pose.P, qm)) / (2 * kStep);
          EXPECT_LT((dTheta + j.B.col(c)).norm(), 1e-6 * j.B.norm()) << toString(m);
        }
        EXPECT_EQ(j.B(0, 1), 0.0);
        EXPECT_EQ(j.B(1, 0), 0.0);
      }
    }
  }
}

TEST(Jacobian, InverseKinematicsRatesSatisfyAvEqualsBThetaDot) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (const Geometry& g : kMachines) {
    for (WorkingMode m : kAllWorkingModes) {
      for (int i = 0; i < 50; ++i) {
        const Pose pose = randomRegularPose(g, m, rng);
        const double a = angle(rng);
        const Vec2 v(std::cos(a), std::sin(a));  // unit velocity, mm per unit time
        const IkResult plus = inverse(g, pose.P + kStep * v, m);
        const IkResult minus = inverse(g, pose.P - kStep * v, m);
        ASSERT_TRUE(plus.ok() && minus.ok());
        const Eigen::Vector2d thetaDot(
            std::remainder(plus.angles.theta1 - minus.angles.theta1, 2 * kPi) / (2 * kStep),
            std::remainder(plus.angles.theta2 - minus.angles.theta2, 2 * kPi) / (2 * kStep));
        const Jacobians j = jacobians(g, pose);
        EXPECT_LT((j.A * v - j.B * thetaDot).norm(), 1e-5 * j.A.norm()) << toString(m);
        const auto J = cartesianJacobian(g, pose);
        ASSERT_TRUE(J.has_value());
        EXPECT_LT((*J * thetaDot - v).norm(), 1e-5) << toString(m);
      }
    }
  }
}

TEST(Jacobian, CartesianJacobianColumnsAreForwardKinematicsDerivatives) {
  auto rng = test::rng();
  for (const Geometry& g : kMachines) {
    for (WorkingMode m : kAllWorkingModes) {
      for (int i = 0; i < 50; ++i) {
        const Pose pose = randomRegularPose(g, m, rng);
        const AssemblyMode am = assemblyModeOf(pose);
        const auto J = cartesianJacobian(g, pose);
        ASSERT_TRUE(J.has_value());
        // |J| reaches thousands of mm/rad near type II, so a smaller step keeps the truncation
        // error (relative ~ (h |J| / (b typeII))^2) below the tolerance.
        const double h = 0.1 * kStep;
        for (int c = 0; c < 2; ++c) {
          JointAngles qp = pose.q, qm = pose.q;
          (c == 0 ? qp.theta1 : qp.theta2) += h;
          (c == 0 ? qm.theta1 : qm.theta2) -= h;
          const FkResult fp = forward(g, qp, am), fm = forward(g, qm, am);
          ASSERT_TRUE(fp.ok() && fm.ok());
          const Vec2 column = (fp.p - fm.p) / (2 * h);  // mm per rad
          EXPECT_LT((column - J->col(c)).norm(), 1e-6 * (1.0 + J->norm()))
              << toString(m) << " column " << c << " at " << pose.P.transpose();
        }
      }
    }
  }
}

TEST(Jacobian, MarginsAreTheAnglesBehindDeterminants) {
  // Header contract: sin(typeII) = |det A| / (b1 b2), sin(typeIi) = |Bii| / (ai bi).
  auto rng = test::rng();
  for (const Geometry& g : kMachines) {
    for (WorkingMode m : kAllWorkingModes) {
      for (int i = 0; i < 100; ++i) {
        const Pose pose = randomRegularPose(g, m, rng, 0.0);
        const Jacobians j = jacobians(g, pose);
        const SingularityMargins sm = singularityMargins(g, pose);
        EXPECT_NEAR(std::sin(sm.typeII), std::abs(j.A.determinant()) / (g.b1 * g.b2), 1e-9);
        EXPECT_NEAR(std::sin(sm.typeI1), std::abs(j.B(0, 0)) / (g.a1 * g.b1), 1e-9);
        EXPECT_NEAR(std::sin(sm.typeI2), std::abs(j.B(1, 1)) / (g.a2 * g.b2), 1e-9);
        EXPECT_GE(sm.typeII, 0.0);
        EXPECT_LE(sm.typeII, kPi / 2);
      }
    }
  }
}

TEST(Singularity, TypeIAtFullStretchAndFold) {
  const Geometry& g = kHoang;
  const Vec2 dir(std::cos(radFromDeg(60.0)), std::sin(radFromDeg(60.0)));
  for (double reach : {g.a1 + g.b1, g.b1 - g.a1}) {  // stretched, folded leg 1
    const Vec2 p = g.motor1() + reach * dir;
    const IkResult ik = inverse(g, p, WorkingMode::PlusPlus);
    ASSERT_TRUE(ik.ok()) << reach;
    const Pose pose = makePose(g, ik.angles, p);
    const SingularityMargins sm = singularityMargins(g, pose);
    EXPECT_LT(sm.typeI1, 1e-6) << reach;
    EXPECT_GT(sm.typeI2, 0.1) << reach;
    EXPECT_GT(sm.typeII, 0.1) << reach;
    EXPECT_EQ(classify(sm, 1e-6), SingularityType::TypeI) << reach;
    EXPECT_NEAR(jacobians(g, pose).B(0, 0), 0.0, 1e-4) << reach;
  }
}

// Symmetric pose theta1 = pi - theta2 with the elbows exactly b1 + b2 apart: floating links
// stretched into one line through P (type II). Hoang-like links that break its eq. (9).
TEST(Singularity, TypeIIWhenFloatingLinksStretchIntoALine) {
  const Geometry g{70.0, 150.0, 70.0, 150.0, 250.0};
  const double theta2 = std::acos((g.b1 + g.b2 - g.w) / (2.0 * g.a2));
  const JointAngles q{kPi - theta2, theta2};
  const FkResult fk = forward(g, q, AssemblyMode::Plus);
  ASSERT_TRUE(fk.ok());
  const Pose pose = makePose(g, q, fk.p);
  EXPECT_NEAR(fk.p.x(), 0.0, 1e-9);  // the midpoint of R1 R2
  const SingularityMargins sm = singularityMargins(g, pose);
  EXPECT_LT(sm.typeII, 1e-6);
  EXPECT_GT(sm.typeI(), 0.1);
  EXPECT_EQ(classify(sm, 1e-6), SingularityType::TypeII);
  EXPECT_FALSE(cartesianJacobian(g, pose).has_value());
  EXPECT_EQ(inverseCondition(g, pose), 0.0);
}

// Asymmetric floating links folded onto one line: |R1 R2| = |b1 - b2|, P beyond R2.
TEST(Singularity, TypeIIWhenFloatingLinksFold) {
  const Geometry& g = kAsymmetric;
  const JointAngles q1{radFromDeg(90.0), 0.0};
  const Vec2 R1 = elbow1(g, q1.theta1);
  // R2: on motor 2's circle (radius a2) and |b1 - b2| from R1 (intersection of two circles).
  const Vec2 c = R1 - g.motor2();
  const double d = c.norm(), r = std::abs(g.b1 - g.b2);
  const double along = (g.a2 * g.a2 - r * r + d * d) / (2.0 * d);
  const double h = std::sqrt(g.a2 * g.a2 - along * along);
  const Vec2 R2 = g.motor2() + along * c / d + h * Vec2(-c.y(), c.x()) / d;
  const JointAngles q{q1.theta1, std::atan2(R2.y(), R2.x() - g.motor2().x())};
  const FkResult fk = forward(g, q, AssemblyMode::Plus);
  ASSERT_TRUE(fk.ok());
  const Pose pose = makePose(g, q, fk.p);
  EXPECT_NEAR((pose.P - pose.R1).norm(), g.b1, 1e-9);
  EXPECT_NEAR((pose.P - pose.R2).norm(), g.b2, 1e-9);
  const SingularityMargins sm = singularityMargins(g, pose);
  EXPECT_LT(sm.typeII, 1e-6);
  EXPECT_EQ(classify(sm, 1e-6), SingularityType::TypeII);
}

// Architecture singularity: a1 = a2, b1 = b2, w = 0. With both motors at 0 the two legs coincide,
// fully stretched along +x: five points collinear, det A = det B = 0.
TEST(Singularity, TypeIIIForCoaxialEqualLegs) {
  const Geometry g{60.0, 90.0, 60.0, 90.0, 0.0};
  const JointAngles q{0.0, 0.0};
  const Pose pose = makePose(g, q, Vec2(g.a1 + g.b1, 0.0));
  const SingularityMargins sm = singularityMargins(g, pose);
  EXPECT_EQ(classify(sm, 1e-9), SingularityType::TypeIII);
  const Jacobians j = jacobians(g, pose);
  EXPECT_NEAR(j.A.determinant(), 0.0, 1e-9);
  EXPECT_NEAR(j.B.determinant(), 0.0, 1e-9);
  // And with a = b, motors opposite: legs folded onto the axis, P on it too.
  const Geometry h{50.0, 50.0, 50.0, 50.0, 0.0};
  const Pose folded = makePose(h, JointAngles{0.0, kPi}, Vec2(0.0, 0.0));
  EXPECT_EQ(classify(singularityMargins(h, folded), 1e-9), SingularityType::TypeIII);
}

TEST(Singularity, NoneAtARegularPose) {
  const Vec2 p(0.0, 150.0);
  const Pose pose = makePose(kHoang, inverse(kHoang, p, WorkingMode::PlusPlus).angles, p);
  EXPECT_EQ(classify(singularityMargins(kHoang, pose), 0.1), SingularityType::None);
}

TEST(Singularity, TypeIIMarginIsContinuousAndZeroOnlyAtTheCrossing) {
  // Walk the symmetric family theta1 = pi - theta2 across the stretched type II pose. The margin
  // changes by at most a Lipschitz bound per step, det A changes sign once, and the margin is 0
  // at the crossing (up to the step size).
  const Geometry g{70.0, 150.0, 70.0, 150.0, 250.0};
  const double crossing = std::acos((g.b1 + g.b2 - g.w) / (2.0 * g.a2));
  const double step = 1e-4;
  double previousMargin = -1.0, previousDet = 0.0, smallest = kPi;
  int signChanges = 0;
  for (double t = crossing - 0.05; t <= crossing + 0.05; t += step) {
    const JointAngles q{kPi - t, t};
    // Beyond the crossing the loop no longer closes with these elbows; FK fails there.
    const FkResult fk = forward(g, q, AssemblyMode::Plus);
    if (!fk.ok()) continue;
    const Pose pose = makePose(g, q, fk.p);
    const double margin = singularityMargins(g, pose).typeII;
    const double det = jacobians(g, pose).A.determinant();
    if (previousMargin >= 0.0) {
      // d(margin)/dt is bounded away from the crossing; near it the margin behaves like
      // sqrt(distance), so allow the sqrt of the step there.
      EXPECT_LT(std::abs(margin - previousMargin), 2.0 * std::sqrt(step)) << t;
      if ((det > 0) != (previousDet > 0) && det != 0.0 && previousDet != 0.0) ++signChanges;
    }
    smallest = std::min(smallest, margin);
    previousMargin = margin;
    previousDet = det;
  }
  EXPECT_LT(smallest, 0.02);
  EXPECT_LE(signChanges, 1);
}

TEST(Singularity, InverseConditionIsInUnitIntervalAndMatchesSingularValues) {
  auto rng = test::rng();
  for (const Geometry& g : kMachines) {
    for (WorkingMode m : kAllWorkingModes) {
      for (int i = 0; i < 100; ++i) {
        const Pose pose = randomRegularPose(g, m, rng, 1e-3);
        const double c = inverseCondition(g, pose);
        EXPECT_GE(c, 0.0);
        EXPECT_LE(c, 1.0);
        // Independent: singular values of a 2x2 from the eigenvalues of J^T J.
        const Eigen::Matrix2d J = *cartesianJacobian(g, pose);
        const Eigen::Matrix2d JtJ = J.transpose() * J;
        const double tr = JtJ.trace(), det = JtJ.determinant();
        const double disc = std::sqrt(std::max(0.0, tr * tr / 4.0 - det));
        const double smax = std::sqrt(tr / 2.0 + disc),
                     smin = std::sqrt(std::max(0.0, tr / 2.0 - disc));
        EXPECT_NEAR(c, smin / smax, 1e-6) << toString(m);
      }
    }
  }
}

}  // namespace
}  // namespace fivebar
