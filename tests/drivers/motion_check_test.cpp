// SPDX-License-Identifier: GPL-3.0-or-later
// The one motion check (drivers/check/motion_check.hpp): every line that can move the machine read as
// GRBL 1.1h reads it and checked from the machine's pose; whole files checked before a byte.
#include <gtest/gtest.h>

#include "core/planning/safety.hpp"
#include "drivers/check/motion_check.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using motion::Verdict;

motion::BoardPose atHome(const MachineProfile& p) {
  motion::BoardPose pose;
  pose.workDeg = {degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2), 0.0};
  return pose;
}

// A joint target inside the workspace: `mm` from the home point along +x, in the home pose's mode.
std::array<double, 2> targetNearHome(const MachineProfile& p, double mm) {
  const Vec2 home = forward(p.geometry, p.homeAngles, p.assembly).p;
  const IkResult ik = inverse(p.geometry, home + Vec2(mm, 0.0), p.defaultMode);
  EXPECT_TRUE(ik.ok());
  return {degFromRad(unwrapNear(ik.angles.theta1, p.homeAngles.theta1)),
          degFromRad(unwrapNear(ik.angles.theta2, p.homeAngles.theta2))};
}

TEST(MotionCheck, SafeMoveFromTheCurrentPosePasses) {
  const MachineProfile p = testProfile();
  const auto t = targetNearHome(p, 20.0);
  const auto c = motion::checkLine(p, "G0 X" + fmt(t[0]) + " Y" + fmt(t[1]) + " (travel)", atHome(p));
  ASSERT_EQ(c.verdict, Verdict::Motion) << c.reason;
  ASSERT_EQ(c.targetsWork.size(), 1u);
  EXPECT_NEAR(c.targetsWork[0][0], t[0], 1e-4);
  EXPECT_TRUE(checkJointMove(p, p.homeAngles, {radFromDeg(t[0]), radFromDeg(t[1])}).ok());
}

TEST(MotionCheck, UnsafeMovesAreRefusedWithTheReason) {
  const MachineProfile p = testProfile();
  const motion::BoardPose home = atHome(p);
  // Beyond motor 1's joint limit: the same verdict core's check gives.
  const double beyond = degFromRad(p.limits.theta1Max) + 10.0;
  const auto far = motion::checkLine(p, "G1X" + fmt(beyond) + "F600", home);
  EXPECT_EQ(far.verdict, Verdict::Refused);
  const MoveCheck core = checkJointMove(p, {radFromDeg(home.workDeg[0]), radFromDeg(home.workDeg[1])},
                                        {radFromDeg(beyond), radFromDeg(home.workDeg[1])});
  EXPECT_FALSE(core.ok());
  EXPECT_NE(far.reason.text().find(describe(core)), std::string::npos) << far.reason;
  // Relative moves (G91) and jogs are read from the current pose.
  EXPECT_EQ(motion::checkLine(p, "G91 G0 X" + fmt(beyond - home.workDeg[0]), home).verdict, Verdict::Refused);
  EXPECT_EQ(motion::checkLine(p, "$J=G91X" + fmt(beyond - home.workDeg[0]) + "F100", home).verdict,
            Verdict::Refused);
  const auto jog = motion::checkLine(p, "$J=G91X1F100", home);
  ASSERT_EQ(jog.verdict, Verdict::Motion) << jog.reason;
  EXPECT_TRUE(jog.jog);
  EXPECT_NEAR(jog.targetsWork[0][0], home.workDeg[0] + 1.0, 1e-9);
  // G53: machine coordinates (MPos = WPos + WCO).
  motion::BoardPose offset = home;
  offset.wco = {100.0, 0.0, 0.0};
  const auto g53 = motion::interpretLine("G53G0X" + fmt(home.workDeg[0] + 100.0), offset);
  ASSERT_EQ(g53.verdict, Verdict::Motion);
  EXPECT_NEAR(g53.targetsWork[0][0], home.workDeg[0], 1e-4);
}

