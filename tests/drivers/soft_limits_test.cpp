// SPDX-License-Identifier: GPL-3.0-or-later
// Pre-flight against the board's soft limits (drivers/check/soft_limits.hpp): targets in machine
// coordinates (work + WCO) inside -$13x..0, exactly where the simulated GRBL raises ALARM:2.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "drivers/check/motion_check.hpp"
#include "drivers/check/soft_limits.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

stream::GcodeJob parse(const std::string& text) {
  stream::JobRules rules;
  rules.stepsPerDeg1 = rules.stepsPerDeg2 = 10.0;
  return stream::parseJob(text, rules);
}

const setup::Settings kBoard{{20, 1.0}, {130, 100.0}, {131, 80.0}};

TEST(SoftLimits, OffMeansNoHit) {
  setup::Settings off = kBoard;
  off[20] = 0.0;
  EXPECT_FALSE(setup::firstSoftLimitHit(parse("G0X500Y500\n"), off, {0.0, 0.0}));
  EXPECT_FALSE(setup::firstSoftLimitHit(parse("G0X500Y500\n"), {}, {0.0, 0.0}));
}

TEST(SoftLimits, TargetsAreCheckedInMachineCoordinates) {
  // Work = machine + 50 on X and + 30 on Y: X may go 50 down to -50, Y 30 down to -50.
  const std::array<double, 2> wco{-50.0, -30.0};
  EXPECT_FALSE(setup::firstSoftLimitHit(parse("G0X50Y30\nG1X-50Y-50F600\n"), kBoard, wco));
  const auto high = setup::firstSoftLimitHit(parse("G0X10Y10\nG0X50.5Y10\n"), kBoard, wco);
  ASSERT_TRUE(high);
  EXPECT_EQ(high->fileLine, 2);
  EXPECT_EQ(high->axis, 0);
  EXPECT_NEAR(high->machineDeg, 0.5, 1e-9);
  const auto low = setup::firstSoftLimitHit(parse("G0X10Y10\nM3S1000\nG1X10Y-50.5F600\n"), kBoard, wco);
  ASSERT_TRUE(low);
  EXPECT_EQ(low->fileLine, 3);
  EXPECT_EQ(low->axis, 1);
  EXPECT_NEAR(low->machineDeg, -80.5, 1e-9);
  EXPECT_NE(setup::describe(*low).find("line 3 moves motor 2 to -80.500 deg"), std::string::npos)
      << setup::describe(*low);
  EXPECT_NE(setup::describe(*low).find("$131=80.000"), std::string::npos);
}

// The pre-flight's verdict is the simulated GRBL's: a job it passes runs without an alarm, a job
// it refuses raises ALARM:2 on the board.
TEST(SoftLimits, PreflightAgreesWithTheSimulatedBoard) {
  const MachineProfile profile = testProfile();
  for (const double overshootDeg : {-0.5, 0.5}) {
    sim::SimConfig config;
    config.profile = profile;
    config.setUp = true;  // the profile's settings; MPos 0,0 at power-up, no reference
    SimLink link(config);
    // Soft limits on (homing first), small travel; the board stands at MPos 0,0; the reference
    // pose makes work = machine + 20 deg on both motors.
    for (const char* line : {"$22=1", "$20=1", "$130=40", "$131=40", "$X", "G10L20P0X20Y20"}) {
      ASSERT_TRUE(link.protocol.enqueue(line).ok());
      ASSERT_TRUE(link.runUntil([&] { return link.protocol.linesInFlight() + link.protocol.linesQueued() == 0; }, 5.0));
    }
    // The new offset arrives with a later status report.
    ASSERT_TRUE(link.runUntil([&] {
      const auto& w = link.protocol.workOffset();
      return w && std::abs(w->x() + 20.0) < 1e-3;
    }, 5.0));
    const grbl::Axes wco = *link.protocol.workOffset();
    ASSERT_NEAR(wco.x(), -20.0, 1e-3);
    const std::string last = "G1X" + std::to_string(20.0 + overshootDeg) + "Y15F600";
    const std::string text = "G1X10Y10F600\n" + last + "\n";
    const setup::Settings board{{20, 1.0}, {130, 40.0}, {131, 40.0}};
    const bool refused = setup::firstSoftLimitHit(parse(text), board, {wco.x(), wco.y()}).has_value();
    EXPECT_EQ(refused, overshootDeg > 0.0);
    bool alarm = false;
    for (const std::string& line : {std::string("G1X10Y10F600"), last})
      ASSERT_TRUE(link.protocol.enqueue(line).ok());
    link.runUntil([&] {
      alarm = link.protocol.state() == grbl::MachineState::Alarm;
      return alarm || (link.protocol.linesInFlight() + link.protocol.linesQueued() == 0 &&
                       link.protocol.state() == grbl::MachineState::Idle);
    }, 20.0);
    EXPECT_EQ(alarm, refused) << "overshoot " << overshootDeg;
  }
}

