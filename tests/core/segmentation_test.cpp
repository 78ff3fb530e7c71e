// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive segmentation: the real drawn curve (dense FK along every planned joint-linear move,
// measured here independently) stays within the budget of the stroke, both ways; moves merge
// many input points; failures name where.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/kinematics/move_samples.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/segmentation.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

constexpr int kDenseSamples = 400;

double pointSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double distanceToPolyline(const Vec2& p, const std::vector<Vec2>& poly) {
  if (poly.size() == 1) return (p - poly[0]).norm();
  double best = 1e300;
  for (size_t i = 0; i + 1 < poly.size(); ++i) best = std::min(best, pointSegment(p, poly[i], poly[i + 1]));
  return best;
}

// The part of `stroke` between arc lengths s0 and s1.
std::vector<Vec2> subPolyline(const std::vector<Vec2>& stroke, double s0, double s1) {
  std::vector<Vec2> out;
  double s = 0.0;
  auto at = [&](size_t i, double target) {
    const Vec2 a = stroke[i], b = stroke[i + 1];
    const double l = (b - a).norm();
    return Vec2(a + (l > 0 ? (target - s) / l : 0.0) * (b - a));
  };
  for (size_t i = 0; i + 1 < stroke.size(); ++i) {
    const double l = (stroke[i + 1] - stroke[i]).norm();
    if (s + l >= s0 && out.empty()) out.push_back(at(i, s0));
    if (!out.empty() && s + l > s0 && s < s1) {
      if (s + l >= s1) { out.push_back(at(i, s1)); return out; }
      out.push_back(stroke[i + 1]);
    }
    s += l;
  }
  if (out.empty()) out.push_back(stroke.back());
  return out;
}

// Largest two-way distance between the dense FK curves of the moves and the stroke.
double measuredMaxDeviation(const Geometry& g, AssemblyMode asmb, const std::vector<Vec2>& stroke,
                            const SegmentedStroke& seg) {
  double worst = 0.0, s = 0.0;
  for (size_t k = 1; k < seg.waypoints.size(); ++k) {
    const JointWaypoint& a = seg.waypoints[k - 1];
    const JointWaypoint& b = seg.waypoints[k];
    const std::vector<Vec2> part = subPolyline(stroke, s, s + b.pathLengthMm);
    s += b.pathLengthMm;
    std::vector<Vec2> curve;
    for (int i = 0; i <= kDenseSamples; ++i) {
      const double u = static_cast<double>(i) / kDenseSamples;
      const FkResult fk = forward(g, {a.q.theta1 + u * (b.q.theta1 - a.q.theta1),
                                      a.q.theta2 + u * (b.q.theta2 - a.q.theta2)}, asmb);
      EXPECT_TRUE(fk.ok());
      curve.push_back(fk.p);
      worst = std::max(worst, distanceToPolyline(fk.p, part));
    }
    for (const Vec2& v : part) worst = std::max(worst, distanceToPolyline(v, curve));
  }
  return worst;
}

std::vector<Vec2> randomStroke(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> cx(-40, 40), cy(150, 190), r(3, 25), u(0, 1);
  std::vector<Vec2> pts;
  const Vec2 c(cx(rng), cy(rng));
  const int kind = static_cast<int>(u(rng) * 3);
  if (kind == 0) {  // circle flattened finely
    const double radius = r(rng);
    const int n = 20 + static_cast<int>(u(rng) * 300);
    for (int i = 0; i <= n; ++i) {
      const double t = 2 * kPi * i / n;
      pts.emplace_back(c + radius * Vec2(std::cos(t), std::sin(t)));
    }
  } else if (kind == 1) {  // a few long straight lines
    const int n = 2 + static_cast<int>(u(rng) * 5);
    for (int i = 0; i < n; ++i) pts.emplace_back(cx(rng), cy(rng));
  } else {  // wobbly spiral
    const int n = 50 + static_cast<int>(u(rng) * 400);
    for (int i = 0; i <= n; ++i) {
      const double t = 6 * kPi * i / n, rad = 2 + 18.0 * i / n;
      pts.emplace_back(c + rad * Vec2(std::cos(t), std::sin(t)) + Vec2(0.3 * std::sin(9 * t), 0));
    }
  }
  return pts;
}

class SegmentationTest : public ::testing::Test {
 protected:
  MachineProfile p = *preset("maker-plotter");
};

TEST_F(SegmentationTest, EveryMoveStaysWithinTheBudgetMeasuredDensely) {
  auto rng = test::rng();
  for (double budget : {0.02, 0.05, 0.2}) {
    for (int trial = 0; trial < 12; ++trial) {
      const std::vector<Vec2> stroke = randomStroke(rng);
      const SegmentedStroke seg = segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly,
                                                stroke, p.homeAngles, {budget});
      ASSERT_TRUE(seg.ok());
      EXPECT_LE(seg.maxDeviationMm, budget);
      // Dense sampling finds at most the reported bound (plus its own sampling error).
      EXPECT_LE(measuredMaxDeviation(p.geometry, p.assembly, stroke, seg), budget * 1.0 + 1e-6)
          << "budget " << budget << " trial " << trial;
    }
  }
}

