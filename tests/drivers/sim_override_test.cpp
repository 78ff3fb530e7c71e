// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated machine's feed and rapid overrides, as GRBL 1.1h applies them (protocol.c,
// planner.c, report.c; drivers/protocol/overrides.hpp): the reported Ov: values, the limits, and
// the timing of overridden moves (capped at $110/$111).
#include <gtest/gtest.h>

#include "drivers/check/machine_setup.hpp"
#include "drivers/protocol/overrides.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using grbl::MachineState;
using grbl::OverrideCommand;

void send(SimLink& link, OverrideCommand c, int times = 1) {
  for (int i = 0; i < times; ++i) {
    link.protocol.sendRealtime(grbl::overrideByte(c));
    link.step(0.01);  // one byte per real-time check
  }
}

// Waits for the next report with an Ov: field (the one after a change carries it).
grbl::MotionOverrides reported(SimLink& link) {
  struct Ov : grbl::ProtocolListener {
    std::optional<std::array<int, 3>> last;
    void onStatus(const grbl::StatusReport& r) override { if (r.overrides) last = r.overrides; }
  } ov;
  link.protocol.addListener(&ov);
  link.runUntil([&] { return ov.last.has_value(); }, 5.0, 0.01);
  link.protocol.removeListener(&ov);
  EXPECT_TRUE(ov.last.has_value());
  if (!ov.last) return {};
  EXPECT_EQ((*ov.last)[2], 100) << "spindle override untouched";
  return {(*ov.last)[0], (*ov.last)[1]};
}

TEST(OverrideFlags, ExecuteAsProtocolCDoes) {
  grbl::OverrideFlags f;
  f.add(OverrideCommand::FeedPlus10);
  f.add(OverrideCommand::FeedPlus10);  // one flag: counts once
  f.add(OverrideCommand::FeedMinus1);
  EXPECT_EQ(f.applyTo({}), (grbl::MotionOverrides{109, 100}));
  f.clear();
  f.add(OverrideCommand::FeedReset);
  f.add(OverrideCommand::FeedPlus1);  // reset first, then the increments
  EXPECT_EQ(f.applyTo({150, 25}), (grbl::MotionOverrides{101, 25}));
  f.clear();
  f.add(OverrideCommand::FeedMinus10);
  EXPECT_EQ(f.applyTo({10, 100}), (grbl::MotionOverrides{10, 100})) << "clamped at 10 %";
  f.clear();
  f.add(OverrideCommand::FeedPlus10);
  EXPECT_EQ(f.applyTo({195, 100}), (grbl::MotionOverrides{200, 100})) << "clamped at 200 %";
  f.clear();
  f.add(OverrideCommand::RapidHalf);
  f.add(OverrideCommand::RapidQuarter);  // low is executed last
  EXPECT_EQ(f.applyTo({}), (grbl::MotionOverrides{100, 25}));
  for (int b = 0x90; b <= 0x97; ++b)
    EXPECT_EQ(grbl::overrideByte(*grbl::overrideCommandOf(char(b))), char(b));
  EXPECT_FALSE(grbl::overrideCommandOf(char(0x98)).has_value());
  EXPECT_FALSE(grbl::overrideCommandOf(char(0x99)).has_value()) << "spindle overrides are not motion overrides";
}

TEST(SimOverrides, ReportedValuesFollowTheBytesWithinTheFirmwareLimits) {
  SimLink link(testProfile());
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{100, 100}));
  send(link, OverrideCommand::FeedPlus10, 3);
  send(link, OverrideCommand::FeedMinus1);
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{129, 100}));
  EXPECT_EQ(link.protocol.reportedOverrides(), (grbl::MotionOverrides{129, 100}));
  send(link, OverrideCommand::FeedPlus10, 12);
  EXPECT_EQ(reported(link).feedPct, 200);
  send(link, OverrideCommand::FeedMinus10, 25);
  EXPECT_EQ(reported(link).feedPct, 10);
  send(link, OverrideCommand::FeedReset);
  send(link, OverrideCommand::RapidQuarter);
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{100, 25}));
  send(link, OverrideCommand::RapidHalf);
  EXPECT_EQ(reported(link).rapidPct, 50);
  send(link, OverrideCommand::RapidFull);
  EXPECT_EQ(reported(link).rapidPct, 100);
}

TEST(SimOverrides, TheSameByteTwiceInOneChunkCountsOnce) {
  SimLink link(testProfile());
  reported(link);
  link.protocol.sendRealtime(grbl::overrideByte(OverrideCommand::FeedPlus10));
  link.protocol.sendRealtime(grbl::overrideByte(OverrideCommand::FeedPlus10));
  link.step(0.01);
  EXPECT_EQ(reported(link).feedPct, 110);
}

TEST(SimOverrides, AResetAndProgramEndRestoreOneHundredPercent) {
  SimLink link(testProfile());
  send(link, OverrideCommand::FeedMinus10, 2);
  send(link, OverrideCommand::RapidHalf);
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{80, 50}));
  link.protocol.enqueue("M2");
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{100, 100}));
  send(link, OverrideCommand::FeedPlus10);
  EXPECT_EQ(reported(link).feedPct, 110);
  link.protocol.sendRealtime(grbl::realtime::kSoftReset);
  link.runUntil([&] { return !link.protocol.reportedOverrides().has_value(); }, 2.0);
  EXPECT_FALSE(link.protocol.reportedOverrides().has_value()) << "unknown after the banner";
  EXPECT_EQ(reported(link), (grbl::MotionOverrides{100, 100}));
}

