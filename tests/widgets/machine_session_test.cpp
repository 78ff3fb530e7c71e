// SPDX-License-Identifier: GPL-3.0-or-later
// The machine session and its panels on the simulated machine: connection and status, the
// alarm banner and its way out, error answers, and the console's history.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>

#include "core/kinematics/units.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "machine_test_support.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/machine_banner.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/port_box.hpp"

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
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
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
  // The simulator starts at MPos 0,0 like a board after power-up: its position is not known (no
  // 0/0 pose through the base), the panel says so; once its reference is set the reported pose
  // is the profile's home pose, within a step.
  EXPECT_FALSE(rig.session.motorAngles().has_value());
  EXPECT_FALSE(rig.session.poseKnown());
  EXPECT_TRUE(panel.positionLabel()->text().contains(QStringLiteral("unknown"))) << panel.positionLabel()->text().toStdString();
  ASSERT_TRUE(rig.setReference());
  const JointAngles q = *rig.session.motorAngles();
  const MachineProfile& p = rig.doc.profile();
  EXPECT_NEAR(degFromRad(q.theta1), degFromRad(p.homeAngles.theta1), 1.0 / p.motors.stepsPerDeg1);
  EXPECT_NEAR(degFromRad(q.theta2), degFromRad(p.homeAngles.theta2), 1.0 / p.motors.stepsPerDeg2);
  // The pen state is the board's own (its reported spindle state): up after power-up, down
  // once the board runs the pen-down command, not when the command is sent.
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_EQ(panel.penLabel()->text(), widgets::MachinePanel::tr("up"));
  ASSERT_TRUE(rig.session.penDown());
  EXPECT_EQ(panel.penLabel()->text(), widgets::MachinePanel::tr("up")) << "shown before the board ran it";
  ASSERT_TRUE(waitUntil([&] { return panel.penLabel()->text() == widgets::MachinePanel::tr("down (drawing)"); }, 5000));
  ASSERT_TRUE(waitUntil([&] { return rig.session.canJog(); }, 5000));
  ASSERT_TRUE(rig.session.penUp());
  ASSERT_TRUE(waitUntil([&] { return panel.penLabel()->text() == widgets::MachinePanel::tr("up"); }, 5000));
  panel.disconnectButton()->click();
  EXPECT_FALSE(rig.session.isConnected());
  EXPECT_TRUE(panel.connectButton()->isEnabled());
}

TEST(MachineBanner, AlarmShowsTheExplanationAndResetThenUnlockClearsIt) {
  MachineRig rig;
  // The alarm (ALARM:1) fires on the board's fourth line: the first two are the $I and $$ the
  // studio sends on connect to compare the settings with the profile, the third the reference.
  ASSERT_TRUE(rig.connect(4.0, sim::Fault{sim::FaultKind::AlarmAfter, 3}));
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));
  widgets::MachineBanner banner(rig.view, rig.session);
  // A fresh board: the banner asks for the reference pose first.
  EXPECT_FALSE(banner.isHidden());
  EXPECT_TRUE(banner.message()->text().contains(QStringLiteral("not known"))) << banner.message()->text().toStdString();
  EXPECT_TRUE(banner.homeButton()->isVisible() || !banner.homeButton()->isHidden());
  ASSERT_TRUE(rig.setReference());
  EXPECT_TRUE(banner.isHidden());
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G4P0.01")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().kind == session::MachineProblem::Kind::Alarm; }, 5000));
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
  EXPECT_EQ(rig.session.problem().kind, session::MachineProblem::Kind::None);
  // A hard-limit alarm loses the position (GRBL's own words): the banner now asks for the
  // reference pose again, and nothing moves until it is set.
  EXPECT_FALSE(rig.session.poseKnown());
  EXPECT_FALSE(banner.isHidden());
  EXPECT_TRUE(banner.message()->text().contains(QStringLiteral("stopped hard while moving")))
      << banner.message()->text().toStdString();
}

