// SPDX-License-Identifier: GPL-3.0-or-later
// Placement of drawings in the machine frame (core/placement.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "core/planning/placement.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

// A 40 x 20 mm drawing: one closed rectangle (work frame, y up) and a hidden layer far away.
Drawing sampleDrawing() {
  Drawing d;
  Layer visible;
  visible.paths.push_back({{{10, 5}, {50, 5}, {50, 25}, {10, 25}}, true});
  visible.paths.push_back({{{20, 10}, {30, 15}}, false});
  Layer hidden;
  hidden.visible = false;
  hidden.paths.push_back({{{1000, 1000}, {2000, 2000}}, false});
  d.layers = {visible, hidden};
  return d;
}

TEST(Placement, BoundsIgnoreHiddenLayers) {
  const auto b = drawingBounds(sampleDrawing());
  ASSERT_TRUE(b.has_value());
  EXPECT_DOUBLE_EQ(b->x0, 10);
  EXPECT_DOUBLE_EQ(b->y0, 5);
  EXPECT_DOUBLE_EQ(b->x1, 50);
  EXPECT_DOUBLE_EQ(b->y1, 25);
  EXPECT_FALSE(drawingBounds(Drawing{}).has_value());
}

TEST(Placement, TransformMapsPointsByCentreRotationAndScale) {
  const Drawing d = sampleDrawing();
  auto rng = test::rng();
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    Placement pl{Vec2(100 * u(rng), 150 + 50 * u(rng)), kPi * u(rng), 1.0 + 0.9 * u(rng)};
    const Eigen::Affine2d t = machineFromWork(d, pl);
    // The bbox centre (30, 15) lands on the centre.
    EXPECT_NEAR(((t * Vec2(30, 15)) - pl.centerMm).norm(), 0.0, 1e-9);
    // A work vector of length L along +x becomes one of length scale * L at angle rotation.
    const Vec2 v = t * Vec2(40, 15) - t * Vec2(30, 15);
    EXPECT_NEAR(v.norm(), 10.0 * pl.scale, 1e-9);
    EXPECT_NEAR(std::atan2(v.y(), v.x()), normalizeRad(pl.rotationRad), 1e-9);
    // y stays counter-clockwise of x (no mirror: the drawing reads upright).
    const Vec2 vy = t * Vec2(30, 25) - t * Vec2(30, 15);
    EXPECT_GT(cross(v, vy), 0.0);
  }
}

TEST(Placement, PlaceDrawingKeepsOrderClosesLoopsAndSkipsHidden) {
  const Drawing d = sampleDrawing();
  const Placement pl{Vec2(0, 200), kPi / 2, 2.0};
  const std::vector<Stroke> s = placeDrawing(d, pl);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].layerIndex, 0);
  EXPECT_EQ(s[0].pathIndex, 0);
  EXPECT_EQ(s[1].pathIndex, 1);
  ASSERT_EQ(s[0].points.size(), 5u);  // closing point appended
  EXPECT_EQ(s[0].points.front(), s[0].points.back());
  // (10, 5) is 20 left of and 10 below the centre: rotated 90 deg and doubled -> (+20, -40).
  EXPECT_NEAR((s[0].points[0] - Vec2(20, 160)).norm(), 0.0, 1e-9);
  EXPECT_FALSE(s[0].reversed);
}

TEST(Placement, FitPutsTheBoundsInsideTheRectangle) {
  const Drawing d = sampleDrawing();
  const RectMm rect{-60, 120, 40, 260};
  for (double rot : {0.0, 0.3, kPi / 2, 2.5}) {
    for (bool keep : {true, false}) {
      const auto pl = fitPlacement(d, rect, keep, 5.0, rot);
      ASSERT_TRUE(pl.has_value());
      const auto b = strokeBounds(placeDrawing(d, *pl));
      ASSERT_TRUE(b.has_value());
      const RectMm inner{rect.x0 + 5, rect.y0 + 5, rect.x1 - 5, rect.y1 - 5};
      EXPECT_TRUE(inner.contains({b->x0, b->y0}, 1e-9) && inner.contains({b->x1, b->y1}, 1e-9))
          << "rotation " << rot << " keepAspect " << keep;
      // Largest fit: the bounds touch the inner rectangle on at least one axis.
      const bool touchesX = std::abs(b->width() - inner.width()) < 1e-6;
      const bool touchesY = std::abs(b->height() - inner.height()) < 1e-6;
      EXPECT_TRUE(touchesX || touchesY);
      if (keep) {
        EXPECT_DOUBLE_EQ(pl->stretchY, 1.0);
      }
      if (!keep && rot == 0.0) {
        EXPECT_TRUE(touchesX && touchesY);
      }
    }
  }
  EXPECT_FALSE(fitPlacement(d, RectMm{0, 0, 8, 8}, true, 5.0).has_value());
}

}  // namespace
}  // namespace fivebar
