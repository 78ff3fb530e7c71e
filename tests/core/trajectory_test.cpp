// SPDX-License-Identifier: GPL-3.0-or-later
// Trajectory sampling: continuous in time, speeds within the motor limits between samples, the
// pose at each move's end time is its target, p is the FK of q, the pen state follows the tool.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "core/planning/planner.hpp"
#include "core/planning/trajectory.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

PlannedJob smallJob(const MachineProfile& p) {
  Drawing d;
  d.layers.resize(1);
  d.layers[0].paths.push_back({{{0, 0}, {30, 0}, {30, 20}}, false});
  Polyline circle;
  for (int k = 0; k < 48; ++k)
    circle.points.emplace_back(Vec2(15, 10) + 8.0 * Vec2(std::cos(k * kPi / 24), std::sin(k * kPi / 24)));
  circle.closed = true;
  d.layers[0].paths.push_back(circle);
  PlanOptions o;
  o.atMm = Vec2(0, 170);
  const PlanResult r = planJob(d, p, o);
  EXPECT_TRUE(r.ok()) << r.message;
  return r.job;
}

TEST(Trajectory, ContinuousAndWithinMotorSpeed) {
  const MachineProfile p = *preset("maker-plotter");
  const Trajectory tr(smallJob(p), p);
  ASSERT_GT(tr.durationS(), 0.0);
  const double dt = 1e-3;
  TrajectorySample prev = tr.at(0.0);
  EXPECT_NEAR(prev.q.theta1, tr.job().start.theta1, 1e-12);
  for (double t = dt; t <= tr.durationS() + dt; t += dt) {
    const TrajectorySample s = tr.at(t);
    EXPECT_LE(std::abs(s.q.theta1 - prev.q.theta1), p.motors.maxSpeedRadPerS1 * dt * 1.001 + 1e-12);
    EXPECT_LE(std::abs(s.q.theta2 - prev.q.theta2), p.motors.maxSpeedRadPerS2 * dt * 1.001 + 1e-12);
    const FkResult fk = forward(p.geometry, s.q, p.assembly);
    ASSERT_TRUE(fk.ok());
    EXPECT_LT((fk.p - s.p).norm(), 1e-9);
    prev = s;
  }
  const TrajectorySample end = tr.at(tr.durationS() + 10);
  EXPECT_NEAR(end.q.theta1, tr.job().start.theta1, 1e-9);
  EXPECT_NEAR(end.q.theta2, tr.job().start.theta2, 1e-9);
}

TEST(Trajectory, MoveEndsHitTheTargetsAndPenStateFollows) {
  const MachineProfile p = *preset("maker-plotter");
  const Trajectory tr(smallJob(p), p);
  const auto& moves = tr.job().moves;
  for (size_t i = 0; i < moves.size(); ++i) {
    const JobMove& m = moves[i];
    if (!isMotion(m.kind)) continue;
    const TrajectorySample s = tr.at(m.startTimeS + m.durationS);
    EXPECT_NEAR(s.q.theta1, m.target.theta1, 1e-7);
    EXPECT_NEAR(s.q.theta2, m.target.theta2, 1e-7);
    const TrajectorySample mid = tr.at(m.startTimeS + 0.5 * m.durationS);
    EXPECT_EQ(mid.moveIndex, static_cast<int>(i));
    EXPECT_EQ(mid.penDown, m.kind == JobMoveKind::Draw);
  }
}

}  // namespace
}  // namespace fivebar

