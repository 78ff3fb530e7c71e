// SPDX-License-Identifier: GPL-3.0-or-later
// Hatch fills (core/planning/hatch.hpp) checked against an independent point-in-polygon test
// (winding number by angle summation): every hatch point inside, every hatch line ending on the
// boundary, the area covered at the spacing, few strokes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/planning/hatch.hpp"

namespace fivebar {
namespace {

using Rings = std::vector<std::vector<Vec2>>;
constexpr double kOnBoundaryMm = 1e-7;

// Winding number of the rings around p by summing the angles the edges subtend (no scanlines,
// no crossing rules: independent of the hatcher).
int windingByAngles(const Rings& rings, const Vec2& p) {
  double total = 0.0;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i] - p, b = ring[(i + 1) % ring.size()] - p;
      total += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  return static_cast<int>(std::lround(total / (2.0 * std::numbers::pi)));
}

bool inside(const Rings& rings, FillRule rule, const Vec2& p) {
  const int w = windingByAngles(rings, p);
  return rule == FillRule::EvenOdd ? (w & 1) != 0 : w != 0;
}

double distanceToBoundary(const Rings& rings, const Vec2& p) {
  double best = 1e300;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const Vec2 ab = b - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * ab - p).norm());
    }
  return best;
}

double distanceToLines(const std::vector<Polyline>& lines, const Vec2& p) {
  double best = 1e300;
  for (const Polyline& l : lines)
    for (std::size_t i = 0; i + 1 < l.points.size(); ++i) {
      const Vec2 a = l.points[i], ab = l.points[i + 1] - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * ab - p).norm());
    }
  return best;
}

// Checks the hatch of `rings` exhaustively; returns the number of strokes.
std::size_t checkHatch(const Rings& rings, FillRule rule, double spacing, double angle) {
  const std::vector<Polyline> lines = hatchArea(rings, rule, spacing, angle);
  const Vec2 dir(std::cos(angle), std::sin(angle));
  std::size_t hatchSegments = 0;
  for (const Polyline& l : lines) {
    EXPECT_GE(l.points.size(), 2u);
    EXPECT_FALSE(l.closed);
    for (std::size_t i = 0; i + 1 < l.points.size(); ++i) {
      const Vec2 a = l.points[i], b = l.points[i + 1];
      // Inside: every sample, by the independent test (or on the boundary).
      for (int s = 0; s <= 20; ++s) {
        const Vec2 p = a + (b - a) * (s / 20.0);
        if (distanceToBoundary(rings, p) > kOnBoundaryMm) {
          EXPECT_TRUE(inside(rings, rule, p)) << "(" << p.x() << ", " << p.y() << ") outside";
        }
      }
      const Vec2 ab = b - a;
      const bool alongHatch = std::abs(ab.x() * dir.y() - ab.y() * dir.x()) < 1e-9 * ab.norm();
      if (alongHatch) {
        ++hatchSegments;
        // A hatch line reaches the boundary at both ends.
        EXPECT_LT(distanceToBoundary(rings, a), kOnBoundaryMm);
        EXPECT_LT(distanceToBoundary(rings, b), kOnBoundaryMm);
        // On the spacing grid: offset across the lines is (k + 1/2) * spacing.
        const double offset = -a.x() * dir.y() + a.y() * dir.x();
        const double k = offset / spacing - 0.5;
        EXPECT_NEAR(k, std::round(k), 1e-6);
      }
    }
  }
  EXPECT_GT(hatchSegments, 0u);
  // Covered: any inside point at least a spacing away from the boundary has a hatch line within
  // half a spacing.
  double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
  for (const auto& ring : rings)
    for (const Vec2& p : ring) {
      minX = std::min(minX, p.x()), maxX = std::max(maxX, p.x());
      minY = std::min(minY, p.y()), maxY = std::max(maxY, p.y());
    }
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> ux(minX, maxX), uy(minY, maxY);
  int checked = 0;
  for (int i = 0; i < 4000 && checked < 300; ++i) {
    const Vec2 p(ux(rng), uy(rng));
    if (!inside(rings, rule, p) || distanceToBoundary(rings, p) < spacing) continue;
    ++checked;
    EXPECT_LE(distanceToLines(lines, p), 0.5 * spacing + 1e-9) << p.transpose();
  }
  EXPECT_GT(checked, 20);
  return lines.size();
}

std::vector<Vec2> square(double x0, double y0, double side, bool counterClockwise = true) {
  std::vector<Vec2> s = {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
  if (!counterClockwise) std::reverse(s.begin(), s.end());
  return s;
}

TEST(Hatch, ConvexSquareIsOneStrokeOfLinesAtTheSpacing) {
  const Rings rings = {square(0, 0, 20)};
  EXPECT_EQ(checkHatch(rings, FillRule::NonZero, 1.0, 0.0), 1u);
  const std::vector<Polyline> lines = hatchArea(rings, FillRule::NonZero, 1.0, 0.0);
  // 20 lines of 20 mm at y = 0.5 ... 19.5, joined by 19 steps of 1 mm.
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < lines[0].points.size(); ++i)
    length += (lines[0].points[i + 1] - lines[0].points[i]).norm();
  EXPECT_NEAR(length, 20 * 20.0 + 19 * 1.0, 1e-9);
  EXPECT_NEAR(lines[0].points.front().y(), 0.5, 1e-12);
  for (double angle : {0.3, 1.0, 2.5, -0.7}) EXPECT_EQ(checkHatch(rings, FillRule::EvenOdd, 0.7, angle), 1u);
}

