// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated machine, driven through GrblProtocol with a stepped clock.
#include <gtest/gtest.h>

#include "drivers/stream/gcode_job.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

using grbl::MachineState;

struct LineLog : grbl::ProtocolListener {
  std::vector<grbl::ParsedLine> lines;
  void onLine(const grbl::ParsedLine& l) override { lines.push_back(l); }
  bool saw(grbl::LineKind kind, int code = -1) const {
    for (const auto& l : lines)
      if (l.kind == kind && (code < 0 || l.code == code)) return true;
    return false;
  }
  bool sawText(const std::string& text) const {
    for (const auto& l : lines)
      if (l.text.find(text) != std::string::npos) return true;
    return false;
  }
};

double stepDeg(const MachineProfile& p) { return 1.0 / p.motors.stepsPerDeg1; }

TEST(SimMachine, StreamsAJobAndDrawsExactlyItsStrokes) {
  const MachineProfile p = testProfile();
  auto rng = fivebar::test::rng();
  const Strokes strokes = randomStrokes(p, rng, 4, 12, 30.0);
  const std::string text = jobText(p, strokes, 3000.0);
  const stream::GcodeJob job = stream::parseJob(text, stream::rulesFor(p));
  ASSERT_TRUE(job.issues.empty());
  SimLink link(p);
  for (const auto& l : job.lines) ASSERT_TRUE(link.protocol.enqueue(l.text).ok());
  ASSERT_TRUE(link.runUntil([&] { return link.protocol.idleLink() && link.sim.state() == MachineState::Idle; }, 120.0));
  const auto end = link.sim.workPosition();
  EXPECT_NEAR(end[0], strokes.back().back()[0], stepDeg(p));
  EXPECT_NEAR(end[1], strokes.back().back()[1], stepDeg(p));
  EXPECT_EQ(link.sim.rxOverflowBytes(), 0);
  ASSERT_EQ(link.sim.strokes().size(), strokes.size());
  expectStrokesCover(strokes, link.sim.strokes(), 1.01 * stepDeg(p));
  expectStrokesCover(stream::strokesOf(job, stream::rulesFor(p)), link.sim.strokes(), 1.01 * stepDeg(p));
}

TEST(SimMachine, TrapezoidalTimingOfOneMove) {
  MachineProfile p = testProfile();
  SimLink link(p);
  const double feedDegPerMin = 3000.0, distDeg = 40.0;
  const double v = feedDegPerMin / 60.0;
  const double a = degFromRad(p.motors.maxAccelRadPerS2_1) * std::sqrt(2.0);  // 45 deg: both axes
  const double start1 = degFromRad(p.homeAngles.theta1), start2 = degFromRad(p.homeAngles.theta2);
  const double dx = distDeg / std::sqrt(2.0);
  link.protocol.enqueue("G1X" + fmt(start1 + dx) + "Y" + fmt(start2 - dx) + "F" + fmt(feedDegPerMin));
  link.step(0.001);
  const double t0 = link.nowS;
  ASSERT_TRUE(link.runUntil([&] { return link.sim.state() == MachineState::Idle && link.sim.plannerBlocks() == 0; }, 30.0, 0.001));
  const double expected = distDeg / v + v / a;  // cruise plus the accel/decel ramps
  EXPECT_NEAR(link.nowS - t0, expected, 0.02 * expected + 0.005);
}

