// SPDX-License-Identifier: GPL-3.0-or-later
// Executed progress on a stock board ($10=1: no Bf: in the reports) and the stall watchdog.
#include <gtest/gtest.h>

#include "drivers/stream/job_runner.hpp"
#include "drivers/stream/job_timeline.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/stream/job_progress.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using stream::RunState;

struct Fixture {
  MachineProfile p = testProfile();
  Strokes strokes;
  stream::GcodeJob job;
  Fixture() {
    auto rng = fivebar::test::rng();
    strokes = randomStrokes(p, rng, 6, 15, 30.0);
    job = stream::parseJob(jobText(p, strokes, 3000.0), stream::rulesFor(p));
  }
};

bool drawnNear(const Strokes& drawn, const Point2& q, double tolDeg) {
  for (const auto& s : drawn)
    for (const auto& d : s)
      if (std::hypot(d[0] - q[0], d[1] - q[1]) <= tolDeg) return true;
  return false;
}

TEST(StockBoardProgress, ExecutedLinesEtaAndResumePointWithoutBf) {
  Fixture f;
  SimLink link(f.p);
  link.protocol.enqueue("$10=1");  // the firmware's default: MPos, no Bf:
  ASSERT_TRUE(link.runUntil([&] { return link.protocol.idleLink(); }, 1.0));
  stream::JobRunner r(link.protocol, f.job);
  r.setTimeline(stream::timelineOf(f.job, f.p));
  r.start(0, {}, link.nowS);
  bool sawProgressWhileRunning = false, sawEta = false, sawBf = false;
  const double tol = 1.01 / f.p.motors.stepsPerDeg1;
  link.runUntil([&] {
    r.tick(link.nowS);
    sawBf = sawBf || link.protocol.lastStatus().plannerBlocksFree.has_value();
    const auto s = r.snapshot();
    if (r.state() == RunState::Running && s.linesCompleted > 0) sawProgressWhileRunning = true;
    if (r.state() == RunState::Running && s.etaS >= 0.0) sawEta = true;
    // Never ahead of the machine: the resume point has been drawn already.
    if (s.lastPenDownPoint && f.job.lines[*s.lastPenDownPoint].penDownDuring) {
      EXPECT_TRUE(drawnNear(link.sim.strokes(), f.job.lines[*s.lastPenDownPoint].endDeg, tol))
          << "line " << f.job.lines[*s.lastPenDownPoint].fileLine << " counted before it was drawn";
    }
    return r.state() == RunState::Finished || r.state() == RunState::Paused;
  }, 300.0);
  ASSERT_EQ(r.state(), RunState::Finished) << r.problem();
  EXPECT_FALSE(sawBf) << "$10=1 reports carry no Bf:";
  EXPECT_TRUE(sawProgressWhileRunning);
  EXPECT_TRUE(sawEta);
  EXPECT_EQ(r.snapshot().linesCompleted, f.job.lines.size());
}

TEST(StockBoardProgress, SetupWritesAStatusMaskWithTheBuffer) {
  EXPECT_EQ(setup::expectedSettings(testProfile()).at(10), 3.0);
}

// A board that stays Idle with lines unanswered (the bytes were lost on the wire): the runner
// pauses with a message instead of waiting forever.
TEST(StallWatchdog, IdleBoardWithUnansweredLinesIsReported) {
  Fixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, link.nowS);
  ASSERT_TRUE(link.runUntil([&] { r.tick(link.nowS); return r.snapshot().linesAcked > 20; }, 60.0));
  bool lose = true;
  std::string lost;
  ASSERT_TRUE(link.runUntil([&] {
    if (lose) {
      // Lines (not real-time bytes) vanish on the way: the board never sees them.
      std::string kept;
      for (char c : link.toSim) (grbl::realtime::isRealtime(c) ? kept : lost) += c;
      link.toSim = kept;
    }
    r.tick(link.nowS);
    return r.state() == RunState::Paused || r.state() == RunState::Finished;
  }, 60.0));
  ASSERT_FALSE(lost.empty());
  EXPECT_EQ(r.state(), RunState::Paused);
  EXPECT_NE(r.problem().find("stays Idle"), std::string::npos) << r.problem();
  EXPECT_NE(r.problem().find("resume"), std::string::npos) << r.problem();
}

TEST(StallWatchdog, SilentBoardIsReported) {
  Fixture f;
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.start(0, {}, link.nowS);
  ASSERT_TRUE(link.runUntil([&] { r.tick(link.nowS); return r.snapshot().linesAcked > 20; }, 60.0));
  // The board goes silent: nothing reaches it and nothing comes back.
  double silentFor = 0.0;
  while (r.state() == RunState::Running && silentFor < 30.0) {
    link.toSim.clear();
    link.nowS += 0.05;
    silentFor += 0.05;
    link.protocol.tick(link.nowS);
    r.tick(link.nowS);
  }
  EXPECT_EQ(r.state(), RunState::Paused);
  EXPECT_NE(r.problem().find("stopped answering"), std::string::npos) << r.problem();
  EXPECT_LT(silentFor, stream::JobRunner::kSilentTimeoutS + 1.0);
}

}  // namespace
}  // namespace fivebar::test

// The progress file a resume reads (fuzz/job_progress_fuzz.cpp found these): a version or a count
// of the wrong type or range is refused, naming the file, instead of an exception out of the
// reader (a string version) or an unchecked conversion (1e300 lines).
namespace fivebar::stream {
namespace {

std::string progressText(const std::string& version, const std::string& totalLines) {
  return "{\"version\": " + version + ", \"jobHash\": \"ab\", \"totalLines\": " + totalLines +
         ", \"lastAckedLine\": 3, \"lastCompletedLine\": 2, \"lastPenDownLine\": 1,"
         " \"penDownAnglesDeg\": [1.5, 2.5], \"linesDone\": 2}";
}

TEST(ProgressFile, ReadsAWellFormedRecordAndRefusesBadFieldsNamingTheFile) {
  std::string error;
  const auto good = progressFromJson(progressText("1", "10"), "job.progress", &error);
  ASSERT_TRUE(good.has_value()) << error;
  EXPECT_EQ(good->totalLines, 10);
  EXPECT_EQ(good->linesDone, 2);
  for (const auto& [version, total] : {std::pair<std::string, std::string>{"\"1\"", "10"},
                                       {"1", "1e300"}, {"1", "-4"}, {"1", "2.5"}, {"1", "\"ten\""},
                                       {"1", "18446744073709551615"}}) {
    error.clear();
    EXPECT_FALSE(progressFromJson(progressText(version, total), "job.progress", &error).has_value())
        << version << " " << total;
    EXPECT_EQ(error.rfind("job.progress: ", 0), 0u) << error;
  }
}

}  // namespace
}  // namespace fivebar::stream
