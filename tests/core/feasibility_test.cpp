// SPDX-License-Identifier: GPL-3.0-or-later
// Job preflight and working-mode selection (core/feasibility.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "core/planning/feasibility.hpp"
#include "core/planning/placement.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};

MachineProfile daiProfile() {
  MachineProfile p;
  p.geometry = kDai;
  p.homeAngles = inverse(kDai, {0.0, 180.0}, WorkingMode::PlusPlus).angles;
  return p;
}

Stroke line(const Vec2& a, const Vec2& b, int n, int layer = 0, int path = 0) {
  Stroke s;
  s.layerIndex = layer;
  s.pathIndex = path;
  for (int i = 0; i <= n; ++i) s.points.push_back(a + (b - a) * (static_cast<double>(i) / n));
  return s;
}

std::vector<Stroke> square(const Vec2& c, double half) {
  return {line(c + Vec2(-half, -half), c + Vec2(half, -half), 20, 0, 0),
          line(c + Vec2(half, -half), c + Vec2(half, half), 20, 0, 1),
          line(c + Vec2(half, half), c + Vec2(-half, half), 20, 1, 0),
          line(c + Vec2(-half, half), c + Vec2(-half, -half), 20, 1, 1)};
}

std::vector<Stroke> shifted(std::vector<Stroke> s, double scale, const Vec2& anchor, const Vec2& to) {
  for (Stroke& st : s)
    for (Vec2& p : st.points) p = to + scale * (p - anchor);
  return s;
}

TEST(Feasibility, CentralJobIsFeasibleAndItsMarginIsTheWorstPointMargin) {
  const MachineProfile pr = daiProfile();
  const std::vector<Stroke> job = square({0.0, 180.0}, 30.0);
  PreflightOptions o;
  o.includeHomeTravel = false;
  const FeasibilityReport r = preflight(job, pr, WorkingMode::PlusPlus, o);
  EXPECT_TRUE(r.feasible) << r.summary();
  EXPECT_EQ(r.problemCount, 0u);
  EXPECT_EQ(r.pointsChecked, 84u);
  // Independent: the smallest type II margin over the points bounds the report from above;
  // joint-linear moves between 3 mm apart points can only dip slightly lower.
  double worstPoint = 10.0;
  for (const Stroke& s : job)
    for (const Vec2& p : s.points) {
      const IkResult ik = inverse(kDai, p, WorkingMode::PlusPlus);
      worstPoint = std::min(worstPoint, singularityMargins(kDai, makePose(kDai, ik.angles, p)).typeII);
    }
  EXPECT_LE(r.minTypeIIMarginRad, worstPoint + 1e-12);
  EXPECT_GT(r.minTypeIIMarginRad, worstPoint - radFromDeg(1.0));
  EXPECT_NE(r.summary().find("feasible"), std::string::npos);
}

TEST(Feasibility, OutOfReachPointIsNamedAndTheFixesWork) {
  const MachineProfile pr = daiProfile();
  // Feasible '++' poses on x = 0 end near y = 254 (reach 257): the line pokes out of them.
  std::vector<Stroke> job = square({0.0, 200.0}, 10.0);
  job.push_back(line({0.0, 200.0}, {0.0, 262.0}, 31, 2, 7));
  const FeasibilityReport r = preflight(job, pr, WorkingMode::PlusPlus, {});
  ASSERT_FALSE(r.feasible);
  bool namedReach = false;
  for (const PreflightProblem& p : r.problems)
    if (p.kind == MoveKind::Point && p.status == MoveStatus::CannotClose) {
      namedReach = true;
      EXPECT_EQ(p.layerIndex, 2);
      EXPECT_EQ(p.pathIndex, 7);
      EXPECT_EQ(p.strokeIndex, 4);
      EXPECT_NEAR((p.whereMm - job[4].points[p.pointIndex]).norm(), 0.0, 1e-12);
      EXPECT_GT(p.whereMm.y(), 255.0);
      EXPECT_NE(p.reason.text().find("out of reach"), std::string::npos) << p.reason;
      EXPECT_NE(p.reason.text().find("layer 2 path 7"), std::string::npos) << p.reason;
    }
  EXPECT_TRUE(namedReach);
  const Vec2 anchor = strokeBounds(job)->center();
  ASSERT_TRUE(r.shrinkFactor.has_value());
  EXPECT_LT(*r.shrinkFactor, 1.0);
  EXPECT_TRUE(preflight(shifted(job, *r.shrinkFactor, anchor, anchor), pr, WorkingMode::PlusPlus).feasible);
  ASSERT_TRUE(r.suggestedAnchorMm.has_value());
  EXPECT_TRUE(preflight(shifted(job, 1.0, anchor, *r.suggestedAnchorMm), pr, WorkingMode::PlusPlus).feasible);
  EXPECT_NE(r.summary().find("shrink"), std::string::npos) << r.summary();
}

