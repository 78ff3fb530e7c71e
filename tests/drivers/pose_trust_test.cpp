// SPDX-License-Identifier: GPL-3.0-or-later
// PoseTrust (issue 23): a position the host does not know is unknown, never assumed. Driven
// with the board's own text through GrblProtocol, the record kept in a temporary state
// directory. Also the board's pen (pen_state.hpp) and the settings that change how it moves.
#include <gtest/gtest.h>

#include <QDir>
#include <QTemporaryDir>
#include <cstdlib>

#include "core/machine/profile.hpp"
#include "drivers/protocol/grbl_protocol.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/protocol/pen_state.hpp"
#include "drivers/protocol/pose_trust.hpp"
#include "drivers/stream/stream_session.hpp"

namespace fivebar::grbl {
namespace {

class PoseTrustTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    previous_ = qgetenv("FIVEBAR_STATE_DIR");
    ::setenv("FIVEBAR_STATE_DIR", dir_.path().toUtf8().constData(), 1);
  }
  void TearDown() override { qputenv("FIVEBAR_STATE_DIR", previous_); }
  QByteArray previous_;

  // One board session: a protocol and the trust listening to it.
  struct Session {
    std::string wire;
    GrblProtocol protocol{[this](std::string_view b) { wire.append(b); }};
    PoseTrust trust;
    explicit Session(const std::string& key) : trust(protocol, key) {}
    void say(const std::string& text) { protocol.receive(text + "\n"); }
    void report(const std::string& state, double x, double y, const std::string& wco = "|WCO:-90.000,-90.000,0.000") {
      say("<" + state + "|MPos:" + std::to_string(x) + "," + std::to_string(y) + ",0.000|FS:0,0" + wco + ">");
    }
  };

  QTemporaryDir dir_;
};

TEST_F(PoseTrustTest, ABoardNeverReferencedFromHereIsUnknownUntilConfirmed) {
  Session s("/dev/ttyUSB0");
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::NotYetRead);
  s.report("Idle", 0.0, 0.0);
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::NotReferenced);
  EXPECT_FALSE(loadBoardRecord("/dev/ttyUSB0").has_value() &&
               loadBoardRecord("/dev/ttyUSB0")->standing == BoardRecord::Standing::AtRest);
  s.trust.confirmed();
  EXPECT_FALSE(s.trust.known()) << "known only from the next report at rest";
  s.report("Idle", 0.0, 0.0);
  EXPECT_TRUE(s.trust.known());
  const auto r = loadBoardRecord("/dev/ttyUSB0");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->standing, BoardRecord::Standing::AtRest);
  EXPECT_NEAR(r->wcoDeg[0], -90.0, 1e-9);
}

TEST_F(PoseTrustTest, APowerCutIsSeenAsAnotherMachinePositionThanTheLastOneAtRest) {
  {
    Session s("board");
    s.report("Idle", 0.0, 0.0);
    s.trust.confirmed();
    s.report("Idle", 0.0, 0.0);
    ASSERT_TRUE(s.trust.known());
    s.trust.aboutToMove();
    EXPECT_EQ(loadBoardRecord("board")->standing, BoardRecord::Standing::Moving);
    s.report("Run", 12.0, -3.0);
    s.report("Idle", 25.5, -7.25);  // the job ended here
    EXPECT_TRUE(s.trust.known());
    EXPECT_EQ(loadBoardRecord("board")->standing, BoardRecord::Standing::AtRest);
    EXPECT_NEAR(loadBoardRecord("board")->machineDeg[0], 25.5, 1e-9);
  }
  {
    // Power back: MPos 0,0, the kept G54 offset: exactly the home pose, and not where the arms are.
    Session s("board");
    s.report("Idle", 0.0, 0.0);
    EXPECT_EQ(s.trust.doubt(), PoseDoubt::PositionChanged);
  }
  {
    // The same board found where it was left: known without asking.
    BoardRecord r;
    r.standing = BoardRecord::Standing::AtRest;
    r.machineDeg = {25.5, -7.25};
    r.wcoDeg = {-90.0, -90.0};
    ASSERT_EQ(saveBoardRecord("board", r), "");
    Session s("board");
    s.report("Idle", 25.5, -7.25);
    EXPECT_TRUE(s.trust.known());
    // Another work offset (someone's G10) is another pose: unknown.
    Session t("board");
    t.report("Idle", 25.5, -7.25, "|WCO:-80.000,-90.000,0.000");
    EXPECT_EQ(t.trust.doubt(), PoseDoubt::PositionChanged);
  }
}

TEST_F(PoseTrustTest, AHostThatLostSightOfAMovingBoardDoesNotTrustIt) {
  {
    Session s("b");
    s.report("Idle", 0.0, 0.0);
    s.trust.confirmed();
    s.report("Idle", 0.0, 0.0);
    s.report("Run", 3.0, 4.0);  // then the host is killed
  }
  Session s("b");
  s.report("Idle", 3.0, 4.0);  // even at the very position it was last seen moving through
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::RunInterrupted);
  Session busy("c");
  busy.report("Jog", 1.0, 1.0);  // moving when the host arrives
  EXPECT_EQ(busy.trust.doubt(), PoseDoubt::RunInterrupted);
}