TEST(MachineBanner, RejectedLineShowsTheErrorTextAndCanBeDismissed) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::MachineBanner banner(rig.view, rig.session);
  // A move without a feed rate: GRBL answers error:22 and nothing moves.
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G1X150")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().kind == session::MachineProblem::Kind::Error; }, 5000));
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
  widgets::ConsolePanel console(rig.consolePort);
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
  const jog::JogPlan plan = jog::planMotorJog(rig.doc.profile(), *rig.session.motorAngles(), 1, 5.0, 20.0 * 60.0);
  ASSERT_TRUE(rig.session.sendJog(plan));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  rig.session.home();  // the maker plotter has no switches: G10 L20 with the home angles
  ASSERT_TRUE(rig.waitIdle());
  const JointAngles q = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(q.theta1), degFromRad(rig.doc.profile().homeAngles.theta1), 0.01);
  EXPECT_NEAR(degFromRad(q.theta2), degFromRad(rig.doc.profile().homeAngles.theta2), 0.01);
}

// The simulated machine drives a true machine when given one (issue 13): with link b1 0.5 mm
// longer, its pen draws where the true geometry puts it, not where the profile says; without
// one, exactly on the plan (within a step).
struct DrawnEnd {
  Vec2 tracedMm;      // the last point of the drawn trace
  JointAngles motor;  // the motors' reported angles there
};
std::optional<DrawnEnd> drawShortStroke(std::optional<MachineProfile> trueMachine) {
  MachineRig rig;
  rig.session.setSimulatedTrueMachine(std::move(trueMachine));
  if (!rig.connect(50.0) || !rig.waitIdle()) {
    ADD_FAILURE() << "the simulated machine did not connect";
    return std::nullopt;
  }
  const ToolSettings& tool = rig.doc.profile().tool;
  EXPECT_EQ(tool.kind, ToolKind::PenServo);
  for (const QString& line : {QStringLiteral("M3 S%1").arg(tool.penDownS), QStringLiteral("G91 G1 X4 Y-3 F300"),
                              QStringLiteral("G1 X-2 Y-2"), QStringLiteral("G90")}) {
    QString refusal;
    const bool settled = waitUntil([&] { return rig.session.bytesInFlight() == 0; }, 5000) && rig.waitIdle();
    if (!settled || !rig.session.sendLine(line, &refusal)) {
      ADD_FAILURE() << line.toStdString() << ": " << refusal.toStdString();
      return std::nullopt;
    }
  }
  // Done when the motors stand still: the reported angles no longer change between reports.
  std::optional<JointAngles> last;
  QElapsedTimer still;
  still.start();
  if (!waitUntil([&] {
        const auto q = rig.session.motorAngles();
        if (!(q && last && q->theta1 == last->theta1 && q->theta2 == last->theta2)) still.restart();
        last = q;
        return still.elapsed() > 700 && rig.session.bytesInFlight() == 0 && rig.session.state() == grbl::MachineState::Idle;
      }, 10000))
    return std::nullopt;
  const auto trace = rig.session.simulatedDrawnTrace();
  const auto q = rig.session.motorAngles();
  if (trace.empty() || trace.back().size() < 2 || !q) return std::nullopt;
  return DrawnEnd{trace.back().back(), *q};
}

TEST(MachineSession, SimulatedMachineDrawsWithItsTrueMachine) {
  const MachineProfile nominal = test::makerPlotter();
  MachineProfile truth = nominal;
  truth.geometry.b1 += 0.5;

  const auto perfect = drawShortStroke(std::nullopt);
  ASSERT_TRUE(perfect);
  const FkResult planned = forward(nominal.geometry, perfect->motor, nominal.assembly);
  ASSERT_TRUE(planned.ok());
  const double stepMm = 0.05;  // a motor step (1/stepsPerDeg deg) moves the pen far less
  EXPECT_LT((perfect->tracedMm - planned.p).norm(), stepMm);

  const auto imperfect = drawShortStroke(truth);
  ASSERT_TRUE(imperfect);
  const FkResult meant = forward(nominal.geometry, imperfect->motor, nominal.assembly);
  const FkResult real = forward(truth.geometry, imperfect->motor, truth.assembly);
  ASSERT_TRUE(meant.ok() && real.ok());
  const double expectedMm = (real.p - meant.p).norm();
  ASSERT_GT(expectedMm, 0.1);  // b1 0.5 mm longer moves the pen by a visible amount
  EXPECT_NEAR((imperfect->tracedMm - meant.p).norm(), expectedMm, 0.02);
  EXPECT_LT((imperfect->tracedMm - real.p).norm(), 0.02);
}

}  // namespace
}  // namespace fivebar
