// SPDX-License-Identifier: GPL-3.0-or-later
// The board's soft limits in the one motion check, on the simulated machine: with $20=1 and a
// small travel, the console, a jog, go to home pose and go-to are refused before a byte is sent
// (the simulated GRBL would raise ALARM:2 or answer error:15), the same moves inside the travel
// pass, and the pre-flight problem list names the job the board would stop.
#include <gtest/gtest.h>

#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>

#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "session/board_preflight.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/panels/preview_panel.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

void submit(widgets::ConsolePanel& console, const QString& line) {
  console.input()->setText(line);
  QKeyEvent press(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
  QCoreApplication::sendEvent(console.input(), &press);
}

// Soft limits on with a travel of 1 deg per motor below the machine's zero: the reference pose
// (the home pose) is machine 0,0, so each motor may turn down by 1 deg and not up at all.
bool softLimitsOn(MachineRig& rig) {
  for (const char* line : {"$22=1", "$20=1", "$130=1", "$131=1"})
    if (!rig.session.link()->protocol().enqueue(line).ok()) return false;
  if (!rig.waitIdle()) return false;
  rig.session.readBoardSettings();
  return waitUntil([&] {
    const auto& b = rig.session.boardSettings();
    return !rig.session.readingBoardSettings() && b && b->count(131) && b->at(131) == 1.0 && b->at(20) == 1.0;
  }, 5000);
}

QString moveTo(const MachineProfile& p, double dTheta1Deg, double dTheta2Deg) {
  return QStringLiteral("G1 X%1 Y%2 F600")
      .arg(degFromRad(p.homeAngles.theta1) + dTheta1Deg, 0, 'f', 3)
      .arg(degFromRad(p.homeAngles.theta2) + dTheta2Deg, 0, 'f', 3);
}

TEST(BoardLimits, ConsoleJogAndGoHomeAreRefusedBeforeTheBoardAlarms) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(softLimitsOn(rig));
  // The board's settings now differ from the profile ($20, $22, $130, $131): moves are refused
  // for that, naming them...
  EXPECT_TRUE(rig.session.settingsStopMoves());
  EXPECT_FALSE(rig.session.canJog());
  EXPECT_TRUE(rig.session.moveRefusal().contains(QStringLiteral("$130"))) << rig.session.moveRefusal().toStdString();
  // ...until the expert's override; then the board's own soft limits are still checked.
  rig.session.setIgnoreSettingDifferences(true);
  const MachineProfile& p = rig.doc.profile();
  const JointAngles before = *rig.session.motorAngles();
  // Console: up by 0.5 deg leaves the travel; the check says so and sends nothing.
  widgets::ConsolePanel console(rig.consolePort);
  submit(console, moveTo(p, 0.5, 0.0));
  EXPECT_FALSE(console.refusalLabel()->isHidden());
  const QString why = console.refusalLabel()->text();
  EXPECT_TRUE(why.contains(QStringLiteral("ALARM:2"))) << why.toStdString();
  EXPECT_TRUE(why.contains(QStringLiteral("$130=1.000"))) << why.toStdString();
  EXPECT_TRUE(why.contains(QStringLiteral("machine coordinates"))) << why.toStdString();
  // Jog: motor 2 up by 1 deg is refused the same way (GRBL would answer error:15).
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  panel.controller().setStep(1.0);
  panel.motorButton(2, +1)->click();
  EXPECT_TRUE(panel.messageLabel()->text().contains(QStringLiteral("soft-limit"))) << panel.messageLabel()->text().toStdString();
  QThread::msleep(300);
  QCoreApplication::processEvents();
  EXPECT_NE(rig.session.state(), grbl::MachineState::Alarm);
  EXPECT_LT(std::abs(degFromRad(rig.session.motorAngles()->theta1 - before.theta1)), 1e-3) << "nothing moved";
  EXPECT_LT(std::abs(degFromRad(rig.session.motorAngles()->theta2 - before.theta2)), 1e-3) << "nothing moved";
  // Inside the travel the same kinds of move pass: console down 0.5 deg, then a jog down 0.3 deg.
  submit(console, moveTo(p, -0.5, 0.0));
  EXPECT_TRUE(console.refusalLabel()->isHidden()) << console.refusalLabel()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return std::abs(degFromRad(rig.session.motorAngles()->theta1 - before.theta1) + 0.5) < 0.05; }, 5000));
  ASSERT_TRUE(rig.waitIdle());
  panel.controller().setStep(0.3);
  panel.motorButton(2, -1)->click();
  ASSERT_TRUE(waitUntil([&] { return std::abs(degFromRad(rig.session.motorAngles()->theta2 - before.theta2) + 0.3) < 0.05; }, 5000))
      << panel.messageLabel()->text().toStdString();
  ASSERT_TRUE(rig.waitIdle());
  // A plan that leaves the travel is refused by sendJog itself, whoever planned it.
  jog::JogPlan outside = jog::planMotorJog(p, *rig.session.motorAngles(), 1, 2.0, 600.0);
  ASSERT_TRUE(outside.ok());
  EXPECT_FALSE(rig.session.sendJog(outside));
  // Go to home pose returns there (machine 0,0: inside the travel).
  QString whyHome;
  EXPECT_TRUE(rig.session.goToHomePose(&whyHome)) << whyHome.toStdString();
  ASSERT_TRUE(waitUntil([&] { return std::abs(degFromRad(rig.session.motorAngles()->theta1 - before.theta1)) < 0.05; }, 5000));
  ASSERT_TRUE(rig.waitIdle());
  // With the reference declared 2 deg lower, home is machine +2 deg: go to home pose is refused.
  ASSERT_TRUE(rig.session.sendLine(moveTo(p, -0.8, -0.8)));
  ASSERT_TRUE(waitUntil([&] { return std::abs(degFromRad(rig.session.motorAngles()->theta1 - before.theta1) + 0.8) < 0.05; }, 5000));
  ASSERT_TRUE(rig.waitIdle());
  rig.session.setReferencePose();  // here is "home" now: machine -0.8, work home
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(waitUntil([&] { return rig.session.workOffsetDeg() && std::abs((*rig.session.workOffsetDeg())[0] - (-0.8 - degFromRad(p.homeAngles.theta1))) < 0.05; }, 5000))
      << (rig.session.workOffsetDeg() ? (*rig.session.workOffsetDeg())[0] : -1e9) << " home " << degFromRad(p.homeAngles.theta1);
  const JointAngles referenced = *rig.session.motorAngles();
  EXPECT_TRUE(rig.session.sendLine(moveTo(p, 0.7, 0.7)));  // machine -0.1: inside
  ASSERT_TRUE(waitUntil([&] { return std::abs(degFromRad(rig.session.motorAngles()->theta1 - referenced.theta1) - 0.7) < 0.05; }, 5000));
  ASSERT_TRUE(waitUntil([&] { return rig.session.state() == grbl::MachineState::Idle; }, 5000));
  QThread::msleep(300);
  QCoreApplication::processEvents();
  QString refusal;
  EXPECT_FALSE(rig.session.sendLine(moveTo(p, 0.9, 0.0), &refusal));  // machine +0.1: outside
  EXPECT_TRUE(refusal.contains(QStringLiteral("ALARM:2"))) << refusal.toStdString();
  QThread::msleep(300);
  QCoreApplication::processEvents();
  EXPECT_NE(rig.session.state(), grbl::MachineState::Alarm);
  // Unchecked, the same line really raises the board's soft-limit alarm: the check agrees.
  rig.session.setUncheckedConsole(true);
  EXPECT_TRUE(rig.session.sendLine(moveTo(p, 0.9, 0.0)));
  EXPECT_TRUE(waitUntil([&] { return rig.session.state() == grbl::MachineState::Alarm; }, 5000));
  EXPECT_EQ(rig.session.problem().code, 2);
}

