// SPDX-License-Identifier: GPL-3.0-or-later
// Jog, go-to, frame and machine setup planning.
#include <gtest/gtest.h>

#include "core/planning/safety.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/check/machine_setup.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

std::optional<JointAngles> parseJogTarget(const std::string& line) {
  const auto w = gcode::parseWords(line.rfind("$J=", 0) == 0 ? line.substr(3) : line);
  if (!w.ok() || !w.has('X') || !w.has('Y')) return std::nullopt;
  return JointAngles{radFromDeg(*w.get('X')), radFromDeg(*w.get('Y'))};
}

TEST(CartesianJog, SubMovesStayOnTheStraightLineAndAreChecked) {
  const MachineProfile p = testProfile();
  const Vec2 start = forward(p.geometry, p.homeAngles, p.assembly).p;
  for (const Vec2& dir : {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(1, 1), Vec2(-1, -1)}) {
    const jog::JogPlan plan = jog::planCartesianJog(p, p.homeAngles, dir, 20.0, 30.0);
    ASSERT_TRUE(plan.ok()) << plan.reason;
    ASSERT_FALSE(plan.lines.empty());
    const Vec2 u = dir.normalized();
    JointAngles prev = p.homeAngles;
    for (size_t i = 0; i < plan.lines.size(); ++i) {
      ASSERT_EQ(plan.lines[i].rfind("$J=G90X", 0), 0u) << plan.lines[i];
      const auto q = parseJogTarget(plan.lines[i]);
      ASSERT_TRUE(q);
      EXPECT_TRUE(checkJointMove(p, prev, *q).ok()) << plan.lines[i];
      // Dense samples of the joint-linear sub-move lie within 0.05 mm (+ the 1e-3 deg rounding)
      // of the straight line through the start.
      for (double t = 0.0; t <= 1.0; t += 0.1) {
        const FkResult fk = forward(p.geometry, {prev.theta1 + t * (q->theta1 - prev.theta1),
                                                 prev.theta2 + t * (q->theta2 - prev.theta2)}, p.assembly);
        ASSERT_TRUE(fk.ok());
        EXPECT_LT(std::abs(cross(u, fk.p - start)), 0.06) << "line " << i << " t " << t;
      }
      prev = *q;
    }
    const Vec2 end = forward(p.geometry, prev, p.assembly).p;
    if (plan.status == jog::JogStatus::Ok) {
      EXPECT_NEAR((end - start).dot(u), 20.0, 0.01);
    }
  }
}

TEST(CartesianJog, StopsAtTheLastSafePointInsteadOfLeavingTheWorkspace) {
  const MachineProfile p = testProfile();
  const jog::JogPlan plan = jog::planCartesianJog(p, p.homeAngles, Vec2(0, 1), 2000.0, 50.0);
  EXPECT_EQ(plan.status, jog::JogStatus::Clipped);
  EXPECT_LT(plan.lengthMm, 2000.0);
  EXPECT_NE(plan.reason.text().find("stopped after"), std::string::npos) << plan.reason;
  JointAngles prev = p.homeAngles;
  for (const JointAngles& q : plan.targets) {
    EXPECT_TRUE(checkJointMove(p, prev, q).ok());
    prev = q;
  }
}

TEST(MotorJog, IsClippedAtTheJointLimit) {
  const MachineProfile p = testProfile();
  const double toLimitDeg = degFromRad(p.limits.theta1Max - p.homeAngles.theta1);
  const jog::JogPlan plan = jog::planMotorJog(p, p.homeAngles, 1, toLimitDeg + 30.0, 600.0);
  ASSERT_TRUE(plan.ok());
  EXPECT_EQ(plan.status, jog::JogStatus::Clipped);
  ASSERT_EQ(plan.targets.size(), 1u);
  EXPECT_LE(plan.targets[0].theta1, p.limits.theta1Max);
  EXPECT_TRUE(checkJointMove(p, p.homeAngles, plan.targets[0]).ok());
}

TEST(JogCommands, HomeOrReferencePose) {
  MachineProfile p = testProfile();
  p.hasHomingSwitches = false;
  const std::string ref = jog::homeCommand(p);
  EXPECT_EQ(ref.rfind("G10L20P0X", 0), 0u) << ref;
  const auto q = parseJogTarget(ref);
  ASSERT_TRUE(q);
  EXPECT_NEAR(q->theta1, p.homeAngles.theta1, radFromDeg(1e-3));
  p.hasHomingSwitches = true;
  EXPECT_EQ(jog::homeCommand(p), "$H");
}

