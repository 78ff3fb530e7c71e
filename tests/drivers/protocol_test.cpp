// SPDX-License-Identifier: GPL-3.0-or-later
// GrblProtocol: character counting, one-at-a-time settings, real-time bytes, polling, resets,
// and recorded transcripts replayed through a fake transport.
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <random>

#include "drivers/protocol/grbl_protocol.hpp"
#include "test_support.hpp"

namespace fivebar::grbl {
namespace {

constexpr double kPiTest = 3.14159265358979323846;

struct Recorder : ProtocolListener {
  std::vector<Ack> acks;
  std::vector<StatusReport> reports;
  std::vector<int> alarms;
  std::vector<std::uint64_t> lost;
  int resets = 0;
  int disconnects = 0;
  void onAck(const Ack& a) override { acks.push_back(a); }
  void onStatus(const StatusReport& r) override { reports.push_back(r); }
  void onAlarm(int code, const std::vector<std::uint64_t>& l) override {
    alarms.push_back(code);
    lost.insert(lost.end(), l.begin(), l.end());
  }
  void onReset(const std::string&, const std::vector<std::uint64_t>& l,
               const std::vector<std::uint64_t>&) override {
    ++resets;
    lost.insert(lost.end(), l.begin(), l.end());
  }
  void onDisconnected(const std::string&) override { ++disconnects; }
};

struct Fixture {
  std::string wire;  // everything written
  GrblProtocol p{[this](std::string_view b) { wire.append(b); }};
  Recorder r;
  Fixture() { p.addListener(&r); }
  std::string take() {
    std::string s;
    s.swap(wire);
    return s;
  }
};

TEST(GrblProtocol, NeverMoreThan128UnacknowledgedBytes) {
  Fixture f;
  auto rng = fivebar::test::rng();
  std::uniform_int_distribution<int> len(1, 79);
  std::vector<std::string> lines;
  for (int i = 0; i < 300; ++i) lines.push_back(std::string(size_t(len(rng)), 'G'));
  for (const auto& l : lines) ASSERT_TRUE(f.p.enqueue(l).ok());
  // The board answers one line at a time; the model below recounts what is unacknowledged.
  std::deque<std::string> onBoard;
  size_t answered = 0;
  while (answered < lines.size()) {
    const std::string sent = f.take();
    size_t start = 0;
    for (size_t nl; (nl = sent.find('\n', start)) != std::string::npos; start = nl + 1)
      onBoard.push_back(sent.substr(start, nl - start));
    int bytes = 0;
    for (const auto& l : onBoard) bytes += int(l.size()) + 1;
    ASSERT_LE(bytes, kRxBufferBytes);
    ASSERT_EQ(bytes, f.p.bytesInFlight());
    ASSERT_FALSE(onBoard.empty()) << "stream stalled with lines queued";
    ASSERT_EQ(onBoard.front(), lines[answered]);
    onBoard.pop_front();
    ++answered;
    f.p.receive("ok\r\n");
  }
  EXPECT_EQ(f.r.acks.size(), lines.size());
  EXPECT_TRUE(f.p.idleLink());
}

TEST(GrblProtocol, FillsTheBudgetExactly) {
  Fixture f;
  // 10-character lines cost 11 bytes: 11 of them fit in 128 (121), the 12th does not.
  for (int i = 0; i < 20; ++i) f.p.enqueue("G1X1.00000");
  EXPECT_EQ(f.p.linesInFlight(), 11u);
  EXPECT_EQ(f.p.bytesInFlight(), 121);
  f.p.receive("ok\n");
  EXPECT_EQ(f.p.linesInFlight(), 11u);
  EXPECT_EQ(f.p.bytesInFlight(), 121);
}

TEST(GrblProtocol, RejectsLinesTheBoardCannotTake) {
  Fixture f;
  // GRBL 1.1h keeps 79 characters (its 80-byte buffer holds the terminator); spaces are not
  // stored, so they do not count.
  EXPECT_EQ(f.p.enqueue(std::string(80, 'X')).status, EnqueueStatus::TooLong);
  EXPECT_TRUE(f.p.enqueue(std::string(79, 'X')).ok());
  EXPECT_TRUE(f.p.enqueue("G1 " + std::string(20, ' ') + std::string(77, 'X')).ok());
  EXPECT_EQ(f.p.enqueue("G1 X1 (why?)").status, EnqueueStatus::ForbiddenCharacter);
  EXPECT_EQ(f.p.enqueue("G1\nX1").status, EnqueueStatus::ForbiddenCharacter);
  EXPECT_EQ(f.p.enqueue("   ").status, EnqueueStatus::Empty);
  EXPECT_NE(describe(EnqueueStatus::TooLong).find("79"), std::string::npos);
}

TEST(GrblProtocol, SettingsWritesGoOneAtATime) {
  Fixture f;
  f.p.enqueue("G1X1F100");
  f.p.enqueue("$100=40");
  f.p.enqueue("$101=40");
  f.p.enqueue("G1X2");
  EXPECT_EQ(f.take(), "G1X1F100\n");  // the setting waits for the stream to drain
  f.p.receive("ok\n");
  EXPECT_EQ(f.take(), "$100=40\n");
  f.p.receive("ok\n");
  EXPECT_EQ(f.take(), "$101=40\n");
  f.p.receive("ok\n");
  EXPECT_EQ(f.take(), "G1X2\n");
  EXPECT_TRUE(isExclusiveLine("$H"));
  EXPECT_TRUE(isExclusiveLine("G10 L20 P0 X0 Y0"));
  EXPECT_FALSE(isExclusiveLine("$J=G91X1F100"));
  EXPECT_FALSE(isExclusiveLine("G1X10"));
}

TEST(GrblProtocol, RealtimeBytesBypassTheBudget) {
  Fixture f;
  for (int i = 0; i < 20; ++i) f.p.enqueue("G1X1.00000");
  f.take();
  const int before = f.p.bytesInFlight();
  f.p.sendRealtime(realtime::kFeedHold);
  f.p.sendRealtime(realtime::kJogCancel);
  EXPECT_EQ(f.take(), std::string("!") + char(0x85));
  EXPECT_EQ(f.p.bytesInFlight(), before);
}

TEST(GrblProtocol, PollsAtMostFiveHertzAndNeverTwoOutstanding) {
  Fixture f;
  f.p.setPollInterval(0.01);  // clamped to 0.2 s
  int polls = 0;
  for (double t = 0.0; t < 2.0; t += 0.01) {
    f.p.tick(t);
    const std::string w = f.take();
    polls += int(std::count(w.begin(), w.end(), '?'));
  }
  EXPECT_EQ(polls, 1) << "no report came back, so no second '?'";
  f.p.receive("<Idle|MPos:0.000,0.000,0.000|Bf:15,128|FS:0,0>\n");
  for (double t = 2.0; t < 4.0; t += 0.01) {
    f.p.tick(t);
    const std::string w = f.take();
    if (w.find('?') != std::string::npos) {
      ++polls;
      f.p.receive("<Idle|MPos:0.000,0.000,0.000|Bf:15,128|FS:0,0>\n");
    }
  }
  EXPECT_GE(polls, 10);
  EXPECT_LE(polls, 12);
}

TEST(GrblProtocol, BannerAndAlarmInvalidateEveryCounter) {
  Fixture f;
  for (int i = 0; i < 20; ++i) f.p.enqueue("G1X1.00000");
  EXPECT_GT(f.p.bytesInFlight(), 0);
  f.p.receive("ALARM:2\r\n");
  EXPECT_EQ(f.p.bytesInFlight(), 0);
  EXPECT_EQ(f.r.alarms, std::vector<int>{2});
  EXPECT_EQ(f.r.lost.size(), 11u);
  EXPECT_EQ(f.p.state(), MachineState::Alarm);
  f.p.receive("ok\r\n");  // a stray answer after the alarm releases nothing
  EXPECT_TRUE(f.r.acks.empty());
  f.p.receive("\r\nGrbl 1.1h ['$' for help]\r\n");
  EXPECT_EQ(f.r.resets, 1);
  EXPECT_TRUE(f.p.idleLink());
  EXPECT_EQ(f.p.version(), "1.1h");
}

TEST(GrblProtocol, DisconnectIsHandledOnce) {
  Fixture f;
  f.p.enqueue("G1X1F100");
  f.p.disconnected("port vanished");
  f.p.disconnected("read error");
  EXPECT_EQ(f.r.disconnects, 1);
  EXPECT_TRUE(f.p.idleLink());
  f.take();
  f.p.enqueue("G1X2");
  EXPECT_EQ(f.take(), "") << "nothing is written to a gone link";
}

TEST(GrblProtocol, MotorAnglesComeFromWorkPosition) {
  Fixture f;
  EXPECT_FALSE(f.p.motorAngles());
  f.p.receive("<Idle|MPos:100.000,50.000,0.000|Bf:15,128|FS:0,0|WCO:10.000,-10.000,0.000>\n");
  ASSERT_TRUE(f.p.motorAngles());
  EXPECT_NEAR(f.p.motorAngles()->theta1, 90.0 * kPiTest / 180.0, 1e-12);
  EXPECT_NEAR(f.p.motorAngles()->theta2, 60.0 * kPiTest / 180.0, 1e-12);
  // Later reports without WCO keep using the last one.
  f.p.receive("<Idle|MPos:101.000,50.000,0.000|Bf:15,128|FS:0,0>\n");
  EXPECT_NEAR(f.p.motorAngles()->theta1, 91.0 * kPiTest / 180.0, 1e-12);
}

// A transcript recorded from a GRBL 1.1h board (fragmented as the USB adapter delivered it):
// the answers and reports must come out whole and in order.
TEST(GrblProtocol, RecordedTranscriptReplaysThroughAFakeTransport) {
  Fixture f;
  f.p.enqueue("$$");
  f.p.enqueue("G1X10F600");
  const std::vector<std::string> chunks = {
      "\r\nGrbl 1.1h ['$' for he", "lp]\r\n$0=10\r\n$1=25\r\n$100=35.5", "56\r\nok\r\n",
      "<Idle|MPos:0.000,0.0", "00,0.000|Bf:15,128|FS:0,0|WCO:0.000,0.000,0.000>\r\no", "k\r\n",
      "error:20\r\n", "[MSG:Caution: Unlocked]\r\n"};
  std::vector<ParsedLine> seen;
  struct All : ProtocolListener {
    std::vector<ParsedLine>* out;
    void onLine(const ParsedLine& l) override { out->push_back(l); }
  } all;
  all.out = &seen;
  f.p.addListener(&all);
  for (const auto& c : chunks) f.p.receive(c);
  // The board had just reset: its banner discarded "$$" in flight and the queued G1, so the
  // answers that follow are strays that release nothing.
  ASSERT_GE(seen.size(), 8u);
  EXPECT_EQ(seen[0].kind, LineKind::Banner);
  EXPECT_EQ(seen[1].kind, LineKind::Setting);
  EXPECT_EQ(seen[3].settingId, 100);
  EXPECT_EQ(seen[5].kind, LineKind::Status);
  EXPECT_EQ(seen[7].kind, LineKind::Error);
  EXPECT_EQ(seen.back().kind, LineKind::Message);
  EXPECT_EQ(f.r.reports.size(), 1u);
  EXPECT_TRUE(f.r.acks.empty());
  EXPECT_EQ(f.r.lost.size(), 1u);
  EXPECT_TRUE(f.p.idleLink());
}

}  // namespace
}  // namespace fivebar::grbl
