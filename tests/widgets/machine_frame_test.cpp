// SPDX-License-Identifier: GPL-3.0-or-later
// Frame (issue 26): the jog panel's Frame button traces the planned job's outline pen up on the
// simulated machine, enabled only when connected with a known pose and a planned job; the
// recovery bar (Reset, Unlock, Set reference pose) is there whenever a machine is connected,
// and the Run panel shows an alarm.
#include <gtest/gtest.h>

#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <algorithm>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/output/gcode.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "machine_test_support.hpp"
#include "session/frame.hpp"
#include "session/run_controller.hpp"
#include "widgets/machine/alarm_strip.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/machine/recovery_bar.hpp"
#include "widgets/machine/run_panel.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

// A 40 x 30 mm rectangle and a circle inside it, work frame.
Drawing frameDrawing() {
  Drawing d;
  d.source = "machine-frame-test";
  d.widthMm = 40.0;
  d.heightMm = 30.0;
  Layer layer;
  layer.id = layer.name = "ink";
  Polyline box;
  box.points = {Vec2(0, 0), Vec2(40, 0), Vec2(40, 30), Vec2(0, 30)};
  box.closed = true;
  Polyline circle;
  for (int i = 0; i < 48; ++i) {
    const double a = 2.0 * kPi * i / 48.0;
    circle.points.push_back(Vec2(20.0 + 10.0 * std::cos(a), 15.0 + 10.0 * std::sin(a)));
  }
  circle.closed = true;
  layer.paths = {box, circle};
  d.layers.push_back(layer);
  return d;
}

// The planned job's pen-down points (machine frame, mm), read from its G-code as the frame is.
std::vector<Vec2> penDownPointsMm(const MachineProfile& p, const PlannedJob& job) {
  const stream::JobRules rules = stream::rulesFor(p);
  std::vector<Vec2> out;
  for (const auto& stroke : stream::strokesOf(stream::parseJob(writeGcode(job, p), rules), rules))
    for (const auto& q : stroke) {
      const FkResult fk = penForward(p, kinematicFromCommanded(p.calibration, {radFromDeg(q[0]), radFromDeg(q[1])}));
      if (fk.ok()) out.push_back(fk.p);
    }
  return out;
}

TEST(Frame, ButtonTracesThePlannedJobsOutlinePenUpOnlyWhenItCan) {
  MachineRig rig;
  session::RunController run(rig.inputs, rig.session);
  widgets::JogPanel panel(rig.view, rig.session, rig.session, rig.jog);
  QPushButton* frame = panel.frameButton();
  EXPECT_FALSE(frame->isEnabled()) << "not connected";
  // Connected, a board fresh from power-up: the pose is not known.
  QString error;
  ASSERT_TRUE(rig.session.connectSimulated(2.0, {}, &error)) << error.toStdString();
  ASSERT_TRUE(waitUntil([&] { return rig.session.lastStatus() != nullptr &&
                                     rig.session.poseDoubt() != grbl::PoseDoubt::NotYetRead; }, 5000));
  EXPECT_FALSE(rig.session.poseKnown());
  EXPECT_FALSE(frame->isEnabled()) << "pose unknown";
  ASSERT_TRUE(rig.setReference());
  ASSERT_TRUE(rig.waitIdle());
  EXPECT_FALSE(frame->isEnabled()) << "no job planned";
  QString why;
  EXPECT_FALSE(rig.session.frameJob(&why));
  EXPECT_TRUE(why.contains(QStringLiteral("No job is planned"))) << why.toStdString();
  // A job planned: the button comes alive.
  Placement placement;
  placement.centerMm = Vec2(0.0, 170.0);
  rig.doc.replaceDrawing(frameDrawing(), QStringLiteral("frame.svg"), placement);
  rig.preview.replanNow();
  ASSERT_TRUE(waitUntil([&] { return frame->isEnabled(); }, 30000)) << rig.preview.result().message.toStdString();
  const PlannedJob* job = rig.inputs.plannedJob();
  ASSERT_NE(job, nullptr);
  const std::vector<Vec2> points = penDownPointsMm(rig.doc.profile(), *job);
  ASSERT_FALSE(points.empty());
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& v : points) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
  // The frame the button sends, planned the same way (session/frame.hpp) from where it starts.
  const auto start = rig.session.jogStart();
  ASSERT_TRUE(start.has_value());
  const jog::JogPlan plan = session::planJobFrame(rig.session, rig.doc.profile(), *start, *job);
  ASSERT_EQ(plan.status, jog::JogStatus::Ok) << plan.reason;
  const std::vector<Vec2> path = jog::penPathMm(rig.doc.profile(), *start, plan);
  ASSERT_FALSE(path.empty());
  const Vec2 corner = path.back();  // the outline's first corner, where it starts and ends
  double nearest = 1e9;
  for (const Vec2& v : points) nearest = std::min(nearest, (v - corner).norm());
  EXPECT_LT(nearest, 0.1) << "the first corner is one of the job's points: " << corner.transpose();
  // From the end of the travel on, the path goes round the outline: inside the job's bounding
  // box, and out to each of its sides.
  const auto outline = std::find_if(path.begin(), path.end(), [&](const Vec2& v) { return (v - corner).norm() < 0.05; });
  ASSERT_NE(outline, path.end());
  Vec2 plo = *outline, phi = *outline;
  for (auto it = outline; it != path.end(); ++it) {
    EXPECT_TRUE(it->x() >= lo.x() - 0.1 && it->x() <= hi.x() + 0.1 && it->y() >= lo.y() - 0.1 &&
                it->y() <= hi.y() + 0.1) << it->transpose();
    plo = plo.cwiseMin(*it);
    phi = phi.cwiseMax(*it);
  }
  EXPECT_LT((plo - lo).norm(), 0.2);
  EXPECT_LT((phi - hi).norm(), 0.2);
  Vec2 alo = path[0], ahi = path[0];  // the whole path, travel included
  for (const Vec2& v : path) { alo = alo.cwiseMin(v); ahi = ahi.cwiseMax(v); }
  // The pen as the board reports it while the frame runs.
  std::vector<Vec2> seen;
  QObject::connect(&rig.view, &session::MachineView::statusUpdated, &panel, [&] {
    if (const auto pen = rig.session.penMm()) seen.push_back(*pen);
  });
  frame->click();
  EXPECT_TRUE(panel.messageLabel()->text().contains(QStringLiteral("outline"))) << panel.messageLabel()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !frame->isEnabled(); }, 2000)) << "busy framing";
  ASSERT_TRUE(rig.waitIdle(30000));
  EXPECT_TRUE(frame->isEnabled());
  // Pen up throughout: the simulated pen drew nothing.
  for (const auto& stroke : rig.session.simulatedDrawnTrace()) EXPECT_LT(stroke.size(), 2u);
  EXPECT_EQ(rig.session.penState(), session::PenState::Up);
  // The machine followed that path and stopped at the first corner.
  EXPECT_LT((*rig.session.penMm() - corner).norm(), 0.1);
  EXPECT_GT(seen.size(), 3u) << "the frame took its time, it was not one jump";
  for (const Vec2& v : seen)
    EXPECT_TRUE(v.x() >= alo.x() - 0.2 && v.x() <= ahi.x() + 0.2 && v.y() >= alo.y() - 0.2 && v.y() <= ahi.y() + 0.2)
        << v.transpose();
}