TEST_F(PoseTrustTest, AResetInMotionLosesThePositionAndAnIdleResetKeepsIt) {
  Session s("d");
  s.report("Idle", 0.0, 0.0);
  s.trust.confirmed();
  s.report("Idle", 0.0, 0.0);
  s.report("Hold:0", 10.0, 10.0);  // the stop sequence: a completed hold, then the reset
  s.say("Grbl 1.1h ['$' for help]");
  s.report("Idle", 10.0, 10.0);
  EXPECT_TRUE(s.trust.known()) << "a reset at rest keeps GRBL's position";
  s.say("Grbl 1.1h ['$' for help]");
  s.report("Idle", 0.0, 0.0);  // the reset button of a board that also lost power
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::PositionChanged);

  Session m("e");
  m.report("Idle", 0.0, 0.0);
  m.trust.confirmed();
  m.report("Idle", 0.0, 0.0);
  m.report("Run", 5.0, 5.0);
  m.say("ALARM:3");
  EXPECT_EQ(m.trust.doubt(), PoseDoubt::ResetInMotion);
  m.say("Grbl 1.1h ['$' for help]");
  m.report("Alarm", 5.0, 5.0);
  EXPECT_FALSE(m.trust.known()) << "the same counters after ALARM:3 prove nothing";
  const auto r = loadBoardRecord("e");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->standing, BoardRecord::Standing::Lost);
  EXPECT_EQ(r->lostBecause, PoseDoubt::ResetInMotion);
  Session later("e");  // the next program hears why
  later.report("Idle", 5.0, 5.0);
  EXPECT_EQ(later.trust.doubt(), PoseDoubt::ResetInMotion);
}

TEST_F(PoseTrustTest, HomingMakesThePositionKnownAndAFailedHomingLosesIt) {
  Session s("f");
  s.report("Alarm", 0.0, 0.0);
  EXPECT_FALSE(s.trust.known());
  ASSERT_TRUE(s.protocol.enqueue("$H").ok());
  s.say("ok");
  s.report("Idle", -1.0, -1.0);
  EXPECT_TRUE(s.trust.known());
  ASSERT_TRUE(s.protocol.enqueue("$H").ok());
  s.say("ALARM:9");
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::HomingFailed);
}

TEST_F(PoseTrustTest, TheWorkOffsetFromDollarHashCompletesTheFirstReport) {
  BoardRecord r;
  r.standing = BoardRecord::Standing::AtRest;
  r.machineDeg = {1.0, 2.0};
  r.wcoDeg = {-90.0, -90.0};
  ASSERT_EQ(saveBoardRecord("g", r), "");
  Session s("g");
  s.report("Idle", 1.0, 2.0, "");  // no WCO: on this report
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::NotYetRead);
  ASSERT_NE(s.protocol.requestParameters(), 0u);
  s.say("[G54:-90.000,-90.000,0.000]");
  s.say("[G92:0.000,0.000,0.000]");
  s.say("ok");
  EXPECT_TRUE(s.trust.known());
}

TEST_F(PoseTrustTest, TheSimulatedMachineKeepsNoRecord) {
  Session s("");
  s.report("Idle", 0.0, 0.0);
  EXPECT_EQ(s.trust.doubt(), PoseDoubt::NotReferenced);
  s.trust.confirmed();
  s.report("Idle", 0.0, 0.0);
  EXPECT_TRUE(s.trust.known());
  EXPECT_FALSE(QDir(dir_.path()).exists(QStringLiteral("boards.json")));
}

TEST(PenState, TheBoardsSpindleStateSaysWhereThePenIs) {
  ToolSettings servo;  // M3 S1000 down, M5 up
  StatusReport r;
  EXPECT_EQ(penFromStatus(servo, r, std::nullopt), BoardPen::Unknown);
  r.spindle = 0.0;
  EXPECT_EQ(penFromStatus(servo, r, std::nullopt), BoardPen::Up);
  r.spindle = 1000.0;
  EXPECT_EQ(penFromStatus(servo, r, std::nullopt), BoardPen::Down);
  ToolSettings lifted = servo;  // M3 S300 up, M3 S1000 down
  lifted.penUpS = 300.0;
  r.spindle = 300.0;
  EXPECT_EQ(penFromStatus(lifted, r, std::nullopt), BoardPen::Up);
  r.spindle = 900.0;
  EXPECT_EQ(penFromStatus(lifted, r, std::nullopt), BoardPen::Down);
  ToolSettings z;
  z.kind = ToolKind::ZAxis;
  EXPECT_EQ(penFromStatus(z, r, 5.0), BoardPen::Up);
  EXPECT_EQ(penFromStatus(z, r, 0.0), BoardPen::Down);
  EXPECT_EQ(penFromStatus(z, r, std::nullopt), BoardPen::Unknown);
}

TEST(MovingSettings, OnlyTheSettingsThatChangeHowTheMachineMovesRefuseAJob) {
  const MachineProfile p = *preset("maker-plotter");
  setup::Settings board = setup::expectedSettings(p);
  EXPECT_TRUE(movingSettingDiffs(board, p).empty());
  board[10] = 1;   // status report mask: not a motion setting
  board[11] = 0.2; // junction deviation: warned elsewhere, not refused
  EXPECT_TRUE(movingSettingDiffs(board, p).empty());
  board[100] = 250.0;
  board[121] = 5.0;
  const auto diffs = movingSettingDiffs(board, p);
  ASSERT_EQ(diffs.size(), 2u);
  EXPECT_EQ(diffs[0].id, 100);
  EXPECT_EQ(diffs[1].id, 121);
  const std::string text = describeSettingDiffs(diffs);
  EXPECT_NE(text.find("$100 (motor 1 steps/deg) is 250 on the board, the profile wants 35.5556"), std::string::npos)
      << text;
}

}  // namespace
}  // namespace fivebar::grbl
