// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "../core/test_support.hpp"
#include "core/import/flatten.hpp"
#include "geometry_support.hpp"

namespace fivebar::svg {
namespace {

Vec2 bezier(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3, double t) {
  const double s = 1.0 - t;
  return s * s * s * p0 + 3 * s * s * t * c1 + 3 * s * t * t * c2 + t * t * t * p3;
}

TEST(Flatten, RandomCubicsStayWithinTolerance) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> coord(-200.0, 200.0);
  for (double tolerance : {0.5, 0.05, 0.001}) {
    for (int trial = 0; trial < 60; ++trial) {
      const Vec2 p0(coord(rng), coord(rng)), c1(coord(rng), coord(rng)),
          c2(coord(rng), coord(rng)), p3(coord(rng), coord(rng));
      std::vector<Vec2> pts{p0};
      flattenCubic(p0, c1, c2, p3, tolerance, pts);
      ASSERT_EQ(pts.back(), p3);
      double worst = 0.0;
      for (int i = 0; i <= 1000; ++i)
        worst = std::max(worst, test::distanceToPolyline(bezier(p0, c1, c2, p3, i / 1000.0), pts, false));
      EXPECT_LE(worst, tolerance) << "trial " << trial << " tolerance " << tolerance;
    }
  }
}

TEST(Flatten, AdaptiveUsesFewPointsOnFlatPartsAndMoreForTighterTolerance) {
  std::vector<Vec2> straight;
  flattenCubic({0, 0}, {1, 0}, {2, 0}, {3, 0}, 0.01, straight);
  EXPECT_EQ(straight.size(), 1u);  // a straight cubic needs only its end point
  std::vector<Vec2> coarse, fine;
  flattenCubic({0, 0}, {0, 50}, {50, 50}, {50, 0}, 0.1, coarse);
  flattenCubic({0, 0}, {0, 50}, {50, 50}, {50, 0}, 0.001, fine);
  EXPECT_GT(fine.size(), 4 * coarse.size());  // error ~ h^2: 100x tighter -> ~10x points
}

TEST(Flatten, TransformedEllipseStaysWithinToleranceWithVerticesOnTheCurve) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> axis(-80.0, 80.0);
  for (double tolerance : {0.05, 0.002}) {
    for (int trial = 0; trial < 50; ++trial) {
      const Vec2 centre(axis(rng), axis(rng)), u(axis(rng), axis(rng)), v(axis(rng), axis(rng));
      std::vector<Vec2> pts;
      flattenEllipse(centre, u, v, tolerance, pts);
      ASSERT_GE(pts.size(), 4u);
      double worst = 0.0;
      for (int i = 0; i < 4000; ++i) {
        const double t = 2 * std::numbers::pi * i / 4000.0;
        worst = std::max(worst, test::distanceToPolyline(centre + u * std::cos(t) + v * std::sin(t), pts, true));
      }
      EXPECT_LE(worst, tolerance) << "trial " << trial;
      // An exact sample: the first point is the curve at t = 0.
      EXPECT_LT((pts.front() - (centre + u)).norm(), 1e-12);
    }
  }
}

// The points cap: a curve that needs more stops there (returns false), one that fits is whole.
TEST(Flatten, MaxPointsStopsACurveThatNeedsMore) {
  std::vector<Vec2> out;
  const Vec2 p0(0, 0), c1(10, 10), c2(1e13, 20), p3(100, 100);
  EXPECT_FALSE(flattenCubic(p0, c1, c2, p3, 0.1, out, 1000));
  EXPECT_EQ(out.size(), 1000u);
  std::vector<Vec2> whole;
  EXPECT_TRUE(flattenCubic(Vec2(0, 0), Vec2(1, 1), Vec2(2, 1), Vec2(3, 0), 0.01, whole, 1000));
  std::vector<Vec2> unlimited;
  EXPECT_TRUE(flattenCubic(Vec2(0, 0), Vec2(1, 1), Vec2(2, 1), Vec2(3, 0), 0.01, unlimited));
  EXPECT_EQ(whole.size(), unlimited.size());
  EXPECT_EQ(whole.back(), Vec2(3, 0));
}

}  // namespace
}  // namespace fivebar::svg