// The one motion check knows the board's soft limits: a line's targets in machine coordinates
// (work + WCO) outside -$13x..0 are refused with the reason, only when $20=1.
TEST(SoftLimits, MotionCheckRefusesTargetsOutsideTheBoardsTravel) {
  motion::BoardPose pose;
  pose.workDeg = {10.0, 10.0, 0.0};
  pose.wco = {-50.0, -30.0, 0.0};
  EXPECT_EQ(motion::checkBoardLines({"G0X50.5Y10"}, pose).passing, 1u) << "soft limits unknown: pass";
  pose.softTravelDeg = std::array<double, 2>{100.0, 80.0};
  const motion::LinesCheck inside = motion::checkBoardLines({"G0X50Y30", "G1X-50Y-50F600"}, pose);
  EXPECT_TRUE(inside.ok(2)) << inside.reason;
  const motion::LinesCheck g0 = motion::checkBoardLines({"G0X20Y10", "G0X50.5Y10", "G0X0Y0"}, pose);
  EXPECT_EQ(g0.passing, 1u);
  EXPECT_NE(g0.reason.text().find("motor 1 to 0.500 deg in machine coordinates"), std::string::npos) << g0.reason;
  EXPECT_NE(g0.reason.text().find("ALARM:2"), std::string::npos) << g0.reason;
  EXPECT_EQ(g0.reason.context(), "MotionCheck");
  const motion::LinesCheck jog = motion::checkBoardLines({"$J=G90X10Y-50.5F100"}, pose);
  EXPECT_EQ(jog.passing, 0u);
  EXPECT_NE(jog.reason.text().find("error:15"), std::string::npos) << jog.reason;
  EXPECT_NE(jog.reason.text().find("$131=80.000"), std::string::npos) << jog.reason;
  // Relative lines are read from the pose, G53 lines in machine coordinates.
  EXPECT_EQ(motion::checkBoardLines({"G91", "G0X40", "G0X0.6"}, pose).passing, 2u);
  EXPECT_EQ(motion::checkBoardLines({"G53G0X0.1Y-5"}, pose).passing, 0u);
  // checkLine refuses the same line for the same reason.
  const MachineProfile profile = testProfile();
  const motion::LineCheck line = motion::checkLine(profile, "G0X50.5Y10", pose);
  EXPECT_FALSE(line.ok());
  EXPECT_EQ(line.reason.text(), g0.reason.text());
}

struct AckLog : grbl::ProtocolListener {
  std::map<std::uint64_t, int> errorOf;  // line id -> error code (0: ok)
  void onAck(const grbl::Ack& ack) override { errorOf[ack.id] = ack.errorCode; }
};

