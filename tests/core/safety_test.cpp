// SPDX-License-Identifier: GPL-3.0-or-later
// Move checks and safe travel (core/safety.hpp), verified against dense independent sampling
// of the forward kinematics and the singularity margins.
#include <gtest/gtest.h>

#include <cmath>

#include "core/planning/safety.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};
const Geometry kAsymmetric{55.0, 130.0, 70.0, 110.0, 42.0};

MachineProfile profileFor(const Geometry& g) {
  MachineProfile p;
  p.name = "test";
  p.geometry = g;
  return p;
}

JointAngles lerpQ(const JointAngles& a, const JointAngles& b, double t) {
  return {a.theta1 + t * (b.theta1 - a.theta1), a.theta2 + t * (b.theta2 - a.theta2)};
}

// Independent dense scan of a joint move: smallest margins and whether the loop always closes.
struct Dense {
  bool closes = true;
  double minTypeII = 10.0;
  double minTypeI = 10.0;
};
Dense denseScan(const MachineProfile& pr, const JointAngles& a, const JointAngles& b, int n) {
  Dense d;
  for (int i = 0; i <= n; ++i) {
    const JointAngles q = lerpQ(a, b, static_cast<double>(i) / n);
    const FkResult fk = forward(pr.geometry, q, pr.assembly);
    if (!fk.ok()) {
      d.closes = false;
      continue;
    }
    const SingularityMargins m = singularityMargins(pr.geometry, makePose(pr.geometry, q, fk.p));
    d.minTypeII = std::min(d.minTypeII, m.typeII);
    d.minTypeI = std::min(d.minTypeI, m.typeI());
  }
  return d;
}

// Symmetric family of dai2022: theta1 = pi - t, theta2 = t. The elbows are 180 + 270 cos t
// apart, so the loop closes (stretched type II) exactly at cos t = 1/3.
JointAngles symmetricPose(double t) { return {kPi - t, t}; }

TEST(Safety, InteriorMoveIsOkAndReportsTheDenseMinimumMargin) {
  const MachineProfile pr = profileFor(kHoang);
  const IkResult a = inverse(kHoang, {-30.0, 150.0}, WorkingMode::PlusPlus);
  const IkResult b = inverse(kHoang, {40.0, 210.0}, WorkingMode::PlusPlus);
  ASSERT_TRUE(a.ok() && b.ok());
  const MoveCheck c = checkJointMove(pr, a.angles, b.angles);
  EXPECT_TRUE(c.ok()) << describe(c);
  const Dense d = denseScan(pr, a.angles, b.angles, 20000);
  EXPECT_GE(c.minTypeIIMarginRad, d.minTypeII - 1e-9);
  EXPECT_NEAR(c.minTypeIIMarginRad, d.minTypeII, radFromDeg(0.05));
  EXPECT_NEAR((c.where - Vec2(40.0, 210.0)).norm(), 0.0, 1e-6);
}

TEST(Safety, LeavingTheClosableRegionIsRefused) {
  MachineProfile pr = profileFor(kDai);
  const double tBoundary = std::acos(1.0 / 3.0);
  const JointAngles from = symmetricPose(radFromDeg(85.0)), to = symmetricPose(radFromDeg(55.0));
  ASSERT_TRUE(checkPose(pr, from).ok());
  const double boundaryFraction = (radFromDeg(85.0) - tBoundary) / radFromDeg(30.0);
  const MoveCheck near = checkJointMove(pr, from, to);
  EXPECT_EQ(near.status, MoveStatus::NearTypeII);
  EXPECT_LT(near.atFraction, boundaryFraction);
  EXPECT_NEAR(near.minTypeIIMarginRad, pr.typeIIMarginRad, radFromDeg(0.5));
  EXPECT_NE(describe(near).find("type II"), std::string::npos) << describe(near);
  pr.typeIIMarginRad = 0.0;
  pr.typeIMarginRad = 0.0;
  const MoveCheck out = checkJointMove(pr, from, to);
  EXPECT_EQ(out.status, MoveStatus::CannotClose) << describe(out);
  EXPECT_NEAR(out.atFraction, boundaryFraction, 1e-3);
  EXPECT_NE(describe(out).find("cannot close"), std::string::npos) << describe(out);
}