TEST(SimMachine, SoftLimitAlarmLocksUntilResetAndUnlock) {
  const MachineProfile p = testProfile();
  sim::SimConfig factoryFresh;  // a factory-fresh board: default settings, no offsets
  factoryFresh.profile = p;
  SimLink link(factoryFresh);
  LineLog log;
  link.protocol.addListener(&log);
  link.protocol.enqueue("$20=1");  // GRBL 1.1h: soft limits need homing enabled
  link.runUntil([&] { return log.saw(grbl::LineKind::Error, 10); }, 1.0);
  ASSERT_TRUE(log.saw(grbl::LineKind::Error, 10));
  for (const char* s : {"$22=1", "$20=1", "$X"}) link.protocol.enqueue(s);
  link.protocol.enqueue("G1X-150F1000");  // inside -$130..0 (200)
  link.protocol.enqueue("G1X-201F1000");  // beyond: ALARM:2 before it moves
  link.runUntil([&] { return log.saw(grbl::LineKind::Alarm); }, 30.0);
  EXPECT_TRUE(log.saw(grbl::LineKind::Alarm, 2));
  EXPECT_TRUE(log.sawText("Reset to continue"));
  const auto answers = [&] {
    return std::count_if(log.lines.begin(), log.lines.end(), [](const grbl::ParsedLine& l) {
      return l.kind == grbl::LineKind::Ok || l.kind == grbl::LineKind::Error;
    });
  };
  const auto answersBefore = answers();
  link.protocol.enqueue("G1X0");  // ignored until the reset
  link.runUntil([] { return false; }, 0.2);
  EXPECT_EQ(answers(), answersBefore);
  link.protocol.sendRealtime(grbl::realtime::kSoftReset);
  link.runUntil([&] { return log.saw(grbl::LineKind::Banner); }, 1.0);
  EXPECT_EQ(link.sim.state(), MachineState::Alarm);
  link.protocol.enqueue("G1X1F100");
  link.runUntil([&] { return log.saw(grbl::LineKind::Error, 9); }, 1.0);
  EXPECT_TRUE(log.saw(grbl::LineKind::Error, 9)) << "G-code is locked in alarm";
  link.protocol.enqueue("$X");
  link.runUntil([&] { return log.sawText("Unlocked"); }, 1.0);
  EXPECT_EQ(link.sim.state(), MachineState::Idle);
}

// GRBL 1.1h limits.c limits_soft_check: a target beyond the travel that comes while a move runs
// holds the feed (a controlled stop, "Hold:1", cycle start ignored), then ALARM:2 with the
// position kept: the machine went on decelerating, stopped short of the move's end, and the reset
// raises no ALARM:3. The line is answered only at the reset.
TEST(SimMachine, ATargetBeyondTheTravelWhileMovingStopsUnderControlThenAlarms) {
  sim::SimConfig factoryFresh;  // default settings: $110 500 deg/min, $120 10 deg/s^2, $130 200
  factoryFresh.profile = testProfile();
  SimLink link(factoryFresh);
  LineLog log;
  link.protocol.addListener(&log);
  for (const char* s : {"$22=1", "$20=1", "$X"}) link.protocol.enqueue(s);
  link.protocol.enqueue("G1X-150F500");
  link.runUntil([] { return false; }, 2.0);  // at full speed (8.3 deg/s after 0.8 s)
  ASSERT_EQ(link.sim.state(), MachineState::Run);
  const auto answers = [&] {
    return std::count_if(log.lines.begin(), log.lines.end(), [](const grbl::ParsedLine& l) {
      return l.kind == grbl::LineKind::Ok || l.kind == grbl::LineKind::Error;
    });
  };
  const auto answersBefore = answers();
  const double atLine = link.sim.workPosition()[0];
  link.protocol.enqueue("G1X-201F500");
  bool sawHoldMoving = false, cycleStartSent = false;
  for (double t = 0.0; t < 10.0 && !log.saw(grbl::LineKind::Alarm); t += 0.002) {
    link.step(0.002);
    if (link.sim.state() == MachineState::Hold && link.protocol.lastStatus().state == MachineState::Hold &&
        link.protocol.lastStatus().subState == 1) {
      sawHoldMoving = true;
      if (!cycleStartSent) link.protocol.sendRealtime(grbl::realtime::kCycleStart);  // ignored
      cycleStartSent = true;
    }
  }
  ASSERT_TRUE(log.saw(grbl::LineKind::Alarm, 2));
  EXPECT_TRUE(sawHoldMoving) << "no Hold:1 while it stopped";
  const double stoppedAt = link.sim.workPosition()[0];
  // v^2 / (2 a) = 8.33^2 / 20 = 3.5 deg of controlled stop, not an instant one.
  EXPECT_LT(stoppedAt, atLine - 2.0);
  EXPECT_GT(stoppedAt, -150.0 + 1.0);  // the first move was not finished
  EXPECT_EQ(answers(), answersBefore);  // the line waits in mc_line
  link.runUntil([] { return false; }, 0.5);
  EXPECT_DOUBLE_EQ(link.sim.workPosition()[0], stoppedAt);  // nothing moves in the alarm
  link.protocol.sendRealtime(grbl::realtime::kSoftReset);
  link.runUntil([&] { return log.saw(grbl::LineKind::Banner); }, 1.0);
  EXPECT_FALSE(log.saw(grbl::LineKind::Alarm, 3)) << "the position was kept";
  EXPECT_EQ(answers(), answersBefore + 1);  // "ok" for the line, at the reset
}

