// SPDX-License-Identifier: GPL-3.0-or-later
// The error budget told honestly (issue 9): every drawn move measured against the true geometry
// with its own FK samples, the joining gap taken from the tolerance and charged, and the 8x goal
// over seeds 1-10 (not one lucky seed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "core/kinematics/kinematics.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

MachineProfile makerPlotter() { return *preset("maker-plotter"); }

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Largest distance from the drawn line (FK of every Draw move, sampled `samples` times along
// the joint-linear move) to the nearest segment of the true geometry (`truth`, machine frame).
double drawnErrorMm(const PlannedJob& job, const MachineProfile& p,
                    const std::vector<std::vector<Vec2>>& truth, int samples = 64) {
  double worst = 0.0;
  JointAngles at = job.start;
  for (const JobMove& m : job.moves) {
    if (!isMotion(m.kind)) continue;
    if (m.kind == JobMoveKind::Draw) {
      for (int k = 0; k <= samples; ++k) {
        const double u = static_cast<double>(k) / samples;
        const JointAngles q{at.theta1 + u * (m.target.theta1 - at.theta1),
                            at.theta2 + u * (m.target.theta2 - at.theta2)};
        const FkResult fk = forward(p.geometry, q, job.assembly);
        if (!fk.ok()) return std::numeric_limits<double>::infinity();
        double nearest = std::numeric_limits<double>::infinity();
        for (const std::vector<Vec2>& line : truth)
          for (std::size_t i = 0; i + 1 < line.size(); ++i)
            nearest = std::min(nearest, pointSegmentDistance(fk.p, line[i], line[i + 1]));
        worst = std::max(worst, nearest);
      }
    }
    at = m.target;
  }
  return worst;
}

// The drawing's polylines in the machine frame, as the planner placed them.
std::vector<std::vector<Vec2>> placedTruth(const Drawing& d, const PlanResult& r) {
  std::vector<std::vector<Vec2>> out;
  for (const Stroke& s : placeDrawing(d, r.placement)) out.push_back(s.points);
  return out;
}

int penDowns(const PlannedJob& job) {
  return static_cast<int>(std::count_if(job.moves.begin(), job.moves.end(),
                                        [](const JobMove& m) { return m.kind == JobMoveKind::PenDown; }));
}

Drawing twoStrokesWithGap(double gapMm) {
  Drawing d;
  d.source = "gap.svg";
  d.layers.resize(1);
  d.layers[0].id = d.layers[0].name = "ink";
  d.layers[0].paths.push_back({{{0, 0}, {30, 0}}, false});
  d.layers[0].paths.push_back({{{30 + gapMm, 0}, {45, 20}}, false});
  return d;
}

// The gap stroke joining bridges comes from the tolerance, and the drawn bridge is charged.
TEST(ErrorBudget, JoiningGapComesFromTheToleranceAndIsCharged) {
  const MachineProfile p = makerPlotter();
  const double gapMm = 0.004;
  const Drawing d = twoStrokesWithGap(gapMm);
  PlanOptions tight;
  tight.toleranceMm = 0.01;  // may bridge kJoinGapShare x 0.01 = 0.002 mm: the strokes stay apart
  const PlanResult apart = planJob(d, p, tight);
  ASSERT_TRUE(apart.ok()) << apart.message;
  EXPECT_EQ(penDowns(apart.job), 2);
  EXPECT_EQ(apart.report.bridgedGapMm, 0.0);
  EXPECT_LE(joinGapMm(tight.toleranceMm), tight.toleranceMm);
  PlanOptions loose;
  loose.toleranceMm = 0.05;  // may bridge 0.01 mm: joined, the 0.004 mm bridge drawn
  const PlanResult joined = planJob(d, p, loose);
  ASSERT_TRUE(joined.ok()) << joined.message;
  EXPECT_EQ(penDowns(joined.job), 1);
  EXPECT_NEAR(joined.report.bridgedGapMm, gapMm, 1e-9);
  // Half the gap (the bridge's middle is that far from both ends) is part of the bound ...
  EXPECT_GE(joined.report.maxDeviationMm, joined.report.jointDeviationMm + 0.5 * gapMm - 1e-12);
  EXPECT_LE(joined.report.maxDeviationMm, loose.toleranceMm);
  // ... and the drawn line, bridge included, is within what the report says.
  const double drawn = drawnErrorMm(joined.job, p, placedTruth(d, joined));
  std::cout << "joined: drawn within " << drawn << " mm, reported " << joined.report.maxDeviationMm
            << " mm\n";
  EXPECT_LE(drawn, joined.report.maxDeviationMm + 1e-6);
  EXPECT_GT(drawn, 0.5 * gapMm - 1e-6);  // the bridge really is drawn
  // A gap over the largest bridge is never joined, whatever the tolerance.
  PlanOptions huge;
  huge.toleranceMm = 2.0;
  const PlanResult wide = planJob(twoStrokesWithGap(2.0 * kJoinGapMaxMm), p, huge);
  ASSERT_TRUE(wide.ok()) << wide.message;
  EXPECT_EQ(penDowns(wide.job), 2);
}

// Random straight lines, about 80 x 60 mm.
Drawing randomLines(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> x(0, 80), y(0, 60);
  Drawing d;
  d.source = "lines.svg";
  d.layers.resize(1);
  d.layers[0].id = d.layers[0].name = "lines";
  for (int i = 0; i < n; ++i) d.layers[0].paths.push_back({{{x(rng), y(rng)}, {x(rng), y(rng)}}, false});
  return d;
}

// The goal on every seed from 1 to 10 (FIVEBAR_TEST_SEED=N adds seed N): at least 8x
// fewer pen-down moves than firmware-style segmentation (200 segments/s at 50 mm/s, none under
// 0.5 mm) on 200 random straight lines at 0.01 mm, the drawn line measured within the tolerance.
TEST(ErrorBudget, EightTimesFewerMovesThanFirmwareOnSeedsOneToTen) {
  const MachineProfile p = makerPlotter();
  std::vector<std::uint64_t> seeds{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  if (std::getenv("FIVEBAR_TEST_SEED")) seeds.push_back(test::seed());
  double lowest = 1e9, highest = 0.0;
  for (const std::uint64_t seed : seeds) {
    std::mt19937_64 rng(seed);
    const Drawing d = randomLines(rng, 200);
    PlanOptions o;
    o.toleranceMm = 0.01;
    o.optimise = false;
    const PlanResult r = planJob(d, p, o);
    ASSERT_TRUE(r.ok()) << "seed " << seed << ": " << r.message;
    const double firmwareLengthMm = std::max(50.0 / 200.0, 0.5);
    long firmware = 0;
    for (const Polyline& l : d.layers[0].paths)
      firmware += static_cast<long>(std::ceil((l.points[1] - l.points[0]).norm() / firmwareLengthMm));
    const double ratio = static_cast<double>(firmware) / r.report.segments;
    const double drawn = drawnErrorMm(r.job, p, placedTruth(d, r), 32);
    std::cout << "seed " << seed << ": firmware-style " << firmware << ", planned "
              << r.report.segments << " (ratio " << ratio << "), reported "
              << r.report.maxDeviationMm << " mm, drawn " << drawn << " mm\n";
    lowest = std::min(lowest, ratio);
    highest = std::max(highest, ratio);
    EXPECT_GE(ratio, 8.0) << "seed " << seed;
    EXPECT_LE(r.report.maxDeviationMm, o.toleranceMm) << "seed " << seed;
    EXPECT_LE(drawn, o.toleranceMm) << "seed " << seed;
  }
  std::cout << "ratio over the seeds: " << lowest << " .. " << highest << "\n";
}

}  // namespace
}  // namespace fivebar