TEST(Feasibility, JogAcrossTheTypeIILocusIsRefused) {
  const MachineProfile pr = daiProfile();
  // Straight down the middle: the '++' poses flip assembly mode where the floating links align.
  const Stroke down = line({0.0, 200.0}, {0.0, 20.0}, 180);
  std::optional<double> flipY;
  for (const Vec2& p : down.points) {
    const IkResult ik = inverse(kDai, p, WorkingMode::PlusPlus);
    if (ik.ok() && assemblyModeOf(makePose(kDai, ik.angles, p)) != pr.assembly) {
      flipY = p.y();
      break;
    }
  }
  ASSERT_TRUE(flipY.has_value()) << "the line must cross the type II locus";
  PreflightOptions o;
  o.includeHomeTravel = false;
  o.suggestFixes = false;
  const FeasibilityReport r = preflight({down}, pr, WorkingMode::PlusPlus, o);
  ASSERT_FALSE(r.feasible);
  const PreflightProblem& first = r.problems.front();
  EXPECT_EQ(first.status, MoveStatus::NearTypeII) << first.reason;
  EXPECT_GT(first.whereMm.y(), *flipY);  // refused before reaching the locus
  bool assembly = false;
  for (const PreflightProblem& p : r.problems) assembly |= p.status == MoveStatus::AssemblyChange;
  EXPECT_TRUE(assembly);
}

TEST(Feasibility, UnwrapsAcrossPlusMinus180Degrees) {
  MachineProfile pr = daiProfile();
  // Find a short horizontal line whose theta1 ('++') crosses +-180 deg at safe poses.
  std::optional<Stroke> crossing;
  for (double y = 40.0; y < 200.0 && !crossing; y += 5.0)
    for (double x = -200.0; x < -60.0 && !crossing; x += 5.0) {
      const Stroke s = line({x, y}, {x + 10.0, y}, 20);
      bool safe = true, above = false, below = false;
      for (const Vec2& p : s.points) {
        const IkResult ik = inverse(kDai, p, WorkingMode::PlusPlus);
        safe = safe && ik.ok() && checkPose(pr, ik.angles).ok();
        if (!safe) break;
        above |= ik.angles.theta1 > radFromDeg(170.0);
        below |= ik.angles.theta1 < radFromDeg(-170.0);
      }
      if (safe && above && below) crossing = s;
    }
  ASSERT_TRUE(crossing.has_value());
  PreflightOptions o;
  o.includeHomeTravel = false;
  o.suggestFixes = false;
  pr.limits.theta1Min = radFromDeg(90.0);
  pr.limits.theta1Max = radFromDeg(270.0);
  const FeasibilityReport r = preflight({*crossing}, pr, WorkingMode::PlusPlus, o);
  EXPECT_TRUE(r.feasible) << r.summary();
  // Limits that end at 180 deg: the continuous motion must go beyond them.
  pr.limits.theta1Min = radFromDeg(-180.0);
  pr.limits.theta1Max = radFromDeg(180.0);
  const FeasibilityReport limited = preflight({*crossing}, pr, WorkingMode::PlusPlus, o);
  ASSERT_FALSE(limited.feasible);
  EXPECT_EQ(limited.problems.front().status, MoveStatus::BeyondJointLimit);
}

TEST(Feasibility, PointNeedingTheOtherAssemblyModeIsReported) {
  const MachineProfile pr = daiProfile();
  std::optional<Vec2> other;
  for (double y = 10.0; y < 120.0 && !other; y += 2.0) {
    const Vec2 p(0.0, y);
    const IkResult ik = inverse(kDai, p, WorkingMode::PlusPlus);
    if (ik.ok() && assemblyModeOf(makePose(kDai, ik.angles, p)) == AssemblyMode::Minus) other = p;
  }
  ASSERT_TRUE(other.has_value());
  PreflightOptions o;
  o.includeHomeTravel = false;
  o.suggestFixes = false;
  const FeasibilityReport r = preflight({line(*other, *other + Vec2(1, 0), 1)}, pr, WorkingMode::PlusPlus, o);
  ASSERT_FALSE(r.feasible);
  EXPECT_EQ(r.problems.front().status, MoveStatus::AssemblyChange);
  EXPECT_NE(r.problems.front().reason.text().find("assembly mode -"), std::string::npos);
}