// Machine time of one straight move of distDeg on both axes (45 deg in the joint plane), with
// the overrides sent before it.
double moveTimeS(const std::string& word, double distDeg, double feedDegPerMin,
                 std::vector<OverrideCommand> before) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  for (OverrideCommand c : before) send(link, c);
  const auto at = link.sim.workPosition();
  const double d = distDeg / std::sqrt(2.0);
  link.protocol.enqueue(word + "X" + fmt(at[0] + d) + "Y" + fmt(at[1] - d) +
                        (feedDegPerMin > 0 ? "F" + fmt(feedDegPerMin) : std::string()));
  link.step(0.001);
  const double t0 = link.nowS;
  EXPECT_TRUE(link.runUntil([&] { return link.sim.state() == MachineState::Idle && link.sim.plannerBlocks() == 0; },
                            60.0, 0.001));
  return link.nowS - t0;
}

TEST(SimOverrides, FeedOverrideScalesG1UpToTheMaximumRate) {
  const MachineProfile p = testProfile();
  const double maxRateDegPerMin = setup::expectedSettings(p).at(110);
  const double a = degFromRad(p.motors.maxAccelRadPerS2_1) * std::sqrt(2.0);
  const double dist = 60.0;
  // A trapezoid of cruise speed v (deg/s along the move).
  const auto trapezoidS = [&](double v) { return dist / v + v / a; };
  const double feed = 0.25 * maxRateDegPerMin * std::sqrt(2.0);  // a quarter of the axes' max rate
  const double v = feed / 60.0;
  EXPECT_NEAR(moveTimeS("G1", dist, feed, {}), trapezoidS(v), 0.02 * trapezoidS(v));
  const double half = moveTimeS("G1", dist, feed, {OverrideCommand::FeedMinus10, OverrideCommand::FeedMinus10,
                                                  OverrideCommand::FeedMinus10, OverrideCommand::FeedMinus10,
                                                  OverrideCommand::FeedMinus10});
  EXPECT_NEAR(half, trapezoidS(0.5 * v), 0.02 * trapezoidS(0.5 * v));
  // 200 % of a quarter of the max rate: half the max rate; 200 % of 0.8: capped at 1.0.
  std::vector<OverrideCommand> plus100(10, OverrideCommand::FeedPlus10);
  EXPECT_NEAR(moveTimeS("G1", dist, feed, plus100), trapezoidS(2.0 * v), 0.02 * trapezoidS(2.0 * v));
  const double vMax = maxRateDegPerMin / 60.0 * std::sqrt(2.0);  // both axes at $110
  EXPECT_NEAR(moveTimeS("G1", dist, 0.8 * vMax * 60.0, plus100), trapezoidS(vMax), 0.02 * trapezoidS(vMax))
      << "an overridden feed never exceeds $110/$111";
  // G0 is not scaled by the feed override, only by the rapid override.
  EXPECT_NEAR(moveTimeS("G0", dist, 0.0, plus100), trapezoidS(vMax), 0.02 * trapezoidS(vMax));
  EXPECT_NEAR(moveTimeS("G0", dist, 0.0, {OverrideCommand::RapidQuarter}), trapezoidS(0.25 * vMax),
              0.02 * trapezoidS(0.25 * vMax));
  EXPECT_NEAR(moveTimeS("G0", dist, 0.0, {OverrideCommand::RapidHalf}), trapezoidS(0.5 * vMax),
              0.02 * trapezoidS(0.5 * vMax));
}

TEST(SimOverrides, JogsIgnoreTheFeedOverride) {
  const double plain = moveTimeS("$J=G90", 20.0, 600.0, {});
  const double overridden = moveTimeS("$J=G90", 20.0, 600.0, {OverrideCommand::FeedMinus10, OverrideCommand::FeedMinus10});
  EXPECT_NEAR(overridden, plain, 0.01 * plain);
}

TEST(SimOverrides, ASlowerFeedMidMoveDeceleratesAtTheAcceleration) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  const double a = degFromRad(p.motors.maxAccelRadPerS2_1);  // per axis; the move is on X only
  const auto at = link.sim.workPosition();
  link.protocol.enqueue("G1X" + fmt(at[0] + 80.0) + "F3000");
  link.runUntil([&] { return link.sim.state() == MachineState::Run; }, 1.0, 0.001);
  link.runUntil([] { return false; }, 0.8, 0.001);  // cruising at 50 deg/s
  constexpr double dtS = 0.001;
  double lastX = link.sim.workPosition()[0], lastV = -1.0;
  bool reached = false;
  for (int i = 0; i < 300 && !reached; ++i) {
    if (i < 5) link.protocol.sendRealtime(grbl::overrideByte(OverrideCommand::FeedMinus10));  // to 50 %
    link.step(dtS);
    const double x = link.sim.workPosition()[0];
    const double v = (x - lastX) / dtS;
    if (lastV >= 0.0) {
      EXPECT_GE(v, lastV - a * dtS - 0.5) << "no jump in speed at step " << i;
    }
    lastX = x;
    lastV = v;
    reached = i > 5 && std::abs(v - 25.0) < 0.2;
  }
  EXPECT_TRUE(reached) << "at " << lastV << " deg/s";
  EXPECT_EQ(link.sim.overrides(), (grbl::MotionOverrides{50, 100}));
}

}  // namespace
}  // namespace fivebar::test
