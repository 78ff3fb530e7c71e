// SPDX-License-Identifier: GPL-3.0-or-later
// JobRunner on the in-process simulated machine: completion, hold/resume, and every injected
// fault ending in a clean, resumable state whose resume completes the drawing.
#include <gtest/gtest.h>

#include "drivers/stream/job_runner.hpp"
#include "drivers/stream/resume.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using stream::RunState;

struct RunnerFixture {
  MachineProfile p = testProfile();
  Strokes strokes;
  stream::GcodeJob job;
  RunnerFixture() {
    auto rng = fivebar::test::rng();
    strokes = randomStrokes(p, rng, 6, 15, 30.0);
    job = stream::parseJob(jobText(p, strokes, 3000.0), stream::rulesFor(p));
    EXPECT_TRUE(job.issues.empty());
  }
  double tol() const { return 1.01 / p.motors.stepsPerDeg1; }
};

bool runTo(SimLink& link, stream::JobRunner& r, std::initializer_list<RunState> states, double maxS) {
  return link.runUntil([&] {
    r.tick(link.nowS);
    for (RunState s : states)
      if (r.state() == s) return true;
    return false;
  }, maxS);
}

// Resumes `job` on `link` from the runner's snapshot and runs it to the end.
void resumeToEnd(SimLink& link, const RunnerFixture& f, const stream::RunSnapshot& snap) {
  link.runUntil([&] { return link.protocol.motorAngles().has_value(); }, 1.0);
  const auto here = link.protocol.motorAngles();
  ASSERT_TRUE(here);
  const stream::ResumePlan plan = stream::planResume(f.job, snap.lastPenDownPoint, f.p, *here);
  ASSERT_TRUE(plan.ok()) << plan.message;
  stream::JobRunner again(link.protocol, f.job);
  again.start(plan.continueFrom, plan.preamble, link.nowS);
  ASSERT_TRUE(runTo(link, again, {RunState::Finished, RunState::Paused}, 300.0));
  ASSERT_EQ(again.state(), RunState::Finished) << again.problem();
}

TEST(JobRunner, StreamsToCompletion) {
  RunnerFixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, 0.0);
  ASSERT_TRUE(runTo(link, r, {RunState::Finished, RunState::Paused}, 300.0));
  ASSERT_EQ(r.state(), RunState::Finished) << r.problem();
  const auto s = r.snapshot();
  EXPECT_EQ(s.linesAcked, f.job.lines.size());
  EXPECT_EQ(s.lastCompleted, s.lastAcked);
  expectStrokesCover(f.strokes, link.sim.strokes(), f.tol());
}

TEST(JobRunner, ExecutedProgressTrailsAcknowledgedProgress) {
  RunnerFixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  EXPECT_LT(r.snapshot().etaS, 0.0) << "no time line: the ETA is unknown";
  r.setTimeline(stream::timelineOf(f.job, f.p));
  r.start(0, {}, 0.0);
  bool sawGap = false;
  link.runUntil([&] {
    r.tick(link.nowS);
    const auto s = r.snapshot();
    EXPECT_LE(s.linesCompleted, s.linesAcked);
    if (s.linesAcked > s.linesCompleted + 5) sawGap = true;
    if (s.linesCompleted > 10 && r.state() == RunState::Running) {
      EXPECT_GE(s.etaS, 0.0);
    }
    return r.state() == RunState::Finished;
  }, 300.0);
  EXPECT_TRUE(sawGap) << "the planner holds acknowledged lines not yet executed";
}

TEST(JobRunner, HoldAndResume) {
  RunnerFixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, 0.0);
  link.runUntil([] { return false; }, 1.0);
  r.hold();
  ASSERT_TRUE(runTo(link, r, {RunState::Held}, 5.0));
  const auto at = link.sim.machinePosition();
  link.runUntil([] { return false; }, 1.0);
  EXPECT_EQ(link.sim.machinePosition(), at) << "nothing moves while held";
  r.resume();
  ASSERT_TRUE(runTo(link, r, {RunState::Finished}, 300.0));
  expectStrokesCover(f.strokes, link.sim.strokes(), f.tol());
}

