// SPDX-License-Identifier: GPL-3.0-or-later
// The machine side's safety on the simulated machine: the console's motion check and its expert
// switch, the reference pose asked for, go-to-home by a checked move, "connected" only after the
// board answered, and the canvas linkage following the machine.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <pty.h>
#include <unistd.h>

#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/machine/machine_dialogs.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "session/settings_advice.hpp"

namespace fivebar {
namespace {

using test::answerBox;
using test::MachineRig;
using test::waitUntil;

void submit(widgets::ConsolePanel& console, const QString& line) {
  console.input()->setText(line);
  QKeyEvent press(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
  QCoreApplication::sendEvent(console.input(), &press);
}

bool near(const JointAngles& a, const JointAngles& b, double tolDeg) {
  return std::abs(degFromRad(a.theta1 - b.theta1)) < tolDeg && std::abs(degFromRad(a.theta2 - b.theta2)) < tolDeg;
}

TEST(ConsoleCheck, RefusesTheSwingAcrossTheBaseAndSaysWhy) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::ConsolePanel console(rig.consolePort);
  EXPECT_FALSE(console.uncheckedSwitch()->isChecked());  // checked by default
  EXPECT_TRUE(console.uncheckedBanner()->isHidden());
  EXPECT_FALSE(console.input()->placeholderText().contains(QStringLiteral("G0 X10 Y20")));
  const JointAngles before = *rig.session.motorAngles();
  // The example: from the home pose this swings the left arm across the base.
  submit(console, QStringLiteral("G0 X10 Y20"));
  EXPECT_FALSE(console.refusalLabel()->isHidden());
  EXPECT_TRUE(console.refusalLabel()->text().contains(QStringLiteral("10.000, 20.000")))
      << console.refusalLabel()->text().toStdString();
  EXPECT_EQ(console.input()->text(), QStringLiteral("G0 X10 Y20"));  // kept for correcting
  EXPECT_FALSE(console.log()->toPlainText().contains(QStringLiteral("> G0 X10 Y20")));
  QThread::msleep(300);
  QCoreApplication::processEvents();
  EXPECT_TRUE(near(*rig.session.motorAngles(), before, 1e-3));  // nothing moved
  // G92 would change the coordinates the check relies on: refused with the studio's words.
  submit(console, QStringLiteral("G92 X0 Y0"));
  EXPECT_TRUE(console.refusalLabel()->text().contains(QStringLiteral("reference pose")))
      << console.refusalLabel()->text().toStdString();
  // A small checked move from the home pose passes and moves the machine.
  const MachineProfile& p = rig.doc.profile();
  const QString small = QStringLiteral("G1 X%1 Y%2 F600")
                            .arg(degFromRad(p.homeAngles.theta1) + 2.0, 0, 'f', 3)
                            .arg(degFromRad(p.homeAngles.theta2) + 2.0, 0, 'f', 3);
  submit(console, small);
  EXPECT_TRUE(console.refusalLabel()->isHidden()) << console.refusalLabel()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !near(*rig.session.motorAngles(), before, 1.0); }, 5000));
  // Non-motion lines pass.
  EXPECT_TRUE(rig.session.sendLine(QStringLiteral("$G")));
}

TEST(ConsoleCheck, ExpertSwitchSendsUncheckedUnderAWarningBanner) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::ConsolePanel console(rig.consolePort);
  console.show();
  console.uncheckedSwitch()->setChecked(true);
  EXPECT_TRUE(rig.session.uncheckedConsole());
  EXPECT_FALSE(console.uncheckedBanner()->isHidden());
  // An unchecked line is sent as typed (a dwell: harmless, but the check is not asked).
  QString refusal;
  EXPECT_TRUE(rig.session.sendLine(QStringLiteral("G4 P0.01"), &refusal));
  EXPECT_TRUE(console.log()->toPlainText().contains(QStringLiteral("Unchecked: G4 P0.01")));
  console.uncheckedSwitch()->setChecked(false);
  EXPECT_FALSE(rig.session.uncheckedConsole());
  EXPECT_TRUE(console.uncheckedBanner()->isHidden());
  EXPECT_FALSE(rig.session.sendLine(QStringLiteral("G0 X10 Y20"), &refusal));
  EXPECT_FALSE(refusal.isEmpty());
}