Drawing squareDrawing() {
  Drawing d;
  d.source = "board-limits-test";
  d.widthMm = d.heightMm = 30.0;
  Layer layer;
  layer.id = layer.name = "ink";
  Polyline square;
  square.points = {Vec2(0, 0), Vec2(30, 0), Vec2(30, 30), Vec2(0, 30)};
  square.closed = true;
  layer.paths = {square};
  d.layers.push_back(layer);
  return d;
}

// The pre-flight problem list names a job the board's soft limits would stop, while connected to
// such a board; it goes when the limits are off again.
TEST(BoardLimits, PreflightListsTheJobTheBoardWouldStop) {
  MachineRig rig;
  Placement placement;
  placement.centerMm = Vec2(0.0, 170.0);
  rig.doc.replaceDrawing(squareDrawing(), QStringLiteral("square.svg"), placement);
  rig.preview.replanNow();
  ASSERT_TRUE(waitUntil([&] { return !rig.preview.busy() && rig.inputs.plannedJob() != nullptr; }, 30000));
  widgets::SimulationController sim;
  widgets::JobLayer layer(rig.doc, rig.preview, sim);
  widgets::PreviewPanel panel(rig.preview, layer);
  session::BoardPreflight preflight(rig.inputs, rig.session);
  QObject::connect(&preflight, &session::BoardPreflight::changed, &panel, &widgets::PreviewPanel::setMachineProblem);
  EXPECT_TRUE(preflight.problem().isEmpty());
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(softLimitsOn(rig));
  ASSERT_TRUE(waitUntil([&] { return !preflight.problem().isEmpty(); }, 3000));
  ASSERT_GE(panel.problems()->count(), 1);
  const QString first = panel.problems()->item(0)->text();
  EXPECT_TRUE(first.contains(QStringLiteral("ALARM:2"))) << first.toStdString();
  EXPECT_TRUE(first.contains(QStringLiteral("machine coordinates"))) << first.toStdString();
  ASSERT_TRUE(rig.session.link()->protocol().enqueue("$20=0").ok());
  ASSERT_TRUE(rig.waitIdle());
  rig.session.readBoardSettings();
  ASSERT_TRUE(waitUntil([&] { return preflight.problem().isEmpty(); }, 5000));
  EXPECT_FALSE(panel.problems()->item(0)->text().contains(QStringLiteral("ALARM:2")));
}

}  // namespace
}  // namespace fivebar