TEST(RecoveryBar, IsThereWhileConnectedAndTheRunPanelShowsTheAlarm) {
  MachineRig rig;
  session::RunController run(rig.inputs, rig.session);
  widgets::RecoveryBar bar(rig.view, rig.session);
  widgets::RunPanel runPanel(run, rig.view, rig.session);
  EXPECT_TRUE(bar.isHidden()) << "no machine";
  EXPECT_TRUE(runPanel.alarmStrip()->isHidden());
  // The alarm (ALARM:1) fires on the board's fourth line (after $I, $$ and the reference).
  ASSERT_TRUE(rig.connect(4.0, sim::Fault{sim::FaultKind::AlarmAfter, 3}));
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));
  EXPECT_FALSE(bar.isHidden());
  EXPECT_FALSE(bar.resetButton()->isHidden());
  EXPECT_FALSE(bar.unlockButton()->isHidden());
  EXPECT_FALSE(bar.referenceButton()->isHidden());
  EXPECT_FALSE(bar.unlockButton()->isEnabled()) << "no alarm yet";
  EXPECT_TRUE(bar.referenceButton()->text() == widgets::RecoveryBar::tr("Set reference pose"));
  // Set reference pose from the bar: it asks first, as the banner does.
  test::answerBox(QStringLiteral("referencePoseQuestion"), QStringLiteral("confirmReference"));
  bar.referenceButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.poseKnown(); }, 5000));
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("G4P0.01")));
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().kind == session::MachineProblem::Kind::Alarm; }, 5000));
  EXPECT_FALSE(runPanel.alarmStrip()->isHidden());
  EXPECT_TRUE(runPanel.alarmStrip()->message()->text().contains(QStringLiteral("Alarm 1")))
      << runPanel.alarmStrip()->message()->text().toStdString();
  EXPECT_TRUE(bar.stateLabel()->text().contains(QStringLiteral("Alarm"))) << bar.stateLabel()->text().toStdString();
  // Reset, then Unlock, from the bar.
  ASSERT_TRUE(waitUntil([&] { return rig.session.problem().needsReset; }, 3000));
  EXPECT_FALSE(bar.unlockButton()->isEnabled());
  bar.resetButton()->click();
  ASSERT_TRUE(waitUntil([&] { return bar.unlockButton()->isEnabled(); }, 3000));
  bar.unlockButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.state() == grbl::MachineState::Idle; }, 5000));
  EXPECT_TRUE(runPanel.alarmStrip()->isHidden());
  rig.session.disconnectMachine();
  EXPECT_TRUE(bar.isHidden());
}

}  // namespace
}  // namespace fivebar
