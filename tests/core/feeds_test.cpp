// SPDX-License-Identifier: GPL-3.0-or-later
// Feeds: per-motor speed limits are never exceeded by the planned feeds, the XY speed never
// exceeds the asked one (dense FK, independent of the planner's own samples), short moves are
// slowed to the firmware's minimum duration, F is |dtheta| / duration, and a move's feed does not
// depend on its neighbours (acceleration and junction speeds are GRBL's own planning).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/planning/feeds.hpp"
#include "core/machine/profile.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

std::vector<JointWaypoint> randomChain(const MachineProfile& p, std::mt19937_64& rng, int n,
                                       double maxStepMm) {
  std::uniform_real_distribution<double> step(-maxStepMm, maxStepMm);
  std::vector<JointWaypoint> chain;
  Vec2 at(0, 170);
  JointAngles q = p.homeAngles;
  chain.push_back({q, at, 0, 0});
  while (static_cast<int>(chain.size()) < n) {
    const Vec2 next = at + Vec2(step(rng), step(rng));
    if (next.x() < -60 || next.x() > 60 || next.y() < 130 || next.y() > 210) continue;
    const IkResult ik = inverse(p.geometry, next, WorkingMode::PlusPlus);
    if (!ik.ok()) continue;
    q = {unwrapNear(ik.angles.theta1, q.theta1), unwrapNear(ik.angles.theta2, q.theta2)};
    chain.push_back({q, next, 0, (next - at).norm()});
    at = next;
  }
  return chain;
}

// Largest XY speed along the move at its planned duration, by dense FK sampling.
double peakXYSpeed(const MachineProfile& p, const JointWaypoint& a, const JointWaypoint& b,
                   double durationS) {
  constexpr int kSamples = 200;
  double peak = 0.0;
  Vec2 prev = a.p;
  for (int i = 1; i <= kSamples; ++i) {
    const double u = static_cast<double>(i) / kSamples;
    const FkResult fk = forward(p.geometry, {a.q.theta1 + u * (b.q.theta1 - a.q.theta1),
                                             a.q.theta2 + u * (b.q.theta2 - a.q.theta2)},
                                p.assembly);
    peak = std::max(peak, (fk.p - prev).norm() * kSamples / durationS);
    prev = fk.p;
  }
  return peak;
}

TEST(Feeds, MotorSpeedLimitsAndAskedSpeedHold) {
  auto rng = test::rng();
  MachineProfile p = *preset("maker-plotter");
  const FeedLimits limits = feedLimitsOf(p);
  for (double asked : {10.0, 40.0, 150.0, 1000.0}) {
    for (double stepMm : {0.3, 3.0, 30.0}) {
      const auto chain = randomChain(p, rng, 60, stepMm);
      const auto feeds = planFeeds(p.geometry, p.assembly, chain, asked, limits);
      ASSERT_EQ(feeds.size(), chain.size() - 1);
      for (size_t k = 0; k < feeds.size(); ++k) {
        const double t = feeds[k].durationS;
        const double d1 = chain[k + 1].q.theta1 - chain[k].q.theta1;
        const double d2 = chain[k + 1].q.theta2 - chain[k].q.theta2;
        EXPECT_LE(std::abs(d1) / t, limits.maxSpeedRadPerS1 * (1 + 1e-9));
        EXPECT_LE(std::abs(d2) / t, limits.maxSpeedRadPerS2 * (1 + 1e-9));
        EXPECT_GE(t, limits.minSegmentDurationS * (1 - 1e-12));
        EXPECT_LE(feeds[k].feedMmPerS, asked * (1 + 1e-9));
        EXPECT_NEAR(feeds[k].jointFeedRadPerS, std::hypot(d1, d2) / t, 1e-9);
        // The 8-sample peak in the planner vs a 200-sample peak here: a few % at most.
        EXPECT_LE(peakXYSpeed(p, chain[k], chain[k + 1], t), asked * 1.03);
      }
    }
  }
}