TEST(SimMachine, ResetDuringMotionRaisesAlarm3ButNotAfterACompletedHold) {
  const MachineProfile p = testProfile();
  for (const bool holdFirst : {false, true}) {
    SimLink link(p);
    LineLog log;
    link.protocol.addListener(&log);
    link.protocol.enqueue("G1X" + fmt(degFromRad(p.homeAngles.theta1) + 30.0) + "F600");
    link.runUntil([] { return false; }, 0.3);
    ASSERT_EQ(link.sim.state(), MachineState::Run);
    if (holdFirst) {
      link.protocol.sendRealtime(grbl::realtime::kFeedHold);
      ASSERT_TRUE(link.runUntil([&] { return link.protocol.lastStatus().state == MachineState::Hold &&
                                             link.protocol.lastStatus().subState == 0; }, 3.0));
    }
    link.protocol.sendRealtime(grbl::realtime::kSoftReset);
    link.runUntil([&] { return log.saw(grbl::LineKind::Banner); }, 1.0);
    EXPECT_EQ(log.saw(grbl::LineKind::Alarm, 3), !holdFirst);
    EXPECT_EQ(link.sim.state(), holdFirst ? MachineState::Idle : MachineState::Alarm);
  }
}

TEST(SimMachine, ProgramPauseHoldsAfterTheMovesBeforeItUntilCycleStart) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  const double x0 = degFromRad(p.homeAngles.theta1);
  const std::string first = fmt(x0 + 5.0), second = fmt(x0 + 10.0);
  link.protocol.enqueue("G1X" + first + "F600");
  link.protocol.enqueue("M0");
  link.protocol.enqueue("G1X" + second + "F600");
  const double x1 = std::stod(first), x2 = std::stod(second);
  const double halfStep = 0.5 / p.motors.stepsPerDeg1 + 1e-9;  // positions are whole steps
  // The first move completes, then the machine holds (Hold:0) with the second move waiting.
  ASSERT_TRUE(link.runUntil([&] { return link.sim.state() == MachineState::Hold; }, 5.0));
  EXPECT_NEAR(link.sim.workPosition()[0], x1, halfStep);
  link.runUntil([] { return false; }, 2.0);
  EXPECT_EQ(link.sim.state(), MachineState::Hold);
  EXPECT_NEAR(link.sim.workPosition()[0], x1, halfStep);
  link.protocol.sendRealtime(grbl::realtime::kCycleStart);
  ASSERT_TRUE(link.runUntil([&] { return std::abs(link.sim.workPosition()[0] - x2) < halfStep &&
                                         link.sim.state() == MachineState::Idle; }, 5.0));
}

// GRBL 1.1h (protocol.c, EXEC_FEED_HOLD): a feed hold while Idle (a stream starved for a moment)
// is a completed hold at once, Hold:0; a line sent then waits, unacknowledged, until the cycle
// start (protocol_exec_rt_suspend reads no line), as the real firmware does (grbl-sim).
TEST(SimMachine, FeedHoldWhileIdleIsACompletedHoldAndLinesWaitForCycleStart) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  int oks = 0;
  struct Acks : grbl::ProtocolListener {
    int* oks;
    void onAck(const grbl::Ack& a) override { *oks += a.errorCode == 0; }
  } acks;
  acks.oks = &oks;
  link.protocol.addListener(&acks);
  ASSERT_TRUE(link.runUntil([&] { return link.protocol.lastStatus().state == MachineState::Idle; }, 2.0));
  link.protocol.sendRealtime(grbl::realtime::kFeedHold);
  ASSERT_TRUE(link.runUntil([&] { return link.protocol.lastStatus().state == MachineState::Hold &&
                                         link.protocol.lastStatus().subState == 0; }, 2.0));
  const double x0 = link.sim.workPosition()[0];
  const std::string target = fmt(degFromRad(p.homeAngles.theta1) + 5.0);
  link.protocol.enqueue("G1X" + target + "F600");
  link.runUntil([] { return false; }, 1.0);
  EXPECT_EQ(link.sim.state(), MachineState::Hold);
  EXPECT_EQ(link.sim.workPosition()[0], x0);
  EXPECT_EQ(oks, 0) << "no ok while the hold lasts";
  link.protocol.sendRealtime(grbl::realtime::kCycleStart);
  const double halfStep = 0.5 / p.motors.stepsPerDeg1 + 1e-9;
  ASSERT_TRUE(link.runUntil([&] { return std::abs(link.sim.workPosition()[0] - std::stod(target)) < halfStep &&
                                         link.sim.state() == MachineState::Idle; }, 5.0));
  EXPECT_EQ(oks, 1);
  link.protocol.removeListener(&acks);
}