TEST(Safety, TouchingTheTypeIILocusIsAnAssemblyChange) {
  MachineProfile pr = profileFor(kAsymmetric);
  pr.typeIIMarginRad = 0.0;
  pr.typeIMarginRad = 0.0;
  const Geometry& g = kAsymmetric;
  // Negative where the loop closes. The stretched locus (d = b1 + b2) bounds a region that
  // straight joint lines leave when they touch it; the folded locus (d = |b1 - b2|) bounds a
  // hole that tangent lines touch and leave again, so both are tried.
  bool folded = false;
  auto gap = [&](const JointAngles& q) {
    const double d = (elbow2(g, q.theta2) - elbow1(g, q.theta1)).norm();
    return folded ? std::abs(g.b1 - g.b2) - d : d - (g.b1 + g.b2);
  };
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  int touches = 0;
  for (int trial = 0; trial < 400 && touches < 5; ++trial) {
    folded = trial % 2 == 1;
    // A stretched (or folded) pose: bisection on theta2 between a closable and a non-closable value.
    const double t1 = angle(rng);
    double lo = angle(rng), hi = angle(rng);
    if (gap({t1, lo}) >= 0.0 || gap({t1, hi}) <= 0.0) continue;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (gap({t1, mid}) < 0.0 ? lo : hi) = mid;
    }
    const JointAngles s{t1, lo};
    const double h = 1e-6;
    const Vec2 grad((gap({t1 + h, lo}) - gap({t1 - h, lo})) / (2 * h),
                    (gap({t1, lo + h}) - gap({t1, lo - h})) / (2 * h));
    const Vec2 tangent = Vec2(-grad.y(), grad.x()).normalized() * radFromDeg(10.0);
    const JointAngles from{s.theta1 - tangent.x(), s.theta2 - tangent.y()};
    const JointAngles to{s.theta1 + tangent.x(), s.theta2 + tangent.y()};
    const Dense d = denseScan(pr, from, to, 4000);
    const double clear = radFromDeg(0.5);  // both ends clearly off the locus
    if (!d.closes || checkPose(pr, from).minTypeIIMarginRad < clear ||
        checkPose(pr, to).minTypeIIMarginRad < clear)
      continue;
    ++touches;
    const MoveCheck c = checkJointMove(pr, from, to);
    EXPECT_EQ(c.status, MoveStatus::AssemblyChange) << describe(c);
    EXPECT_NEAR(c.atFraction, 0.5, 0.05);
    EXPECT_NE(describe(c).find("assembly"), std::string::npos);
  }
  EXPECT_GT(touches, 0) << "no touching move found; seed " << test::seed();
}

TEST(Safety, RandomMovesAgreeWithDenseSampling) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi), delta(-0.6, 0.6);
  for (const Geometry& g : {kDai, kAsymmetric}) {
    const MachineProfile pr = profileFor(g);
    int refused = 0, accepted = 0;
    while (refused + accepted < 300) {
      const JointAngles a{angle(rng), angle(rng)};
      if (!checkPose(pr, a).ok()) continue;
      const JointAngles b{a.theta1 + delta(rng), a.theta2 + delta(rng)};
      const MoveCheck c = checkJointMove(pr, a, b);
      const Dense d = denseScan(pr, a, b, 6000);
      const double slack = radFromDeg(0.01);
      if (c.ok()) {
        ++accepted;
        EXPECT_TRUE(d.closes);
        EXPECT_GE(d.minTypeII, pr.typeIIMarginRad - slack);
        EXPECT_GE(d.minTypeI, pr.typeIMarginRad - slack);
      } else {
        ++refused;
        EXPECT_TRUE(!d.closes || d.minTypeII < pr.typeIIMarginRad + slack ||
                    d.minTypeI < pr.typeIMarginRad + slack)
            << describe(c);
      }
    }
    EXPECT_GT(refused, 10);
    EXPECT_GT(accepted, 10);
  }
}

TEST(Safety, PathCheckAgreesWithMoveByMoveChecks) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi), delta(-0.15, 0.15);
  const MachineProfile pr = profileFor(kAsymmetric);
  int failing = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<JointAngles> poses{{angle(rng), angle(rng)}};
    for (int i = 0; i < 30; ++i)
      poses.push_back({poses.back().theta1 + delta(rng), poses.back().theta2 + delta(rng)});
    const PathCheck path = checkJointPath(pr, poses);
    // Expected, move by move: a move is reported when its start pose is fine and the move
    // fails, or (start already bad) when its end pose is bad; pose 0 on its own.
    std::vector<std::pair<std::size_t, MoveStatus>> expected;
    if (!checkPose(pr, poses[0]).ok()) expected.push_back({0, checkPose(pr, poses[0]).status});
    for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
      if (checkPose(pr, poses[i]).ok()) {
        const MoveCheck c = checkJointMove(pr, poses[i], poses[i + 1]);
        if (!c.ok()) expected.push_back({i, c.status});
      } else if (!checkPose(pr, poses[i + 1]).ok()) {
        expected.push_back({i, checkPose(pr, poses[i + 1]).status});
      }
    }
    ASSERT_EQ(path.problems.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(path.problems[k].move, expected[k].first);
      EXPECT_EQ(path.problems[k].check.status, expected[k].second);
    }
    failing += path.ok() ? 0 : 1;
  }
  EXPECT_GT(failing, 0);
  EXPECT_LT(failing, 40);
}

