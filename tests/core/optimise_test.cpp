// SPDX-License-Identifier: GPL-3.0-or-later
// Stroke optimisation (core/optimise.hpp): joins, reversal and reordering keep every point,
// travel time (joint space) goes down, layers keep their order; RDP simplification bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/planning/optimise.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};

MachineProfile daiProfile() {
  MachineProfile p;
  p.geometry = kDai;
  p.motors.maxSpeedRadPerS1 = 3.0;
  p.motors.maxSpeedRadPerS2 = 2.0;  // unequal on purpose: cost is per motor
  return p;
}

// Random short strokes in a reachable patch of the dai2022 workspace.
std::vector<Stroke> randomStrokes(std::mt19937_64& rng, int n, int layers) {
  std::uniform_real_distribution<double> x(-50.0, 50.0), y(130.0, 200.0), step(-4.0, 4.0);
  std::uniform_int_distribution<int> len(1, 6);
  std::vector<Stroke> out;
  for (int layer = 0; layer < layers; ++layer)
    for (int i = 0; i < n; ++i) {
      Stroke s;
      s.layerIndex = layer;
      s.pathIndex = i;
      Vec2 p(x(rng), y(rng));
      for (int k = len(rng); k >= 0; --k) {
        s.points.push_back(p);
        p += Vec2(step(rng), step(rng));
      }
      out.push_back(s);
    }
  return out;
}

// Independent travel time: IK of both ends, shortest angle difference per motor over its speed.
double independentTravel(const std::vector<Stroke>& strokes, const MachineProfile& pr) {
  double total = 0.0;
  for (std::size_t i = 1; i < strokes.size(); ++i) {
    const IkResult a = inverse(pr.geometry, strokes[i - 1].points.back(), WorkingMode::PlusPlus);
    const IkResult b = inverse(pr.geometry, strokes[i].points.front(), WorkingMode::PlusPlus);
    EXPECT_TRUE(a.ok() && b.ok());
    const double d1 = std::abs(std::remainder(b.angles.theta1 - a.angles.theta1, 2 * kPi));
    const double d2 = std::abs(std::remainder(b.angles.theta2 - a.angles.theta2, 2 * kPi));
    total += std::max(d1 / pr.motors.maxSpeedRadPerS1, d2 / pr.motors.maxSpeedRadPerS2);
  }
  return total;
}

using Key = std::pair<int, int>;  // layerIndex, pathIndex

TEST(Optimise, ReorderKeepsEveryStrokeIntactAndCutsTravel) {
  auto rng = test::rng();
  const MachineProfile pr = daiProfile();
  const std::vector<Stroke> in = randomStrokes(rng, 400, 1);
  OptimiseOptions o;
  o.join = false;
  const OptimiseResult r = optimise(in, pr, WorkingMode::PlusPlus, o);
  ASSERT_EQ(r.strokes.size(), in.size());
  std::map<Key, int> seen;
  for (const Stroke& s : r.strokes) {
    ++seen[{s.layerIndex, s.pathIndex}];
    std::vector<Vec2> pts = in[s.pathIndex].points;
    if (s.reversed) std::reverse(pts.begin(), pts.end());
    EXPECT_EQ(s.points, pts) << "stroke " << s.pathIndex;
  }
  EXPECT_EQ(seen.size(), in.size());
  const double before = independentTravel(in, pr), after = independentTravel(r.strokes, pr);
  EXPECT_NEAR(r.report.travelBeforeS, before, 1e-9);
  EXPECT_NEAR(r.report.travelAfterS, after, 1e-9);
  EXPECT_LT(after, 0.3 * before) << "before " << before << " s, after " << after << " s";
}

TEST(Optimise, TwoOptDoesNotLoseToGreedyAlone) {
  auto rng = test::rng();
  const MachineProfile pr = daiProfile();
  const std::vector<Stroke> in = randomStrokes(rng, 600, 1);
  OptimiseOptions greedy;
  greedy.join = false;
  greedy.maxTwoOptPasses = 0;
  OptimiseOptions full = greedy;
  full.maxTwoOptPasses = 50;
  const double g = optimise(in, pr, WorkingMode::PlusPlus, greedy).report.travelAfterS;
  const double f = optimise(in, pr, WorkingMode::PlusPlus, full).report.travelAfterS;
  EXPECT_LT(f, g);
}