TEST(Feeds, AMoveRunsAtTheAskedSpeedWhateverItsNeighbours) {
  // A sharp turn between long moves used to lower both moves' cruise feeds (the velocity change
  // at the junction); GRBL slows at the junction itself ($11), so the cruise feed stays.
  auto rng = test::rng();
  MachineProfile p = *preset("maker-plotter");
  const FeedLimits limits = feedLimitsOf(p);
  const auto chain = randomChain(p, rng, 40, 20.0);
  const auto feeds = planFeeds(p.geometry, p.assembly, chain, 60.0, limits);
  for (size_t k = 0; k < feeds.size(); ++k) {
    const std::vector<JointWaypoint> alone{chain[k], chain[k + 1]};
    const auto single = planFeeds(p.geometry, p.assembly, alone, 60.0, limits);
    EXPECT_EQ(feeds[k].durationS, single[0].durationS) << "move " << k;
    EXPECT_EQ(feeds[k].limit, single[0].limit) << "move " << k;
  }
  int atAsked = 0;
  for (const SegmentFeed& f : feeds) atAsked += f.limit == FeedLimit::AskedSpeed ? 1 : 0;
  EXPECT_GT(atAsked, static_cast<int>(feeds.size()) / 2);  // 20 mm moves, 60 mm/s: mostly free
}

TEST(Feeds, ShortMovesAreSlowedToTheMinimumDuration) {
  MachineProfile p = *preset("maker-plotter");
  std::vector<JointWaypoint> chain;
  for (int i = 0; i < 3; ++i) {
    const Vec2 at(0.05 * i, 170);
    const IkResult ik = inverse(p.geometry, at, WorkingMode::PlusPlus);
    chain.push_back({ik.angles, at, 0, i == 0 ? 0.0 : 0.05});
  }
  const auto feeds = planFeeds(p.geometry, p.assembly, chain, 40.0, feedLimitsOf(p));
  for (const SegmentFeed& f : feeds) {
    EXPECT_EQ(f.limit, FeedLimit::MinDuration);
    EXPECT_NEAR(f.durationS, kMinSegmentDurationS, 1e-12);
    EXPECT_NEAR(f.feedMmPerS, 0.05 / kMinSegmentDurationS, 1e-9);  // 10 mm/s, not 40
  }
}

TEST(Feeds, MotorLimitSlowsTheXYSpeedWhereTheJacobianIsLarge) {
  // Same 5 mm radial move far from and close to the reach edge (type I: the legs stretch); the
  // motors are the limit at a huge asked speed, so the XY feed is lower where J^-1 is larger.
  MachineProfile p = *preset("maker-plotter");
  auto feedAt = [&](const Vec2& a, const Vec2& b) {
    const JointAngles qa = inverse(p.geometry, a, WorkingMode::PlusPlus).angles;
    const JointAngles qb = inverse(p.geometry, b, WorkingMode::PlusPlus).angles;
    const std::vector<JointWaypoint> chain{{qa, a, 0, 0}, {qb, b, 0, (b - a).norm()}};
    const auto f = planFeeds(p.geometry, p.assembly, chain, 1e5, feedLimitsOf(p));
    EXPECT_EQ(f[0].limit, FeedLimit::MotorSpeed);
    // The faster motor runs exactly at its limit.
    const double fastest = std::max(std::abs(qb.theta1 - qa.theta1), std::abs(qb.theta2 - qa.theta2));
    EXPECT_NEAR(fastest / f[0].durationS, p.motors.maxSpeedRadPerS1, 1e-9);
    return f[0].feedMmPerS;
  };
  const double middle = feedAt({0, 170}, {0, 175});
  const double nearEdge = feedAt({0, 258}, {0, 263});  // radial move
  EXPECT_LT(nearEdge, 0.8 * middle);
}

}  // namespace
}  // namespace fivebar
