// SPDX-License-Identifier: GPL-3.0-or-later
// JogSettle: when the host may trust the reported position again after jogs, cancels and a new
// reference pose (drivers/jog/jog_settle.hpp).
#include <gtest/gtest.h>

#include "drivers/jog/jog_settle.hpp"

namespace fivebar::test {
namespace {

using grbl::MachineState;
using jog::JogSettle;

constexpr JointAngles kEnd{0.5, 1.5};

TEST(JogSettle, FreshTrackerIsSettled) {
  JogSettle s;
  EXPECT_TRUE(s.settled());
  EXPECT_FALSE(s.blocked());
  EXPECT_FALSE(s.pendingEnd());
}

TEST(JogSettle, AJogEndsOnlyAfterItsAnswersAndTwoQuietReports) {
  JogSettle s;
  s.jogSent({1, 2}, kEnd);
  ASSERT_TRUE(s.pendingEnd());
  EXPECT_DOUBLE_EQ(s.pendingEnd()->theta1, kEnd.theta1);
  EXPECT_FALSE(s.settled());
  EXPECT_FALSE(s.blocked());  // a running jog may be extended: jogs start at its end
  // Idle reports while lines are unanswered do not count.
  s.reported(MachineState::Idle, false);
  s.reported(MachineState::Idle, false);
  EXPECT_FALSE(s.settled());
  EXPECT_EQ(s.answered(1, true), JogSettle::AckAction::None);
  EXPECT_EQ(s.answered(2, true), JogSettle::AckAction::None);
  EXPECT_EQ(s.jogLinesInFlight(), 0u);
  // Jogging reports do not count either.
  s.reported(MachineState::Jog, false);
  EXPECT_FALSE(s.settled());
  s.reported(MachineState::Idle, false);
  EXPECT_FALSE(s.settled()) << "one quiet report may answer a '?' sent before the last ok";
  s.reported(MachineState::Idle, false);
  EXPECT_TRUE(s.settled());
  EXPECT_FALSE(s.pendingEnd());
}

TEST(JogSettle, ARefusedJogLineForgetsThePlannedEnd) {
  JogSettle s;
  s.jogSent({7}, kEnd);
  EXPECT_TRUE(s.isJogLine(7));
  s.answered(7, false);
  EXPECT_FALSE(s.isJogLine(7));
  EXPECT_FALSE(s.pendingEnd());
}

TEST(JogSettle, CancelBlocksUntilSettledAndAsksForASecondCancel) {
  JogSettle s;
  s.jogSent({1, 2, 3, 4}, kEnd);
  s.answered(1, true);
  // 4 was still in the host's queue and is dropped; 2 and 3 are in the board's buffer.
  s.cancelled({4});
  EXPECT_TRUE(s.blocked());
  EXPECT_FALSE(s.pendingEnd());
  EXPECT_FALSE(s.isJogLine(4));
  EXPECT_EQ(s.answered(2, true), JogSettle::AckAction::None);
  // The last buffered line entered the planner after the cancel: cancel it too.
  EXPECT_EQ(s.answered(3, true), JogSettle::AckAction::CancelAgain);
  EXPECT_TRUE(s.blocked());
  s.reported(MachineState::Idle, false);
  s.reported(MachineState::Idle, false);
  EXPECT_FALSE(s.blocked());
  EXPECT_TRUE(s.settled());
}

TEST(JogSettle, CancelWithNothingBufferedNeverAsksAgain) {
  JogSettle s;
  s.jogSent({1}, kEnd);
  s.answered(1, true);
  s.cancelled({});
  EXPECT_EQ(s.answered(1, true), JogSettle::AckAction::None);
  EXPECT_EQ(s.answered(99, true), JogSettle::AckAction::None);
}

TEST(JogSettle, NewReferenceWaitsForAReportWithTheWorkOffset) {
  JogSettle s;
  s.referenceSent(10);
  EXPECT_TRUE(s.blocked());
  // Quiet reports before the answer, or without a WCO after it, do not settle.
  s.reported(MachineState::Idle, true);
  s.reported(MachineState::Idle, true);
  EXPECT_TRUE(s.blocked()) << "a WCO before the G10 answer is the old offset";
  s.answered(10, true);
  s.reported(MachineState::Idle, false);
  s.reported(MachineState::Idle, false);
  EXPECT_TRUE(s.blocked());
  s.reported(MachineState::Idle, true);  // the new offset: the position is known
  EXPECT_TRUE(s.blocked()) << "and one more quiet report";
  s.reported(MachineState::Idle, false);
  EXPECT_FALSE(s.blocked());
}

TEST(JogSettle, RefusedReferenceStopsWaitingForTheOffset) {
  JogSettle s;
  s.referenceSent(10);
  s.answered(10, false);
  s.reported(MachineState::Idle, false);
  s.reported(MachineState::Idle, false);
  EXPECT_TRUE(s.settled());
}

TEST(JogSettle, AlarmOrResetUnblocksAndForgetsLostLines) {
  JogSettle s;
  s.jogSent({1, 2}, kEnd);
  s.cancelled({});
  s.interrupted({1, 2});
  EXPECT_TRUE(s.settled());
  EXPECT_EQ(s.jogLinesInFlight(), 0u);
  EXPECT_EQ(s.answered(2, true), JogSettle::AckAction::None);
  s.referenceSent(3);
  s.interrupted({3});
  EXPECT_TRUE(s.settled());
}

TEST(JogSettle, ClearForgetsEverything) {
  JogSettle s;
  s.jogSent({1}, kEnd);
  s.referenceSent(2);
  s.clear();
  EXPECT_TRUE(s.settled());
  EXPECT_EQ(s.jogLinesInFlight(), 0u);
}

}  // namespace
}  // namespace fivebar::test