TEST_F(SegmentationTest, EndsOnTheStrokeEndsAndCoversItsLength) {
  auto rng = test::rng();
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Vec2> stroke = randomStroke(rng);
    const SegmentedStroke seg =
        segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, stroke, p.homeAngles, {0.05});
    ASSERT_TRUE(seg.ok());
    EXPECT_LT((seg.waypoints.front().p - stroke.front()).norm(), 1e-9);
    EXPECT_LT((seg.waypoints.back().p - stroke.back()).norm(), 1e-9);
    double length = 0.0, covered = 0.0;
    for (size_t i = 1; i < stroke.size(); ++i) length += (stroke[i] - stroke[i - 1]).norm();
    for (const JointWaypoint& w : seg.waypoints) covered += w.pathLengthMm;
    EXPECT_NEAR(covered, length, 1e-6 * length);
    // Every waypoint's angles are the IK of its point, continuous along the stroke.
    for (size_t k = 1; k < seg.waypoints.size(); ++k) {
      const FkResult fk = forward(p.geometry, seg.waypoints[k].q, p.assembly);
      EXPECT_LT((fk.p - seg.waypoints[k].p).norm(), 1e-9);
      EXPECT_LT(std::abs(seg.waypoints[k].q.theta1 - seg.waypoints[k - 1].q.theta1), kPi / 2);
      EXPECT_LT(std::abs(seg.waypoints[k].q.theta2 - seg.waypoints[k - 1].q.theta2), kPi / 2);
    }
  }
}

TEST_F(SegmentationTest, MergesDenseNearlyStraightInputIntoFewMoves) {
  // A gentle arc (radius 500 mm) sampled every 0.1 mm over 60 mm: 601 input points.
  std::vector<Vec2> stroke;
  for (int i = 0; i <= 600; ++i) {
    const double t = (i * 0.1 - 30.0) / 500.0;
    stroke.emplace_back(500.0 * std::sin(t), 170.0 + 500.0 * (1 - std::cos(t)));
  }
  const SegmentedStroke seg =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, stroke, p.homeAngles, {0.05});
  ASSERT_TRUE(seg.ok());
  EXPECT_LT(seg.waypoints.size(), 60u);  // at least 10 input points per move on average
  EXPECT_LE(measuredMaxDeviation(p.geometry, p.assembly, stroke, seg), 0.05);
}

TEST_F(SegmentationTest, SplitsLongStraightLinesWhereTheJointLinearCurveBulges) {
  const std::vector<Vec2> stroke{{-60, 140}, {60, 200}};
  const SegmentedStroke seg =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, stroke, p.homeAngles, {0.05});
  ASSERT_TRUE(seg.ok());
  EXPECT_GT(seg.waypoints.size(), 3u);
  EXPECT_LE(measuredMaxDeviation(p.geometry, p.assembly, stroke, seg), 0.05);
}

// Circles flattened with chords whose sagitta is at most `flattenMm` (what an importer does).
std::vector<Vec2> flattenedCircle(const Vec2& c, double r, double flattenMm) {
  const int n = static_cast<int>(std::ceil(kPi / std::acos(1.0 - flattenMm / r)));
  std::vector<Vec2> pts;
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * kPi * i / n;
    pts.emplace_back(c + r * Vec2(std::cos(t), std::sin(t)));
  }
  return pts;
}

// Max distance of the drawn curve (FK samples) from the TRUE circle, analytically.
double deviationFromCircle(const Geometry& g, AssemblyMode asmb, const SegmentedStroke& seg,
                           const Vec2& c, double r) {
  double worst = 0.0;
  for (size_t k = 1; k < seg.waypoints.size(); ++k) {
    const JointAngles a = seg.waypoints[k - 1].q, b = seg.waypoints[k].q;
    for (int i = 0; i <= 40; ++i) {
      const double u = i / 40.0;
      const FkResult fk = forward(g, {a.theta1 + u * (b.theta1 - a.theta1),
                                      a.theta2 + u * (b.theta2 - a.theta2)}, asmb);
      worst = std::max(worst, std::abs((fk.p - c).norm() - r));
    }
  }
  return worst;
}

TEST_F(SegmentationTest, FewerSegmentsThanFixedLengthAtEqualTotalDeviation) {
  // Firmware style: the curve flattened at 0.05 mm, every piece cut to 0.5 mm. Adaptive: the
  // same total deviation from the true circle, split 40 % flattening / 60 % joint-linear.
  auto rng = test::rng();
  std::uniform_real_distribution<double> cx(-40, 40), cy(150, 190), rr(2, 40);
  size_t fixedCount = 0, adaptiveCount = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Vec2 c(cx(rng), cy(rng));
    const double r = rr(rng);
    const SegmentedStroke fixed = segmentFixedLength(p.geometry, WorkingMode::PlusPlus, p.assembly,
                                                     flattenedCircle(c, r, 0.05), p.homeAngles, 0.5);
    ASSERT_TRUE(fixed.ok());
    const double total = deviationFromCircle(p.geometry, p.assembly, fixed, c, r);
    const SegmentedStroke adaptive =
        segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly,
                      flattenedCircle(c, r, 0.4 * total), p.homeAngles, {0.6 * total});
    ASSERT_TRUE(adaptive.ok());
    EXPECT_LE(deviationFromCircle(p.geometry, p.assembly, adaptive, c, r), total);
    fixedCount += fixed.waypoints.size() - 1;
    adaptiveCount += adaptive.waypoints.size() - 1;
  }
  EXPECT_LE(3 * adaptiveCount, fixedCount) << adaptiveCount << " vs " << fixedCount;
}