// The check's verdict is the simulated GRBL's, for seeded random targets around the travel box:
// a G1 line the check passes runs, one it refuses raises ALARM:2; a jog it refuses gets error:15.
TEST(SoftLimits, MotionCheckAgreesWithTheSimulatedBoard) {
  const MachineProfile profile = testProfile();
  sim::SimConfig config;
  config.profile = profile;
  config.setUp = true;
  SimLink link(config);
  AckLog acks;
  link.protocol.addListener(&acks);
  const auto idle = [&] {
    return link.runUntil([&] {
      return link.protocol.linesInFlight() + link.protocol.linesQueued() == 0 &&
             link.protocol.state() == grbl::MachineState::Idle;
    }, 10.0);
  };
  for (const char* line : {"$22=1", "$20=1", "$130=40", "$131=40", "$X", "G10L20P0X20Y20"})
    ASSERT_TRUE(link.protocol.enqueue(line).ok());
  ASSERT_TRUE(idle());
  ASSERT_NE(link.protocol.requestSettings(), 0u);
  ASSERT_TRUE(idle());
  // The new offset arrives with a later status report.
  ASSERT_TRUE(link.runUntil([&] {
    const auto& w = link.protocol.workOffset();
    return w && std::abs(w->x() + 20.0) < 1e-3 && std::abs(w->y() + 20.0) < 1e-3;
  }, 5.0));
  std::mt19937 rng(20261202u);  // seed printed on failure
  std::uniform_real_distribution<double> near(-2.0, 2.0);
  int refusedCount = 0;
  for (int i = 0; i < 12; ++i) {
    const auto pose = motion::boardPoseOf(link.protocol);
    ASSERT_TRUE(pose && pose->softTravelDeg) << "the protocol saw $20=1 and $130/$131";
    // Around the box's corners in work coordinates: X in 20-40..20, Y likewise.
    const double x = (i % 2 ? 20.0 : -20.0) + near(rng), y = (i % 3 ? 20.0 : -20.0) + near(rng);
    const bool jog = i % 4 == 3;
    char line[96];
    std::snprintf(line, sizeof line, jog ? "$J=G90X%.3fY%.3fF3000" : "G1X%.3fY%.3fF3000", x, y);
    const bool refused = !motion::checkBoardLines({line}, *pose).ok(1);
    refusedCount += refused;
    bool alarm = false;
    const auto id = link.protocol.enqueue(line);
    ASSERT_TRUE(id.ok());
    link.runUntil([&] {
      alarm = link.protocol.state() == grbl::MachineState::Alarm;
      return alarm || (link.protocol.linesInFlight() + link.protocol.linesQueued() == 0 &&
                       link.protocol.state() == grbl::MachineState::Idle);
    }, 20.0);
    // A status report or two later: the move ran to its end, or the alarm came.
    link.runUntil([&] { return link.protocol.state() == grbl::MachineState::Alarm; }, 0.6);
    alarm = link.protocol.state() == grbl::MachineState::Alarm;
    if (!alarm) {
      ASSERT_TRUE(idle()) << line;
    }
    if (jog) {
      // GRBL answers a jog beyond the travel with error:15 and moves nothing.
      EXPECT_FALSE(alarm) << line << " seed 20261202";
      ASSERT_TRUE(acks.errorOf.count(id.id)) << line;
      EXPECT_EQ(acks.errorOf[id.id] == 15, refused) << line << " seed 20261202";
    } else {
      EXPECT_EQ(alarm, refused) << line << " seed 20261202";
    }
    if (alarm) {  // ALARM:2: reset, unlock (the position is kept)
      link.protocol.sendRealtime(grbl::realtime::kSoftReset);
      link.runUntil([&] { return false; }, 1.0);
      ASSERT_TRUE(link.protocol.enqueue("$X").ok());
      ASSERT_TRUE(idle());
    }
  }
  EXPECT_GT(refusedCount, 2);
  EXPECT_LT(refusedCount, 10);
  link.protocol.removeListener(&acks);
}

}  // namespace
}  // namespace fivebar::test