TEST(Hatch, HolesUnderBothFillRules) {
  // Hole drawn the opposite way: a hole under both rules.
  const Rings opposite = {square(0, 0, 30), square(10, 10, 10, false)};
  for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    EXPECT_LE(checkHatch(opposite, rule, 0.8, 0.4), 4u);
    EXPECT_FALSE(inside(opposite, rule, {15, 15}));
  }
  // Hole drawn the same way: a hole for evenodd only; nonzero fills it.
  const Rings same = {square(0, 0, 30), square(10, 10, 10, true)};
  checkHatch(same, FillRule::EvenOdd, 0.8, 0.4);
  checkHatch(same, FillRule::NonZero, 0.8, 0.4);
  const auto evenOdd = hatchArea(same, FillRule::EvenOdd, 0.8, 0.4);
  const auto nonZero = hatchArea(same, FillRule::NonZero, 0.8, 0.4);
  EXPECT_GT(distanceToLines(evenOdd, {15, 15}), 4.0);
  EXPECT_LT(distanceToLines(nonZero, {15, 15}), 0.41);
}

TEST(Hatch, SelfIntersectingStarAndConcaveShape) {
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = std::numbers::pi / 2 + i * 4.0 * std::numbers::pi / 5.0;
    star.emplace_back(25 + 20 * std::cos(a), 25 + 20 * std::sin(a));
  }
  checkHatch({star}, FillRule::NonZero, 0.5, 0.2);
  checkHatch({star}, FillRule::EvenOdd, 0.5, 0.2);
  EXPECT_LT(distanceToLines(hatchArea({star}, FillRule::NonZero, 0.5, 0.2), {25, 25}), 0.26);
  EXPECT_GT(distanceToLines(hatchArea({star}, FillRule::EvenOdd, 0.5, 0.2), {25, 25}), 2.0);
  // A U: the joins must not jump across the gap between its arms.
  const Rings u = {{{0, 0}, {30, 0}, {30, 30}, {20, 30}, {20, 10}, {10, 10}, {10, 30}, {0, 30}}};
  EXPECT_LE(checkHatch(u, FillRule::NonZero, 1.0, 0.0), 2u);
  checkHatch(u, FillRule::NonZero, 1.3, std::numbers::pi / 2);
  checkHatch(u, FillRule::EvenOdd, 0.9, 0.77);
}

TEST(Hatch, ApplyFillKeepsStrokesDropsOrHatchesFillOnlyShapes) {
  std::vector<Polyline> paths;
  paths.push_back(Polyline{{{0, 0}, {5, 5}}, false});  // a stroke
  Polyline outer{square(0, 0, 10), true, FillRule::EvenOdd, true, true};
  Polyline hole{square(3, 3, 4), true, FillRule::EvenOdd, false, true};
  paths.push_back(outer);
  paths.push_back(hole);
  Polyline stroked{square(20, 0, 10), true, FillRule::NonZero, true, false};  // filled and stroked
  paths.push_back(stroked);
  HatchSettings s;
  s.spacingMm = 1.0;
  EXPECT_EQ(applyFill(paths, FillMode::Outline, s).size(), 4u);
  const auto none = applyFill(paths, FillMode::None, s);
  ASSERT_EQ(none.size(), 2u);
  EXPECT_FALSE(none[1].fillOnly);
  const auto hatched = applyFill(paths, FillMode::Hatch, s);
  // stroke, 2 rings, hatch of the ring shape, stroked square, its hatch (1 stroke).
  ASSERT_GE(hatched.size(), 6u);
  EXPECT_EQ(hatched[3].fill, FillRule::None);
  s.outline = false;
  const auto bare = applyFill(paths, FillMode::Hatch, s);
  EXPECT_EQ(bare.size(), hatched.size() - 2);
  s.crosshatch = true;
  const auto crossed = applyFill(paths, FillMode::Hatch, s);
  std::size_t vertical = 0;
  for (const Polyline& l : crossed)
    for (std::size_t i = 0; i + 1 < l.points.size(); ++i)
      if (std::abs(l.points[i].x() - l.points[i + 1].x()) < 1e-9 &&
          std::abs(l.points[i].y() - l.points[i + 1].y()) > 2.0)
        ++vertical;
  EXPECT_GT(vertical, 10u);
  EXPECT_EQ(validate(HatchSettings{0.0, 0.0, false, true}), "hatch spacing must be at least 0.01 mm");
  EXPECT_EQ(fillModeFromString("hatch"), FillMode::Hatch);
  EXPECT_FALSE(fillModeFromString("solid"));
}

}  // namespace
}  // namespace fivebar
