// Trajectory sampling: continuous in time, speeds within the motor limits between samples, the
// pose at each move's end time is its target, p is the FK of q, the pen state follows the tool.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

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

// The studio's trajectory reuses the planner's own timing (PlanOptions::keepBlockTimings) and
// shares the job: it samples exactly as one that copies the job and times it again.
TEST(Trajectory, PlannerTimingsGiveTheSameTrajectory) {
  const MachineProfile p = *preset("maker-plotter");
  Drawing d;
  d.layers.resize(1);
  d.layers[0].paths.push_back({{{0, 0}, {30, 0}, {30, 20}, {5, 25}}, false});
  PlanOptions o;
  o.atMm = Vec2(0, 170);
  o.keepBlockTimings = true;
  PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.blockTimings.size(), r.job.moves.size());
  const Trajectory copied(r.job, p);
  auto job = std::make_shared<const PlannedJob>(r.job);
  const Trajectory shared(job, r.blockTimings, p);
  EXPECT_EQ(&shared.job(), job.get());  // not copied
  ASSERT_DOUBLE_EQ(shared.durationS(), copied.durationS());
  for (int k = 0; k <= 500; ++k) {
    const double t = copied.durationS() * k / 500.0;
    const TrajectorySample a = copied.at(t), b = shared.at(t);
    EXPECT_EQ(a.moveIndex, b.moveIndex);
    EXPECT_DOUBLE_EQ(a.q.theta1, b.q.theta1);
    EXPECT_DOUBLE_EQ(a.q.theta2, b.q.theta2);
    EXPECT_EQ(a.penDown, b.penDown);
  }
  // A timing list that does not fit the job is refused, not read out of bounds.
  r.blockTimings.pop_back();
  EXPECT_THROW(Trajectory(job, r.blockTimings, p), std::invalid_argument);
}

}  // namespace
}  // namespace fivebar