TEST(SimMachine, BadLinesGetErrorCodes) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  std::vector<int> codes;
  struct Acks : grbl::ProtocolListener {
    std::vector<int>* out;
    void onAck(const grbl::Ack& a) override { out->push_back(a.errorCode); }
  } acks;
  acks.out = &codes;
  link.protocol.addListener(&acks);
  for (const char* line : {"G1X1", "G2X1Y1I1", "G1X1..2F100", "$999=1", "Q5", "$J=X1", "G4"})
    link.protocol.enqueue(line);
  link.runUntil([&] { return codes.size() == 7; }, 2.0);
  // As GRBL 1.1h: G1 and G2 without a feed rate error:22 (an arc is parsed, not refused).
  EXPECT_EQ(codes, (std::vector<int>{22, 22, 2, 3, 20, 22, 28}));
}

TEST(SimMachine, JogMovesAndCancelStopsItShort) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  const double start = link.sim.workPosition()[0];
  link.protocol.enqueue("$J=G91X20F600");
  link.runUntil([] { return false; }, 0.5);
  EXPECT_EQ(link.sim.state(), MachineState::Jog);
  link.protocol.sendRealtime(grbl::realtime::kJogCancel);
  ASSERT_TRUE(link.runUntil([&] { return link.sim.state() == MachineState::Idle; }, 2.0));
  const double moved = link.sim.workPosition()[0] - start;
  EXPECT_GT(moved, 1.0);
  EXPECT_LT(moved, 19.0);
  std::vector<int> codes;
  struct Acks : grbl::ProtocolListener {
    std::vector<int>* out;
    void onAck(const grbl::Ack& a) override { out->push_back(a.errorCode); }
  } acks;
  acks.out = &codes;
  link.protocol.addListener(&acks);
  // Soft limits (-$130..0 in machine coordinates; $20=1 needs $22=1): a jog past MPos 0 is
  // refused, not an alarm.
  for (const char* s : {"$22=1", "$20=1", "$130=300"}) link.protocol.enqueue(s);
  link.protocol.enqueue("$J=G53X10F600");
  link.runUntil([&] { return codes.size() == 4; }, 1.0);
  EXPECT_EQ(codes, (std::vector<int>{0, 0, 0, 15})) << "a jog beyond the soft limits is refused";
  EXPECT_EQ(link.sim.state(), MachineState::Idle);
}

TEST(SimMachine, SettingsReadAndWrite) {
  const MachineProfile p = testProfile();
  SimLink link(p);
  LineLog log;
  link.protocol.addListener(&log);
  link.protocol.enqueue("$$");
  link.protocol.enqueue("$100=50");
  link.protocol.enqueue("$$");
  link.runUntil([&] { return link.protocol.idleLink(); }, 1.0);
  std::vector<double> s100;
  for (const auto& l : log.lines)
    if (l.kind == grbl::LineKind::Setting && l.settingId == 100) s100.push_back(l.settingValue);
  ASSERT_EQ(s100.size(), 2u);
  EXPECT_NEAR(s100[0], p.motors.stepsPerDeg1, 1e-3);
  EXPECT_DOUBLE_EQ(s100[1], 50.0);
}

// The "|WCO:" fields of the status reports in `out`, in order ("" for a report without one).
std::vector<std::string> wcoFieldsOf(const std::string& out) {
  std::vector<std::string> fields;
  for (size_t at = out.find('<'); at != std::string::npos; at = out.find('<', at + 1)) {
    const std::string report = out.substr(at, out.find('>', at) - at);
    const size_t w = report.find("|WCO:");
    fields.push_back(w == std::string::npos
                         ? ""
                         : report.substr(w + 5, report.find('|', w + 5) - w - 5));
  }
  return fields;
}

