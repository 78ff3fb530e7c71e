// Pre-flight against the board's soft limits (drivers/soft_limits.hpp): targets in machine
// coordinates (work + WCO) inside -$13x..0, exactly where the simulated GRBL raises ALARM:2.
#include <gtest/gtest.h>

#include "drivers/soft_limits.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

job::GcodeJob parse(const std::string& text) {
  job::JobRules rules;
  rules.stepsPerDeg1 = rules.stepsPerDeg2 = 10.0;
  return job::parseJob(text, rules);
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

}  // namespace
}  // namespace fivebar::test