namespace fivebar {
namespace {

// A drawing of many short strokes (seeded): with a pen servo, a chain per stroke.
Drawing strokes(int count) {
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> x(0, 60), y(0, 40), turn(-1.0, 1.0);
  Drawing d;
  d.layers.resize(1);
  for (int k = 0; k < count; ++k) {
    Polyline line;
    Vec2 at(x(rng), y(rng));
    double heading = 0.0;
    for (int j = 0; j < 6; ++j) {
      line.points.push_back(at);
      heading += turn(rng);
      at += 3.0 * Vec2(std::cos(heading), std::sin(heading));
    }
    d.layers[0].paths.push_back(line);
  }
  return d;
}

// Timing a job chain by chain (what the studio's trajectory does as it is sampled) gives every
// move exactly the timing the whole job's estimate gives it: with a pen servo (a chain per
// stroke), a Z axis and a laser (no pen command synchronises: one chain), on a job large enough
// for the whole-job estimate to time it in two parts on two threads.
TEST(Trajectory, ChainTimingsAreTheWholeJobsTimings) {
  for (const ToolKind tool : {ToolKind::PenServo, ToolKind::ZAxis, ToolKind::Laser}) {
    MachineProfile p = *preset("maker-plotter");
    p.tool.kind = tool;
    PlanOptions o;
    o.atMm = Vec2(-30, 150);
    const PlanResult r = planJob(strokes(tool == ToolKind::PenServo ? 3000 : 300), p, o);
    ASSERT_TRUE(r.ok()) << r.message;
    PlannedJob whole = r.job;
    const std::vector<GrblBlockTiming> expected = estimateJobTime(whole, p);
    ASSERT_EQ(expected.size(), r.job.moves.size());
    if (tool == ToolKind::PenServo) {
      ASSERT_GT(r.job.moves.size(), 20000u);  // the whole-job estimate times it in two parts
    }
    std::size_t chains = 0;
    for (std::size_t i = 0; i < r.job.moves.size();) {
      const TimedChain c = timeChainAround(r.job, p, i);
      ASSERT_EQ(c.begin, i);
      ASSERT_GT(c.end, c.begin);
      for (std::size_t k = c.begin; k < c.end; ++k) {
        const GrblBlockTiming& a = c.timings[k - c.begin];
        const GrblBlockTiming& b = expected[k];
        ASSERT_EQ(a.durationS, b.durationS) << "move " << k;
        ASSERT_EQ(a.entryPerS, b.entryPerS) << "move " << k;
        ASSERT_EQ(a.exitPerS, b.exitPerS) << "move " << k;
        ASSERT_EQ(a.nominalPerS, b.nominalPerS) << "move " << k;
        ASSERT_EQ(a.accelPerS2, b.accelPerS2) << "move " << k;
        ASSERT_EQ(a.lengthUnits, b.lengthUnits) << "move " << k;
      }
      // Any move of the chain finds the same chain.
      const TimedChain again = timeChainAround(r.job, p, (c.begin + c.end) / 2);
      EXPECT_EQ(again.begin, c.begin);
      EXPECT_EQ(again.end, c.end);
      i = c.end;
      ++chains;
    }
    if (tool == ToolKind::PenServo) {
      EXPECT_GT(chains, 3000u);
    } else {
      EXPECT_EQ(chains, 1u);
    }
  }
}

// The studio's trajectory shares the planned job (not copied) and samples each move with the
// whole job's GRBL timing: the pose inside a move is where the trapezoid of that timing puts it.
TEST(Trajectory, SharedJobSamplesWithTheWholeJobsTimings) {
  const MachineProfile p = *preset("maker-plotter");
  const PlanResult r = planJob(strokes(40), p, [] {
    PlanOptions o;
    o.atMm = Vec2(-30, 150);
    return o;
  }());
  ASSERT_TRUE(r.ok()) << r.message;
  auto job = std::make_shared<const PlannedJob>(r.job);
  const Trajectory shared(job, p);
  EXPECT_EQ(&shared.job(), job.get());  // not copied
  PlannedJob whole = r.job;
  const std::vector<GrblBlockTiming> expected = estimateJobTime(whole, p);
  ASSERT_DOUBLE_EQ(shared.durationS(), whole.summary.estimatedTimeS);
  JointAngles before = r.job.start;
  int sampled = 0;
  // Moves in a scattered order, so that chains are left and found again.
  std::vector<std::size_t> order(r.job.moves.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  std::vector<JointAngles> from(r.job.moves.size());
  for (std::size_t i = 0; i < r.job.moves.size(); ++i) {
    from[i] = before;
    if (isMotion(r.job.moves[i].kind)) before = r.job.moves[i].target;
  }
  for (const std::size_t i : order) {
    const JobMove& m = r.job.moves[i];
    if (!isMotion(m.kind) || expected[i].lengthUnits <= 0.0 || m.durationS <= 0.0) continue;
    const double t = m.startTimeS + 0.3 * m.durationS;
    const TrajectorySample s = shared.at(t);
    ASSERT_EQ(s.moveIndex, static_cast<int>(i));
    const double u = distanceAt(expected[i], t - m.startTimeS) / expected[i].lengthUnits;
    EXPECT_NEAR(s.q.theta1, from[i].theta1 + u * (m.target.theta1 - from[i].theta1), 1e-12);
    EXPECT_NEAR(s.q.theta2, from[i].theta2 + u * (m.target.theta2 - from[i].theta2), 1e-12);
    EXPECT_EQ(s.penDown, m.kind == JobMoveKind::Draw);
    ++sampled;
  }
  EXPECT_GT(sampled, 200);
}

}  // namespace
}  // namespace fivebar
