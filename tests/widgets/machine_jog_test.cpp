// SPDX-License-Identifier: GPL-3.0-or-later
// The jog panel driving the simulated machine (the planning itself: tests/drivers/jog_plan_test).
#include <gtest/gtest.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QPushButton>
#include <cmath>

#include "core/planning/safety.hpp"
#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "test_support.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "widgets/machine/jog_panel.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

TEST(JogPanel, ArrowStepMovesTheSimulatedMachine) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  const Vec2 before = *rig.session.penMm();
  // Step 10 mm, then a tap (press + release) on "+X".
  panel.controller().setStep(10.0);
  panel.arrowButton(1, 0)->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  const Vec2 after = *rig.session.penMm();
  // One motor step is about 0.028 deg: well under 0.2 mm at the pen.
  EXPECT_NEAR(after.x() - before.x(), 10.0, 0.2);
  EXPECT_NEAR(after.y() - before.y(), 0.0, 0.2);
  EXPECT_TRUE(panel.messageLabel()->text().isEmpty()) << panel.messageLabel()->text().toStdString();
}

TEST(JogPanel, MotorButtonTurnsOneMotor) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  const JointAngles before = *rig.session.motorAngles();
  panel.controller().setStep(1.0);
  panel.motorButton(2, -1)->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  const JointAngles after = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(after.theta2 - before.theta2), -1.0, 0.05);
  EXPECT_NEAR(degFromRad(after.theta1 - before.theta1), 0.0, 0.05);
}

TEST(JogPanel, HoldingStreamsAContinuousJogAndReleaseStopsIt) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(1.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  panel.controller().setStep(0.1);
  panel.controller().setSpeedMmPerS(20.0);
  const Vec2 before = *rig.session.penMm();
  QPushButton* down = panel.arrowButton(0, -1);
  emit down->pressed();
  waitUntil([] { return false; }, 1200);  // hold for 1.2 s
  EXPECT_TRUE(panel.controller().streaming());
  emit down->released();
  ASSERT_TRUE(rig.waitIdle());
  const Vec2 stopped = *rig.session.penMm();
  // Far more than one 0.1 mm step, at most the hold time at speed plus a short overshoot.
  EXPECT_LT(stopped.y() - before.y(), -5.0);
  EXPECT_GT(stopped.y() - before.y(), -40.0);
  EXPECT_NEAR(stopped.x(), before.x(), jog::kDefaultDeviationMm + 0.2);
  // It stays stopped.
  waitUntil([] { return false; }, 500);
  EXPECT_NEAR((*rig.session.penMm() - stopped).norm(), 0.0, 1e-6);
}

TEST(JogPanel, GoToPreviewsThenMovesOnConfirm) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  const Vec2 start = *rig.session.penMm();
  const Vec2 target = start + Vec2(-20.0, 10.0);
  panel.goToTool().pick(QPointF(target.x(), target.y()));
  ASSERT_TRUE(panel.goToTool().pending().has_value());
  EXPECT_TRUE(panel.confirmButton()->isEnabled());
  // Nothing moves before the confirmation.
  waitUntil([] { return false; }, 300);
  EXPECT_NEAR((*rig.session.penMm() - start).norm(), 0.0, 1e-6);
  panel.confirmButton()->click();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jogSettled(); }, 2000));
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_NEAR((*rig.session.penMm() - target).norm(), 0.0, 0.2);
}

// One click, one move: once the confirmed go-to is sent, the tool disarms (the Go to button
// unchecks and the canvas gets its previous tool back), so the next click does not plan another.
TEST(JogPanel, GoToDisarmsAfterItsMove) {
  MachineRig rig;
  ASSERT_TRUE(rig.connect(8.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::CanvasView canvas;
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  panel.attachCanvas(&canvas);
  panel.goToButton()->click();
  ASSERT_TRUE(panel.goToButton()->isChecked());
  EXPECT_EQ(canvas.tool(), &panel.goToTool());
  const Vec2 target = *rig.session.penMm() + Vec2(10.0, 5.0);
  panel.goToTool().pick(QPointF(target.x(), target.y()));
  ASSERT_TRUE(panel.confirmButton()->isEnabled());
  panel.confirmButton()->click();
  EXPECT_FALSE(panel.goToButton()->isChecked());
  EXPECT_NE(canvas.tool(), &panel.goToTool());
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_NEAR((*rig.session.penMm() - target).norm(), 0.0, 0.2);
}

}  // namespace
}  // namespace fivebar

namespace fivebar {
namespace {

// The arrow keys jog whenever the studio's window has the focus and no text or value field does:
// not only after a click on the canvas.
TEST(JogPanel, ArrowKeysJogWhereverTheFocusIsButInTextFields) {
  test::MachineRig rig;
  ASSERT_TRUE(rig.connect(4.0));
  ASSERT_TRUE(rig.waitIdle());
  QWidget window;
  auto* layout = new QHBoxLayout(&window);
  auto* canvas = new widgets::CanvasView(&window);
  auto* button = new QPushButton(QStringLiteral("elsewhere"), &window);
  auto* field = new QLineEdit(&window);
  auto* panel = new widgets::JogPanel(rig.view, rig.session, rig.session, rig.jog, &window);
  layout->addWidget(canvas);
  layout->addWidget(button);
  layout->addWidget(field);
  layout->addWidget(panel);
  panel->attachCanvas(canvas);
  rig.jog.setStep(10.0);
  window.resize(900, 500);
  window.show();
  QApplication::setActiveWindow(&window);
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  const auto tap = [](QWidget* target) {
    QTest::keyPress(target, Qt::Key_Right);
    QTest::keyRelease(target, Qt::Key_Right);
  };

  // A text field keeps its arrows: nothing moves.
  field->setFocus();
  ASSERT_TRUE(test::waitUntil([&] { return QApplication::focusWidget() == field; }, 2000));
  const Vec2 before = *rig.session.penMm();
  tap(field);
  test::waitUntil([] { return false; }, 400);
  EXPECT_TRUE(rig.session.jogSettled());
  EXPECT_NEAR((*rig.session.penMm() - before).norm(), 0.0, 1e-6);

  // A button has the focus, not the canvas: the arrow jogs one step.
  button->setFocus();
  ASSERT_TRUE(test::waitUntil([&] { return QApplication::focusWidget() == button; }, 2000));
  tap(button);
  ASSERT_TRUE(test::waitUntil([&] { return !rig.session.jogSettled(); }, 2000)) << "the arrow key did not jog";
  ASSERT_TRUE(rig.waitIdle());
  const Vec2 after = *rig.session.penMm();
  EXPECT_NEAR(after.x() - before.x(), 10.0, 0.2);
  EXPECT_NEAR(after.y() - before.y(), 0.0, 0.2);
}

}  // namespace
}  // namespace fivebar