TEST(ReferencePose, IsSetOnlyAfterConfirmationAndGoHomeReturnsByACheckedMove) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel jog(rig.view, rig.session, rig.session, rig.jog);
  const MachineProfile& p = rig.doc.profile();
  // Move away from the home pose by 5 degrees of motor 1.
  const jog::JogPlan plan =
      jog::planMotorJog(p, *rig.session.motorAngles(), 1, 5.0, 20.0 * 60.0);
  ASSERT_TRUE(rig.session.sendJog(plan));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  const JointAngles away = *rig.session.motorAngles();
  ASSERT_FALSE(near(away, p.homeAngles, 1.0));
  // Cancel: nothing is declared.
  QString question;
  answerBox(QStringLiteral("referencePoseQuestion"), QString(), QMessageBox::Cancel, &question);
  jog.homeButton()->click();
  EXPECT_TRUE(question.contains(QString::fromStdString(p.name))) << question.toStdString();
  EXPECT_TRUE(question.contains(QStringLiteral("home pose")));
  QThread::msleep(300);
  QCoreApplication::processEvents();
  EXPECT_TRUE(near(*rig.session.motorAngles(), away, 1e-3));
  // Go to home pose: a checked pen-up move back, the reference unchanged.
  QString why;
  ASSERT_TRUE(rig.session.goToHomePose(&why)) << why.toStdString();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle(15000));
  EXPECT_TRUE(near(*rig.session.motorAngles(), p.homeAngles, 0.05));
  EXPECT_EQ(rig.session.penState(), session::PenState::Up);
  // After a G91 typed in the console the go-to still goes home: it sets G90 first.
  ASSERT_TRUE(rig.session.sendJog(jog::planMotorJog(p, *rig.session.motorAngles(), 1, 5.0, 20.0 * 60.0)));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  QString refusal;
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G91"), &refusal)) << refusal.toStdString();
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(rig.session.goToHomePose(&why)) << why.toStdString();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle(15000));
  EXPECT_TRUE(near(*rig.session.motorAngles(), p.homeAngles, 0.05));
  // Away again, then confirm: the pose where the machine stands becomes the home pose.
  ASSERT_TRUE(rig.session.sendJog(jog::planMotorJog(p, *rig.session.motorAngles(), 1, 5.0, 20.0 * 60.0)));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  answerBox(QStringLiteral("referencePoseQuestion"), QStringLiteral("confirmReference"));
  jog.homeButton()->click();
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_TRUE(near(*rig.session.motorAngles(), p.homeAngles, 0.01));
}

TEST(Connection, IsNotConnectedWithoutGrblAndNamesPortAndBaud) {
  int master = -1, slave = -1;
  char name[256] = {};
  ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  QSignalSpy failed(&rig.session, &session::MachineSession::connectFailed);
  QString error;
  ASSERT_TRUE(rig.session.connectSerial(QString::fromLatin1(name), 115200, &error)) << error.toStdString();
  EXPECT_FALSE(rig.session.isConnected());
  EXPECT_TRUE(rig.session.isConnecting());
  EXPECT_FALSE(panel.linkLabel()->text().startsWith(QStringLiteral("Connected")));
  ASSERT_TRUE(waitUntil([&] { return failed.count() > 0; }, session::MachineSession::kConnectTimeoutMs + 3000));
  const QString message = failed.front().front().toString();
  EXPECT_TRUE(message.contains(QString::fromLatin1(name))) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("115200")));
  EXPECT_FALSE(rig.session.isConnected());
  EXPECT_FALSE(rig.session.isConnecting());
  EXPECT_EQ(panel.linkLabel()->text(), message);
  ::close(slave);
  ::close(master);
}

TEST(SettingsAdvice, SoftLimitsOnWithoutSwitchesStopTheJob) {
  const std::vector<setup::SettingDiff> diffs = {{20, 1.0, 0.0}, {110, 3000.0, 6000.0}};
  const auto advice = session::adviseOnSettings(diffs);
  ASSERT_EQ(advice.size(), 2u);
  EXPECT_TRUE(advice[0].stopsJob);
  EXPECT_TRUE(advice[0].text.contains(QStringLiteral("ALARM:2")));
  EXPECT_FALSE(advice[1].stopsJob);
  EXPECT_TRUE(session::anyStopsJob(advice));
  EXPECT_TRUE(session::settingsWarningText(diffs).contains(QStringLiteral("$20, $110")));
  EXPECT_FALSE(session::anyStopsJob(session::adviseOnSettings({{110, 3000.0, 6000.0}})));
}

TEST(MachineLayer, FollowsTheMachineWithTheSimulationAsAGhost) {
  MachineRig rig;
  widgets::SimulationController sim;
  widgets::MachineLayer layer(rig.doc, sim);
  const MachineProfile& p = rig.doc.profile();
  ASSERT_TRUE(layer.pose().has_value());
  EXPECT_FALSE(layer.ghost().has_value());
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  const jog::JogPlan plan =
      jog::planMotorJog(p, *rig.session.motorAngles(), 2, -6.0, 20.0 * 60.0);
  ASSERT_TRUE(rig.session.sendJog(plan));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 1000));
  ASSERT_TRUE(rig.waitIdle());
  layer.setExternalAngles(rig.session.motorAngles());
  const JointAngles q = *rig.session.motorAngles();
  EXPECT_NEAR(layer.pose()->q.theta1, q.theta1, 1e-9);
  EXPECT_NEAR(layer.pose()->q.theta2, q.theta2, 1e-9);
  layer.setExternalAngles(std::nullopt);
  EXPECT_NEAR(layer.pose()->q.theta1, p.homeAngles.theta1, 1e-9);
}

}  // namespace
}  // namespace fivebar