// Real GRBL 1.1 sends WCO in the first status report after the offset changes (G10 L20 / L2),
// not only on its periodic refresh.
TEST(SimMachine, ChangedWorkOffsetIsInTheNextStatusReport) {
  sim::SimConfig config;
  config.profile = testProfile();
  config.instant = true;
  sim::SimMachine sim(config);
  EXPECT_EQ(sim.takeOutput(), "") << "GRBL sends nothing when the port opens";
  const auto status = [&] {
    sim.receive("?");
    sim.advance(0.001);
    const auto f = wcoFieldsOf(sim.takeOutput());
    EXPECT_EQ(f.size(), 1u);
    return f.empty() ? std::string("?") : f.back();
  };
  // Past the periodic WCO report, so the next one would not carry it by schedule.
  for (int i = 0; i < 3; ++i) status();
  ASSERT_EQ(status(), "");
  sim.receive("G10 L20 P1 X10 Y-5\n");
  sim.advance(0.01);
  const std::string reply = sim.takeOutput();
  ASSERT_NE(reply.find("ok"), std::string::npos) << reply;
  const std::string wco = status();
  ASSERT_FALSE(wco.empty()) << "no WCO right after G10 L20";
  double x = 0, y = 0, z = 0;
  ASSERT_EQ(std::sscanf(wco.c_str(), "%lf,%lf,%lf", &x, &y, &z), 3) << wco;
  // G10 L20: the current machine position (0,0 after power-up) becomes work X10 Y-5, so
  // WCO = MPos - (10, -5).
  EXPECT_NEAR(x, sim.machinePosition()[0] - 10.0, 1e-2) << wco;
  EXPECT_NEAR(y, sim.machinePosition()[1] + 5.0, 1e-2) << wco;
  EXPECT_EQ(sim.machinePosition()[0], 0.0);
  // Unchanged afterwards: back to the periodic schedule (not in the following report).
  EXPECT_EQ(status(), "");
}

TEST(SimMachine, RealSpeedStreamingNeverStarvesThePlannerInAStroke) {
  const MachineProfile p = testProfile();
  auto rng = fivebar::test::rng();
  // One long stroke of short segments (about 0.5 deg each): the planner must stay fed.
  Strokes strokes = randomStrokes(p, rng, 1, 2, 20.0);
  std::vector<Point2> fine;
  const Point2 a = strokes[0][0], b = strokes[0][1];
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    fine.push_back({a[0] + t * (b[0] - a[0]) + 0.3 * std::sin(i * 0.7), a[1] + t * (b[1] - a[1])});
  }
  const std::string text = jobText(p, {fine}, 2400.0);
  const stream::GcodeJob job = stream::parseJob(text, stream::rulesFor(p));
  SimLink link(p);
  size_t next = 0;
  // Host side as a real sender behaves: keep the protocol's queue topped up.
  ASSERT_TRUE(link.runUntil([&] {
    while (next < job.lines.size() && link.protocol.linesQueued() < 4)
      link.protocol.enqueue(job.lines[next++].text);
    return next == job.lines.size() && link.protocol.idleLink() && link.sim.state() == MachineState::Idle;
  }, 120.0, 0.001));
  EXPECT_EQ(link.sim.plannerStarvationsInStroke(), 0);
  EXPECT_EQ(link.sim.strokes().size(), 1u);
}

// A board with homing switches (fivebar-sim --homing-switches): the switches sit at machine 0
// in + direction; $H moves there (Z, then X and Y), answers no status request meanwhile, and
// ends at the pull-off position -$27 on every axis, Idle, then answers ok.
TEST(SimMachine, HomingWithSwitchesEndsAtThePullOffPosition) {
  sim::SimConfig config;  // a factory-fresh board with switches
  config.profile = testProfile();
  config.homingSwitches = true;
  sim::SimMachine m(config);
  std::string out;
  const auto run = [&](double seconds) {
    for (double t = 0; t < seconds; t += 0.01) {
      m.advance(0.01);
      out += m.takeOutput();
    }
  };
  m.receive("$22=1\nG0X-10Y-20\n");  // the firmware's default rates: about 3.5 s
  run(6.0);
  ASSERT_EQ(m.state(), grbl::MachineState::Idle);
  EXPECT_NEAR(m.machinePosition()[1], -20.0, 1e-9);
  out.clear();
  m.receive("$H\n");
  run(0.5);
  EXPECT_EQ(m.state(), grbl::MachineState::Home);
  m.receive("?");
  EXPECT_EQ(m.takeOutput(), "") << "a status request answered while homing";
  run(30.0);
  EXPECT_EQ(out, "ok\r\n");
  EXPECT_EQ(m.state(), grbl::MachineState::Idle);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.machinePosition()[size_t(i)], -1.0, 0.02) << "axis " << i;  // -$27
  // Without $22=1 there is no homing cycle.
  m.receive("$22=0\n$H\n");
  run(0.1);
  EXPECT_NE(out.find("error:5"), std::string::npos) << out;
}

}  // namespace
}  // namespace fivebar::test