TEST(Feasibility, AutoPicksTheFeasibleModeWithTheLargestMargin) {
  const MachineProfile pr = daiProfile();
  auto rng = test::rng();
  std::uniform_real_distribution<double> cx(-120.0, 120.0), cy(-60.0, 240.0), half(5.0, 40.0);
  PreflightOptions o;
  o.includeHomeTravel = false;
  o.suggestFixes = false;
  int chosen = 0, none = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Stroke> job = square({cx(rng), cy(rng)}, half(rng));
    const ModeChoice c = chooseMode(job, pr, o);
    ASSERT_EQ(c.reports.size(), 4u);
    std::optional<WorkingMode> best;
    double bestMargin = -1.0;
    for (WorkingMode m : kAllWorkingModes) {
      const FeasibilityReport r = preflight(job, pr, m, o);
      if (r.feasible && r.minTypeIIMarginRad > bestMargin) bestMargin = r.minTypeIIMarginRad, best = m;
    }
    EXPECT_EQ(c.mode, best);
    if (c.mode) {
      ++chosen;
      EXPECT_TRUE(preflight(job, pr, *c.mode, o).feasible);
    } else {
      ++none;
    }
  }
  EXPECT_GT(chosen, 0);
  EXPECT_GT(none, 0);
}

TEST(Feasibility, HundredThousandPointsAreFast) {
  const MachineProfile pr = daiProfile();
  std::vector<Stroke> job;
  for (int i = 0; i < 1000; ++i) {
    const double y = 150.0 + 0.06 * i;
    job.push_back(line({-40.0, y}, {40.0, y}, 99, 0, i));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const FeasibilityReport r = preflight(job, pr, WorkingMode::PlusPlus, {});
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.feasible) << r.summary();
  EXPECT_EQ(r.pointsChecked, 100000u);
#ifdef NDEBUG  // timing only means something in an optimised build
  EXPECT_LT(s, 1.0);  // loose for a loaded CI machine; the figure is in docs/performance
#else
  (void)s;
#endif
}

// The preflight checks strokes in parallel chunks (of 1024) and merges them in job order: the
// report must name exactly the broken strokes, in order, the same on every run.
TEST(Feasibility, ManyStrokesReportProblemsInJobOrderAndRepeatably) {
  const MachineProfile pr = daiProfile();
  std::vector<Stroke> job;
  std::vector<int> broken;
  std::size_t reachable = 0;
  for (int i = 0; i < 2500; ++i) {
    const double x = -30.0 + 0.024 * i;
    job.push_back(line({x, 160.0}, {x + 5.0, 175.0}, 3, i % 3, i));
    if (i % 600 == 17) {  // pokes out of both legs' reach (more than 270 mm from each motor)
      job.back().points.push_back({0.0, 262.0});
      broken.push_back(i);
    }
    for (const Vec2& p : job.back().points) reachable += inverse(kDai, p, WorkingMode::PlusPlus).ok();
  }
  PreflightOptions o;
  o.maxListedProblems = 1000;
  o.suggestFixes = false;
  const FeasibilityReport r = preflight(job, pr, WorkingMode::PlusPlus, o);
  ASSERT_FALSE(r.feasible);
  EXPECT_EQ(r.pointsChecked, reachable);
  std::vector<int> named;
  for (std::size_t k = 0; k < r.problems.size(); ++k) {
    const PreflightProblem& p = r.problems[k];
    if (k > 0) {
      EXPECT_GE(p.strokeIndex, r.problems[k - 1].strokeIndex);
    }
    if (p.kind == MoveKind::Point && p.status == MoveStatus::CannotClose) {
      named.push_back(p.strokeIndex);
      EXPECT_EQ(p.pathIndex, p.strokeIndex);
      EXPECT_EQ(p.pointIndex, 4);
    }
  }
  EXPECT_EQ(named, broken);
  const FeasibilityReport again = preflight(job, pr, WorkingMode::PlusPlus, o);
  ASSERT_EQ(again.problems.size(), r.problems.size());
  for (std::size_t k = 0; k < r.problems.size(); ++k)
    EXPECT_EQ(again.problems[k].reason, r.problems[k].reason);
  EXPECT_EQ(again.minTypeIIMarginRad, r.minTypeIIMarginRad);
}

}  // namespace
}  // namespace fivebar