TEST(Optimise, LayersKeepTheirOrderAndJoinOnlyWithinALayer) {
  const MachineProfile pr = daiProfile();
  // Layer 0: a - b meet end to start exactly, c meets b's end reversed; layer 1 starts where
  // layer 0's last stroke ends but must not be joined to it.
  std::vector<Stroke> in(4);
  in[0].points = {{0, 150}, {10, 150}};
  in[1].points = {{10, 150}, {10, 160}};
  in[2].points = {{20, 170}, {10.01, 160}};
  in[2].pathIndex = 2;
  in[1].pathIndex = 1;
  in[3].points = {{20, 170}, {40, 190}};
  in[3].layerIndex = 1;
  in[3].pathIndex = 0;
  const OptimiseResult r = optimise(in, pr, WorkingMode::PlusPlus, {});
  ASSERT_EQ(r.strokes.size(), 2u);
  EXPECT_EQ(r.report.joins, 2u);
  EXPECT_EQ(r.strokes[0].layerIndex, 0);
  EXPECT_EQ(r.strokes[1].layerIndex, 1);
  // The exact join drops one duplicate; the 0.01 mm join keeps both points.
  const std::vector<Vec2> chain{{0, 150}, {10, 150}, {10, 160}, {10.01, 160}, {20, 170}};
  std::vector<Vec2> got = r.strokes[0].points;
  if (got.front() != chain.front()) std::reverse(got.begin(), got.end());
  EXPECT_EQ(got, chain);
  EXPECT_EQ(r.report.pointsAfter, r.report.pointsBefore - 1);
  EXPECT_EQ(r.strokes[1].points, in[3].points);
}

TEST(Optimise, ManyLayersStayGroupedAndNothingIsLost) {
  auto rng = test::rng();
  const MachineProfile pr = daiProfile();
  const std::vector<Stroke> in = randomStrokes(rng, 150, 3);
  OptimiseOptions o;
  o.joinToleranceMm = 0.0;  // random ends never meet exactly
  const OptimiseResult r = optimise(in, pr, WorkingMode::PlusPlus, o);
  ASSERT_EQ(r.strokes.size(), in.size());
  EXPECT_TRUE(std::is_sorted(r.strokes.begin(), r.strokes.end(),
                             [](const Stroke& a, const Stroke& b) { return a.layerIndex < b.layerIndex; }));
  std::size_t points = 0;
  for (const Stroke& s : r.strokes) points += s.points.size();
  EXPECT_EQ(points, r.report.pointsBefore);
}

TEST(Optimise, RamerDouglasPeuckerStaysWithinTolerance) {
  auto rng = test::rng();
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<Vec2> pts;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i * 0.01;
    pts.push_back({10 * std::cos(t) + noise(rng), 10 * std::sin(t) + noise(rng)});
  }
  const double tol = 0.5;
  const std::vector<Vec2> s = simplifyPolyline(pts, tol);
  EXPECT_LT(s.size(), pts.size() / 4);
  EXPECT_EQ(s.front(), pts.front());
  EXPECT_EQ(s.back(), pts.back());
  // Every original point lies within tol of the simplified polyline.
  for (const Vec2& p : pts) {
    double best = 1e9;
    for (std::size_t k = 1; k < s.size(); ++k) {
      const Vec2 ab = s[k] - s[k - 1];
      const double t = std::clamp((p - s[k - 1]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (p - s[k - 1] - t * ab).norm());
    }
    ASSERT_LE(best, tol + 1e-12);
  }
  const std::vector<Vec2> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_EQ(simplifyPolyline(line, 1e-6).size(), 2u);
  EXPECT_EQ(simplifyPolyline(pts, 0.0), pts);
}

TEST(Optimise, HundredThousandStrokesWithinBudget) {
  auto rng = test::rng();
  const MachineProfile pr = daiProfile();
  const std::vector<Stroke> in = randomStrokes(rng, 100000, 1);
  OptimiseOptions o;
  o.join = false;
  const OptimiseResult r = optimise(in, pr, WorkingMode::PlusPlus, o);
  EXPECT_EQ(r.strokes.size(), in.size());
  EXPECT_LT(r.report.travelAfterS, 0.1 * r.report.travelBeforeS);
#ifdef NDEBUG  // timing only means something in an optimised build
  EXPECT_LT(r.report.seconds, 3.0);  // loose for a loaded CI machine; figures in docs/performance
#endif
}

}  // namespace
}  // namespace fivebar
