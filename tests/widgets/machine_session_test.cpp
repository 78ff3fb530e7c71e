// The machine session and its panels on the simulated machine: connection and status, the
// alarm banner and its way out, error answers, and the console's history.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>

#include "core/kinematics/units.hpp"
#include "drivers/grbl_codes.hpp"
#include "machine_test_support.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/machine_banner.hpp"
#include "widgets/machine/machine_panel.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

void pressKey(QWidget* w, int key) {
  QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier);
  QCoreApplication::sendEvent(w, &press);
}

TEST(MachinePanel, ConnectsTheSimulatedMachineAndShowsItsStatus) {
  MachineRig rig;
  widgets::MachinePanel panel(rig.session);
  EXPECT_EQ(panel.portBox()->currentIndex(), 0);  // the simulated machine comes first
  panel.connectButton()->click();
  // "Connected" only once the board answered with a status report.
  EXPECT_TRUE(rig.session.isConnecting());
  EXPECT_TRUE(panel.linkLabel()->text().contains(QStringLiteral("waiting")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 5000));
  EXPECT_TRUE(panel.linkLabel()->text().startsWith(QStringLiteral("Connected")));
  EXPECT_FALSE(panel.connectButton()->isEnabled());
  EXPECT_TRUE(panel.disconnectButton()->isEnabled());
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_EQ(panel.stateLabel()->text(), widgets::stateName(grbl::MachineState::Idle));
  // The simulator starts at MPos 0,0 like a board after power-up; once its reference is set the
  // reported pose is the profile's home pose, within a step.
  const JointAngles raw = *rig.session.motorAngles();
  EXPECT_EQ(raw.theta1, 0.0);
  ASSERT_TRUE(rig.setReference());
  const JointAngles q = *rig.session.motorAngles();
  const MachineProfile& p = rig.doc.profile();
  EXPECT_NEAR(degFromRad(q.theta1), degFromRad(p.homeAngles.theta1), 1.0 / p.motors.stepsPerDeg1);
  EXPECT_NEAR(degFromRad(q.theta2), degFromRad(p.homeAngles.theta2), 1.0 / p.motors.stepsPerDeg2);
  panel.disconnectButton()->click();
  EXPECT_FALSE(rig.session.isConnected());
  EXPECT_TRUE(panel.connectButton()->isEnabled());
}

TEST(MachineBanner, AlarmShowsTheExplanationAndResetThenUnlockClearsIt) {
  MachineRig rig;
  // The alarm (ALARM:1) fires on the board's third line: the first two are the $I and $$ the
  // studio sends on connect to compare the settings with the profile.
  ASSERT_TRUE(rig.connect(4.0, sim::Fault{sim::FaultKind::AlarmAfter, 2}));
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));
  widgets::MachineBanner banner(rig.session);
  EXPECT_TRUE(banner.isHidden());
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G4P0.01")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().kind == widgets::MachineProblem::Kind::Alarm; }, 5000));
  EXPECT_FALSE(banner.isHidden());
  const grbl::CodeInfo* info = grbl::findAlarm(1);
  ASSERT_NE(info, nullptr);
  EXPECT_TRUE(banner.message()->text().contains(QString::fromUtf8(info->name.data(), qsizetype(info->name.size()))))
      << banner.message()->text().toStdString();
  // The board demands a reset first: Unlock is offered only after it.
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().needsReset; }, 3000));
  EXPECT_FALSE(banner.unlockButton()->isEnabled());
  banner.resetButton()->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.problem().needsReset; }, 3000));
  EXPECT_TRUE(banner.unlockButton()->isEnabled());
  EXPECT_FALSE(banner.isHidden());  // still locked after the reset
  banner.unlockButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.state() == grbl::MachineState::Idle; }, 5000));
  EXPECT_TRUE(banner.isHidden());
  EXPECT_EQ(rig.session.problem().kind, widgets::MachineProblem::Kind::None);
}

TEST(MachineBanner, RejectedLineShowsTheErrorTextAndCanBeDismissed) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::MachineBanner banner(rig.session);
  // A move without a feed rate: GRBL answers error:22 and nothing moves.
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G1X150")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().kind == widgets::MachineProblem::Kind::Error; }, 5000));
  EXPECT_EQ(rig.session.problem().code, 22);
  EXPECT_TRUE(banner.message()->text().contains(QString::fromStdString(grbl::describeError(22))));
  EXPECT_FALSE(banner.isHidden());
  banner.dismissButton()->click();
  EXPECT_TRUE(banner.isHidden());
}

TEST(ConsolePanel, ShowsSentAndReceivedLinesAndWalksTheHistory) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::ConsolePanel console(rig.session);
  QLineEdit* input = console.input();
  input->setText(QStringLiteral("$I"));
  pressKey(input, Qt::Key_Return);
  ASSERT_TRUE(waitUntil([&] { return console.log()->toPlainText().contains(QStringLiteral("1.1h.20190830")); }, 5000));
  EXPECT_TRUE(console.log()->toPlainText().contains(QStringLiteral("> $I")));
  input->setText(QStringLiteral("$G"));
  pressKey(input, Qt::Key_Return);
  ASSERT_TRUE(waitUntil([&] { return console.log()->toPlainText().contains(QStringLiteral("G54")); }, 5000));
  EXPECT_TRUE(input->text().isEmpty());
  input->setText(QStringLiteral("draft"));
  pressKey(input, Qt::Key_Up);
  EXPECT_EQ(input->text(), QStringLiteral("$G"));
  pressKey(input, Qt::Key_Up);
  EXPECT_EQ(input->text(), QStringLiteral("$I"));
  pressKey(input, Qt::Key_Up);  // stays at the oldest
  EXPECT_EQ(input->text(), QStringLiteral("$I"));
  pressKey(input, Qt::Key_Down);
  EXPECT_EQ(input->text(), QStringLiteral("$G"));
  pressKey(input, Qt::Key_Down);
  EXPECT_EQ(input->text(), QStringLiteral("draft"));
}

TEST(MachineSession, SetReferencePoseMakesTheCurrentPoseTheHomePose) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  // Move motor 1 by 5 degrees, then declare that pose to be the home pose.
  const widgets::JogPlan plan = widgets::planMotorJog(rig.doc.profile(), *rig.session.motorAngles(), 1,
                                                  radFromDeg(5.0), radFromDeg(20.0));
  ASSERT_TRUE(rig.session.sendJog(plan));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  rig.session.home();  // the maker plotter has no switches: G10 L20 with the home angles
  ASSERT_TRUE(rig.waitIdle());
  const JointAngles q = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(q.theta1), degFromRad(rig.doc.profile().homeAngles.theta1), 0.01);
  EXPECT_NEAR(degFromRad(q.theta2), degFromRad(rig.doc.profile().homeAngles.theta2), 0.01);
}

}  // namespace
}  // namespace fivebar