TEST(JobRunner, ProgramPauseIsHeldUntilResumed) {
  RunnerFixture f;
  // A pen change in the middle of the job, as the planner writes it between layers.
  std::string text = jobText(f.p, f.strokes, 3000.0);
  const size_t middle = text.find("G0", text.size() / 2);
  ASSERT_NE(middle, std::string::npos);
  text.insert(middle, "M0\n");
  const stream::GcodeJob withPause = stream::parseJob(text, stream::rulesFor(f.p));
  ASSERT_TRUE(withPause.issues.empty());
  for (const bool resumeAtTheBoard : {false, true}) {
    SimLink link(f.p);
    stream::JobRunner r(link.protocol, withPause);
    r.start(0, {}, 0.0);
    ASSERT_TRUE(runTo(link, r, {RunState::Held, RunState::Finished, RunState::Paused}, 300.0));
    ASSERT_EQ(r.state(), RunState::Held) << r.problem();
    const auto at = link.sim.machinePosition();
    link.runUntil([&] { r.tick(link.nowS); return false; }, 2.0);
    EXPECT_EQ(r.state(), RunState::Held);
    EXPECT_EQ(link.sim.machinePosition(), at) << "nothing moves during the pause";
    if (resumeAtTheBoard) link.protocol.sendRealtime(grbl::realtime::kCycleStart);  // its button
    else r.resume();
    ASSERT_TRUE(runTo(link, r, {RunState::Finished, RunState::Paused}, 300.0));
    ASSERT_EQ(r.state(), RunState::Finished) << r.problem();
    expectStrokesCover(f.strokes, link.sim.strokes(), f.tol());
  }
}

TEST(JobRunner, StopLeavesACleanMachineAndResumeCompletes) {
  RunnerFixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, 0.0);
  link.runUntil([] { return false; }, 2.0);
  r.stop(link.nowS);
  ASSERT_TRUE(runTo(link, r, {RunState::Stopped}, 30.0));
  EXPECT_EQ(link.sim.state(), grbl::MachineState::Idle) << "hold before reset keeps the position";
  resumeToEnd(link, f, r.snapshot());
  expectStrokesCover(f.strokes, link.sim.strokes(), f.tol());
}

struct FaultCase {
  sim::FaultKind kind;
  const char* expectInProblem;
};

void PrintTo(const FaultCase& c, std::ostream* os) { *os << "fault kind " << int(c.kind); }

class JobRunnerFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(JobRunnerFault, EndsCleanAndResumeDrawsTheRest) {
  RunnerFixture f;
  const long atLine = long(f.job.lines.size() / 2);
  SimLink link(f.p, {GetParam().kind, atLine});
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, 0.0);
  ASSERT_TRUE(runTo(link, r, {RunState::Paused, RunState::Finished}, 300.0));
  ASSERT_EQ(r.state(), RunState::Paused);
  EXPECT_NE(r.problem().find(GetParam().expectInProblem), std::string::npos) << r.problem();
  r.stop(link.nowS);
  ASSERT_TRUE(runTo(link, r, {RunState::Stopped}, 30.0));
  const stream::RunSnapshot snap = r.snapshot();
  ASSERT_LT(snap.linesCompleted, f.job.lines.size());
  Strokes drawn = link.sim.strokes();
  if (GetParam().kind == sim::FaultKind::DropAfter) {
    EXPECT_TRUE(r.disconnected());
    SimLink fresh(f.p);  // the board after a power cycle
    resumeToEnd(fresh, f, snap);
    drawn.insert(drawn.end(), fresh.sim.strokes().begin(), fresh.sim.strokes().end());
  } else {
    EXPECT_EQ(link.sim.state(), grbl::MachineState::Idle) << "stop unlocks after an alarm";
    resumeToEnd(link, f, snap);
    drawn = link.sim.strokes();
  }
  expectStrokesCover(f.strokes, drawn, f.tol());
}

INSTANTIATE_TEST_SUITE_P(
    Faults, JobRunnerFault,
    ::testing::Values(FaultCase{sim::FaultKind::ResetAfter, "reset"},
                      FaultCase{sim::FaultKind::AlarmAfter, "ALARM:1"},
                      FaultCase{sim::FaultKind::ErrorOn, "error:20"},
                      FaultCase{sim::FaultKind::DropAfter, "Connection lost"}),
    [](const auto& instance) {
      switch (instance.param.kind) {
        case sim::FaultKind::ResetAfter: return std::string("Reset");
        case sim::FaultKind::AlarmAfter: return std::string("Alarm");
        case sim::FaultKind::ErrorOn: return std::string("Error");
        default: return std::string("Drop");
      }
    });

}  // namespace
}  // namespace fivebar::test