TEST_F(SegmentationTest, OutOfReachNamesThePoint) {
  const std::vector<Vec2> stroke{{0, 170}, {10, 175}, {0, 400}, {0, 180}};
  const SegmentedStroke seg =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, stroke, p.homeAngles, {0.05});
  EXPECT_EQ(seg.status, SegmentStatus::OutOfReach);
  EXPECT_LT((seg.failedAt - Vec2(0, 400)).norm(), 1e-12);
}

TEST_F(SegmentationTest, DotAndDuplicatesGiveNoZeroLengthMoves) {
  const std::vector<Vec2> dot{{0, 170}, {0, 170}};
  const SegmentedStroke a =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, dot, p.homeAngles, {0.05});
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.waypoints.size(), 1u);
  const std::vector<Vec2> dup{{0, 170}, {5, 170}, {5, 170}, {10, 171}};
  const SegmentedStroke b =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, dup, p.homeAngles, {0.05});
  ASSERT_TRUE(b.ok());
  for (size_t k = 1; k < b.waypoints.size(); ++k) EXPECT_GT(b.waypoints[k].pathLengthMm, 0.0);
}

TEST_F(SegmentationTest, AnglesUnwrapNearTheReference) {
  // Reference one turn up: the stroke's angles follow it instead of jumping back.
  const JointAngles ref{p.homeAngles.theta1 + 2 * kPi, p.homeAngles.theta2 - 2 * kPi};
  const std::vector<Vec2> stroke{{0, 170}, {10, 170}};
  const SegmentedStroke seg =
      segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, stroke, ref, {0.05});
  ASSERT_TRUE(seg.ok());
  EXPECT_NEAR(seg.waypoints[0].q.theta1, ref.theta1, 1e-9);
  EXPECT_NEAR(seg.waypoints[0].q.theta2, ref.theta2, 1e-9);
}

// A long straight line is split into pieces; when the last piece reaches the line's end, the end
// is a waypoint like any vertex (no zero-length moves, the stroke ends where it should).
TEST_F(SegmentationTest, SplitLinesEndOnTheirEndWithoutZeroLengthMoves) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> x(-90, 90), y(80, 250), budget(0.005, 0.06);
  int planned = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<Vec2> line{{x(rng), y(rng)}, {x(rng), y(rng)}};
    const SegmentedStroke seg = segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly, line,
                                              p.homeAngles, {budget(rng)});
    if (!seg.ok()) continue;  // out of reach in ++: not this test's business
    ++planned;
    ASSERT_NEAR((seg.waypoints.back().p - line[1]).norm(), 0.0, 1e-9) << "trial " << trial;
    for (size_t k = 1; k < seg.waypoints.size(); ++k)
      ASSERT_GT(seg.waypoints[k].pathLengthMm, 0.0) << "trial " << trial << " move " << k;
  }
  EXPECT_GT(planned, 100);
}

TEST_F(SegmentationTest, MoveSamplesAreForwardKinematicsAtEqualSteps) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> x(-60, 60), y(140, 220), unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const IkResult a = inverse(p.geometry, {x(rng), y(rng)}, WorkingMode::PlusPlus);
    const IkResult b = inverse(p.geometry, {x(rng), y(rng)}, WorkingMode::PlusPlus);
    ASSERT_TRUE(a.ok() && b.ok());
    // Short moves (Taylor step rotation) and long ones (re-anchored every 32 samples).
    const int n = trial % 2 ? 1 + static_cast<int>(unit(rng) * 8) : 40 + static_cast<int>(unit(rng) * 900);
    std::vector<Vec2> out(static_cast<size_t>(n) + 1);
    const bool closes = sampleJointMove(p.geometry, p.assembly, a.angles, MotorTrig::of(a.angles),
                                        b.angles, n, out.data());
    bool allClose = true;
    for (int k = 0; k <= n; ++k) {
      const double u = static_cast<double>(k) / n;
      const FkResult fk = forward(p.geometry,
                                  {a.angles.theta1 + u * (b.angles.theta1 - a.angles.theta1),
                                   a.angles.theta2 + u * (b.angles.theta2 - a.angles.theta2)},
                                  p.assembly);
      allClose = allClose && fk.ok();
      if (closes && fk.ok()) {
        ASSERT_LT((fk.p - out[static_cast<size_t>(k)]).norm(), 1e-9) << k << " of " << n;
      }
    }
    EXPECT_EQ(closes, allClose) << "trial " << trial;
  }
}

}  // namespace
}  // namespace fivebar