TEST(MotionCheck, LinesThatCannotBeCheckedAreRefused) {
  const MachineProfile p = testProfile();
  const motion::BoardPose home = atHome(p);
  for (const char* line : {"G2X1Y1I1F100", "G3 X1 Y1 R5", "G10L20P0X0Y0", "G92X0Y0", "G92.1",
                           "G20", "G55", "G38.2X1F10"}) {
    const auto c = motion::checkLine(p, line, home);
    EXPECT_EQ(c.verdict, Verdict::Refused) << line;
    EXPECT_FALSE(c.reason.empty()) << line;
  }
  EXPECT_NE(motion::checkLine(p, "G10L20P0X0Y0", home).reason.text().find("fivebar reference"), std::string::npos);
  // G28 goes to a stored position: refused while it is unknown, checked once known.
  EXPECT_EQ(motion::checkLine(p, "G28", home).verdict, Verdict::Refused);
  motion::BoardPose stored = home;
  stored.g28Machine = {0.0, 0.0, 0.0};
  const auto g28 = motion::interpretLine("G28", stored);
  ASSERT_EQ(g28.verdict, Verdict::Motion);
  EXPECT_EQ(g28.targetsWork.back()[0], 0.0);
}

TEST(MotionCheck, NonMotionLinesPass) {
  const MachineProfile p = testProfile();
  const motion::BoardPose home = atHome(p);
  for (const char* line : {"M3S1000", "G4P0.5", "$$", "$H", "$100=35.5", "F600", "G21 G90 G94", "Z5",
                           "; comment", "(only a comment)"}) {
    const auto c = motion::checkLine(p, line, home);
    EXPECT_EQ(c.verdict, Verdict::Pass) << line << ": " << c.reason;
  }
  EXPECT_TRUE(motion::interpretLine("$H", home).systemCommand);
}

TEST(MotionCheck, FileCheckNamesTheFirstOffendingLine) {
  const MachineProfile p = testProfile();
  auto rng = fivebar::test::rng();
  const Strokes strokes = randomStrokes(p, rng, 3, 6, 25.0);
  const std::string good = jobText(p, strokes, 2000.0);
  const motion::Axes3 start = atHome(p).workDeg;
  const motion::FileCheck ok = motion::checkFile(p, good, start);
  EXPECT_TRUE(ok.ok) << ok.reason;
  EXPECT_GT(ok.motionLines, 0u);
  // An arc and a move beyond the joint limit inserted after the first stroke.
  const size_t lines = size_t(std::count(good.begin(), good.end(), '\n'));
  for (const std::string& bad : std::vector<std::string>{"G2X1Y1I1F100", "G1X" + fmt(degFromRad(p.limits.theta1Max) + 20.0) + "F600"}) {
    const motion::FileCheck c = motion::checkFile(p, good + bad + "\n", start);
    EXPECT_FALSE(c.ok) << bad;
    EXPECT_EQ(c.fileLine, int(lines) + 1) << c.reason;
    EXPECT_NE(c.reason.find("line " + std::to_string(lines + 1)), std::string::npos) << c.reason;
  }
  // System commands do not belong in a job.
  EXPECT_FALSE(motion::checkFile(p, "G90\n$H\n", start).ok);
}

TEST(MotionCheck, JobHeaderGivesProfileAndStartPose) {
  const auto h = motion::readJobHeader("; FiveBar Studio job\n; profile: maker-plotter\n"
                                       "; start pose X151.1460 Y28.8540\nG21 G90 G94\n");
  ASSERT_TRUE(h.profileName);
  EXPECT_EQ(*h.profileName, "maker-plotter");
  ASSERT_TRUE(h.startDeg);
  EXPECT_DOUBLE_EQ((*h.startDeg)[0], 151.146);
  EXPECT_DOUBLE_EQ((*h.startDeg)[1], 28.854);
  EXPECT_FALSE(motion::readJobHeader("G0X1\n").profileName);
}

}  // namespace
}  // namespace fivebar::test
