// SPDX-License-Identifier: GPL-3.0-or-later
// The run ETA (JobRunner::snapshot().etaS: the job's time line, JobTimeline::remainingS, under
// the reported overrides), the one `fivebar stream` prints and the studio's Run panel shows:
// monotone while the job runs at the modelled rate, close to the machine time really left, and
// following a feed override.
#include <gtest/gtest.h>

#include <functional>

#include "drivers/stream/job_runner.hpp"
#include "drivers/stream/job_timeline.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using stream::RunState;

struct EtaFixture {
  MachineProfile p = testProfile();
  stream::GcodeJob job;
  stream::JobTimeline timeline;
  EtaFixture() {
    auto rng = fivebar::test::rng();
    job = stream::parseJob(jobText(p, randomStrokes(p, rng, 6, 15, 30.0), 3000.0), stream::rulesFor(p));
    EXPECT_TRUE(job.issues.empty());
    timeline = stream::timelineOf(job, p);
  }
};

struct Sample {
  double tS, etaS;
};

// Runs the job to the end on the simulated board; the ETA every 0.1 s of machine time.
// atS / then: a callback once, at that machine time.
std::vector<Sample> run(const EtaFixture& f, double* endS, double atS = -1.0,
                        const std::function<void(SimLink&)>& then = {}) {
  SimLink link(f.p);
  stream::JobRunner r(link.protocol, f.job);
  r.setTimeline(f.timeline);
  r.start(0, {}, link.nowS);
  std::vector<Sample> out;
  double nextS = 0.0;
  bool called = false;
  link.runUntil([&] {
    r.tick(link.nowS);
    if (then && !called && link.nowS >= atS) { then(link); called = true; }
    if (link.nowS >= nextS && r.state() == RunState::Running) {
      out.push_back({link.nowS, r.snapshot().etaS});
      nextS += 0.1;
    }
    return r.state() == RunState::Finished || r.state() == RunState::Paused;
  }, 600.0);
  EXPECT_EQ(r.state(), RunState::Finished) << r.problem();
  *endS = link.nowS;
  return out;
}

TEST(RunEta, MonotoneAndWithinTenPercentOfTheTimeReallyLeft) {
  EtaFixture f;
  double endS = 0.0;
  const std::vector<Sample> s = run(f, &endS);
  ASSERT_GT(s.size(), 20u);
  const double total = f.timeline.totalS();
  EXPECT_NEAR(total, endS, 0.1 * endS) << "the plan's time model against the simulated board";
  for (std::size_t i = 0; i < s.size(); ++i) {
    ASSERT_GE(s[i].etaS, 0.0);
    if (i > 0) {
      EXPECT_LE(s[i].etaS, s[i - 1].etaS + 1e-9) << "at " << s[i].tS << " s";
    }
    EXPECT_NEAR(s[i].etaS, endS - s[i].tS, 0.1 * endS) << "at " << s[i].tS << " s";
  }
}

TEST(RunEta, FollowsTheReportedFeedOverride) {
  EtaFixture f;
  double plainEndS = 0.0;
  run(f, &plainEndS);
  const double atS = 0.3 * plainEndS;
  double endS = 0.0;
  const std::vector<Sample> s = run(f, &endS, atS, [](SimLink& link) {
    for (int i = 0; i < 5; ++i) {  // 50 %: one byte per real-time check
      link.protocol.sendRealtime(grbl::overrideByte(grbl::OverrideCommand::FeedMinus10));
      link.step(0.002);
    }
  });
  EXPECT_GT(endS, 1.3 * plainEndS) << "the job's feed moves took longer";
  // Once the board reported 50 % (within a second: Ov: follows a change at once), the ETA is
  // the time really left within 10 % of it, plus the line under way: the ETA counts it whole
  // until it is out of the board's planner (the job's longest line at 50 %, about 2 s here).
  const stream::JobTimeline at50 = f.timeline.overridden({50, 100});
  double longestLineS = 0.0;
  for (std::size_t i = 1; i < at50.lineEndS.size(); ++i)
    longestLineS = std::max(longestLineS, at50.lineEndS[i] - at50.lineEndS[i - 1]);
  int checked = 0;
  for (const Sample& x : s) {
    if (x.tS < atS + 1.0 || endS - x.tS < 1.0) continue;
    EXPECT_NEAR(x.etaS, endS - x.tS, 0.1 * (endS - x.tS) + longestLineS) << "at " << x.tS << " s";
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

// The job planned at an override from the start against the simulated board running it at that
// override from the start (GRBL's planner as sim_override_test checks it): within 5 %.
TEST(JobTimeline, OverriddenTimeLineMatchesTheBoardRunningAtTheOverride) {
  EtaFixture f;
  EXPECT_EQ(f.timeline.overridden({}).lineEndS, f.timeline.lineEndS);
  for (const grbl::MotionOverrides ov : {grbl::MotionOverrides{50, 100}, grbl::MotionOverrides{200, 25},
                                         grbl::MotionOverrides{150, 50}}) {
    double endS = 0.0;
    run(f, &endS, 0.0, [&](SimLink& link) {
      std::vector<grbl::OverrideCommand> bytes;
      for (int p = 100; p < ov.feedPct; p += 10) bytes.push_back(grbl::OverrideCommand::FeedPlus10);
      for (int p = 100; p > ov.feedPct; p -= 10) bytes.push_back(grbl::OverrideCommand::FeedMinus10);
      if (ov.rapidPct == 50) bytes.push_back(grbl::OverrideCommand::RapidHalf);
      if (ov.rapidPct == 25) bytes.push_back(grbl::OverrideCommand::RapidQuarter);
      for (grbl::OverrideCommand c : bytes) {
        link.protocol.sendRealtime(grbl::overrideByte(c));
        link.step(0.0005);
      }
    });
    const double modelS = f.timeline.overridden(ov).totalS();
    EXPECT_NEAR(modelS, endS, 0.05 * endS) << ov.feedPct << " % / " << ov.rapidPct << " %";
  }
  // 3000 deg/min is a third of the maker plotter's $110: 200 % is not capped, and the feed
  // moves take less time; a slower feed more.
  EXPECT_LT(f.timeline.overridden({200, 100}).totalS(), f.timeline.totalS());
  EXPECT_GT(f.timeline.overridden({50, 100}).totalS(), f.timeline.totalS());
  EXPECT_GT(f.timeline.overridden({100, 25}).totalS(), f.timeline.totalS());
}

}  // namespace
}  // namespace fivebar::test