TEST(Frame, TracesTheHullOfTheStrokesWithCheckedMoves) {
  const MachineProfile p = testProfile();
  auto rng = fivebar::test::rng();
  const Strokes strokes = randomStrokes(p, rng, 5, 10, 25.0);
  const stream::JobRules rules = stream::rulesFor(p);
  const stream::GcodeJob gj = stream::parseJob(jobText(p, strokes, 3000.0), rules);
  for (const auto shape : {jog::FrameShape::ConvexHull, jog::FrameShape::BoundingBox}) {
    const jog::JogPlan plan = jog::planFrame(p, p.homeAngles, gj, rules, shape, 40.0);
    ASSERT_EQ(plan.status, jog::JogStatus::Ok) << plan.reason;
    // Every stroke point lies inside (or on) the traced outline: check against its hull.
    std::vector<Vec2> traced;
    for (const JointAngles& q : plan.targets) traced.push_back(forward(p.geometry, q, p.assembly).p);
    const std::vector<Vec2> hull = jog::convexHull(traced);
    for (const auto& s : strokes)
      for (const auto& pt : s) {
        const Vec2 xy = forward(p.geometry, {radFromDeg(pt[0]), radFromDeg(pt[1])}, p.assembly).p;
        for (size_t i = 0; i < hull.size(); ++i)
          EXPECT_GE(cross(hull[(i + 1) % hull.size()] - hull[i], xy - hull[i]), -0.1);
      }
    JointAngles prev = p.homeAngles;
    for (const JointAngles& q : plan.targets) {
      EXPECT_TRUE(checkJointMove(p, prev, q).ok());
      prev = q;
    }
  }
}

// A pen stays up all along the frame; a laser is lit at a low power along the outline only
// (M4 after the travel, M5 at the end), never at the job's drawing power.
TEST(Frame, PenStaysUpAndALaserTracesAtLowPower) {
  MachineProfile p = testProfile();
  auto rng = fivebar::test::rng();
  const Strokes strokes = randomStrokes(p, rng, 3, 6, 20.0);
  for (const ToolKind kind : {ToolKind::PenServo, ToolKind::Laser}) {
    p.tool.kind = kind;
    p.tool.laserPowerS = 800.0;
    const stream::JobRules rules = stream::rulesFor(p);
    const stream::GcodeJob gj = stream::parseJob(jobText(p, strokes, 3000.0), rules);
    const jog::JogPlan plan = jog::planFrame(p, p.homeAngles, gj, rules, jog::FrameShape::ConvexHull, 40.0);
    ASSERT_EQ(plan.status, jog::JogStatus::Ok) << plan.reason;
    std::vector<std::string> toolLines;
    for (const std::string& l : plan.lines)
      if (l.rfind("M", 0) == 0) toolLines.push_back(l);
    if (kind == ToolKind::PenServo) {
      EXPECT_EQ(toolLines, std::vector<std::string>{"M5"});  // penUpS 0: M5, then only moves
    } else {
      ASSERT_EQ(toolLines.size(), 3u);
      EXPECT_EQ(toolLines[0], "M5");  // the travel
      EXPECT_EQ(toolLines[1], "M4S8");  // 1 % of S800
      EXPECT_EQ(toolLines[2], "M5");
      EXPECT_EQ(plan.lines.back(), "M5");
    }
  }
}

TEST(Frame, ConvexHullOfASquareWithInnerPoints) {
  const auto hull = jog::convexHull({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {0.2, 0.7}});
  EXPECT_EQ(hull.size(), 4u);
}

TEST(MachineSetup, ComparesBacksUpAndWritesOneAtATime) {
  const MachineProfile p = testProfile();
  const setup::Settings wanted = setup::expectedSettings(p);
  ASSERT_TRUE(wanted.count(100));
  EXPECT_NEAR(wanted.at(100), p.motors.stepsPerDeg1, 1e-3);
  SimLink link(p);
  // Detune the board first so there is something to fix.
  link.protocol.enqueue("$100=10");
  link.protocol.enqueue("$121=5");
  link.runUntil([&] { return link.protocol.idleLink(); }, 1.0);
  setup::SettingsSync sync(link.protocol);
  sync.read();
  ASSERT_TRUE(link.runUntil([&] { return sync.state() == setup::SetupState::Done; }, 1.0));
  EXPECT_NEAR(sync.board().at(100), 10.0, 1e-9);
  const auto diffs = setup::compare(sync.board(), wanted);
  std::vector<int> ids;
  for (const auto& d : diffs) ids.push_back(d.id);
  EXPECT_NE(std::find(ids.begin(), ids.end(), 100), ids.end());
  EXPECT_NE(std::find(ids.begin(), ids.end(), 121), ids.end());
  std::string backup;
  link.allSent.clear();
  sync.apply(diffs, [&](const std::string& text) { backup = text; return std::string(); });
  ASSERT_TRUE(link.runUntil([&] { return sync.state() != setup::SetupState::Writing; }, 2.0));
  EXPECT_EQ(sync.state(), setup::SetupState::Done) << sync.problem();
  EXPECT_NE(backup.find("$100=10\n"), std::string::npos) << backup;
  sync.read();
  link.runUntil([&] { return link.protocol.idleLink(); }, 1.0);
  for (const auto& d : setup::compare(sync.board(), wanted))
    ADD_FAILURE() << "$" << d.id << " still differs";
  // A failing backup writes nothing.
  setup::SettingsSync again(link.protocol);
  again.apply({{100, 1.0, 2.0}}, [](const std::string&) { return std::string("disk full"); });
  EXPECT_EQ(again.state(), setup::SetupState::Failed);
  EXPECT_NE(again.problem().find("disk full"), std::string::npos);
}

}  // namespace
}  // namespace fivebar::test