TEST(Safety, JointLimitsAreCheckedOnContinuousAngles) {
  MachineProfile pr = profileFor(kDai);
  // A safe pose with theta1 around 180 deg.
  std::optional<double> theta2;
  for (double t2 = 0.0; t2 < 2 * kPi && !theta2; t2 += radFromDeg(1.0))
    if (checkJointMove(pr, {radFromDeg(178.0), t2}, {radFromDeg(182.0), t2}).ok()) theta2 = t2;
  ASSERT_TRUE(theta2.has_value());
  pr.limits.theta1Min = radFromDeg(170.0);
  pr.limits.theta1Max = radFromDeg(190.0);
  const JointAngles from{radFromDeg(179.0), *theta2};
  EXPECT_TRUE(checkJointMove(pr, from, {radFromDeg(181.0), *theta2}).ok());
  // The same target written as -179 deg is the long way round: beyond the limit at once.
  const MoveCheck longWay = checkJointMove(pr, from, {radFromDeg(-179.0), *theta2});
  EXPECT_EQ(longWay.status, MoveStatus::BeyondJointLimit);
  EXPECT_LT(longWay.atFraction, 9.5 / 358.0);
  EXPECT_NE(describe(longWay).find("joint limit"), std::string::npos);
  // Crossing the upper limit: reported where theta1 passes 190 deg.
  const MoveCheck over = checkJointMove(pr, from, {radFromDeg(195.0), *theta2});
  if (over.status == MoveStatus::BeyondJointLimit) {
    EXPECT_NEAR(over.atFraction, 11.0 / 16.0, radFromDeg(0.1) / radFromDeg(16.0) + 1e-9);
  } else {
    EXPECT_FALSE(over.ok());  // some other problem came first
    EXPECT_LT(over.atFraction, 11.0 / 16.0);
  }
}

TEST(Safety, SafeTravelIsStraightWhenPossibleAndDetoursOtherwise) {
  const MachineProfile pr = profileFor(kDai);
  const IkResult a = inverse(kDai, {-20.0, 170.0}, WorkingMode::PlusPlus);
  const IkResult b = inverse(kDai, {30.0, 190.0}, WorkingMode::PlusPlus);
  ASSERT_TRUE(a.ok() && b.ok());
  const auto straight = planSafeTravel(pr, a.angles, b.angles);
  ASSERT_TRUE(straight.has_value());
  ASSERT_EQ(straight->size(), 1u);
  EXPECT_EQ(straight->front(), b.angles);

  auto rng = test::rng();
  std::uniform_real_distribution<double> x(-200.0, 200.0), y(0.0, 250.0);
  int detours = 0;
  for (int trial = 0; trial < 400 && detours < 3; ++trial) {
    const IkResult p = inverse(kDai, {x(rng), y(rng)}, WorkingMode::PlusPlus);
    const IkResult q = inverse(kDai, {x(rng), y(rng)}, WorkingMode::PlusPlus);
    if (!p.ok() || !q.ok() || !checkPose(pr, p.angles).ok() || !checkPose(pr, q.angles).ok())
      continue;
    const JointAngles to{unwrapNear(q.angles.theta1, p.angles.theta1),
                         unwrapNear(q.angles.theta2, p.angles.theta2)};
    if (checkJointMove(pr, p.angles, to).ok()) continue;
    const auto path = planSafeTravel(pr, p.angles, to);
    if (!path) continue;
    ++detours;
    ASSERT_GE(path->size(), 2u);
    EXPECT_EQ(path->back(), to);
    JointAngles here = p.angles;
    for (const JointAngles& w : *path) {
      EXPECT_TRUE(checkJointMove(pr, here, w).ok());
      here = w;
    }
  }
  EXPECT_GT(detours, 0) << "seed " << test::seed();
}

TEST(Safety, NoTravelBetweenWorkingModes) {
  const MachineProfile pr = profileFor(kDai);
  const IkResult a = inverse(kDai, {0.0, 170.0}, WorkingMode::PlusPlus);
  const IkResult b = inverse(kDai, {0.0, 170.0}, WorkingMode::MinusPlus);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_TRUE(checkPose(pr, a.angles).ok());
  EXPECT_FALSE(planSafeTravel(pr, a.angles, b.angles).has_value());
}

}  // namespace
}  // namespace fivebar
