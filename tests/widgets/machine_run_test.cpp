// SPDX-License-Identifier: GPL-3.0-or-later
// Running a planned job on the simulated machine through the run panel: to completion with the
// executed part coloured on the canvas, and resuming after the link drops (also from a fresh
// controller, as after a restart of the studio).
#include <gtest/gtest.h>

#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QToolButton>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "core/output/gcode.hpp"
#include "drivers/stream/job_progress.hpp"
#include "drivers/transport/simulated_transport.hpp"
#include "machine_test_support.hpp"
#include "widgets/document/preview_controller.hpp"
#include "session/run_controller.hpp"
#include "widgets/machine/run_layer.hpp"
#include "widgets/machine/override_controls.hpp"
#include "widgets/machine/run_panel.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

// A small drawing: a 30 mm square, a triangle and a circle, work frame.
Drawing testDrawing() {
  Drawing d;
  d.source = "machine-run-test";
  d.widthMm = d.heightMm = 40.0;
  Layer layer;
  layer.id = layer.name = "ink";
  Polyline square;
  square.points = {Vec2(0, 0), Vec2(30, 0), Vec2(30, 30), Vec2(0, 30)};
  square.closed = true;
  Polyline triangle;
  triangle.points = {Vec2(5, 5), Vec2(25, 5), Vec2(15, 22)};
  triangle.closed = true;
  Polyline circle;  // 90 segments: enough lines that a fault can strike mid-job
  for (int i = 0; i < 90; ++i) {
    const double a = 2.0 * kPi * i / 90.0;
    circle.points.push_back(Vec2(15.0 + 12.0 * std::cos(a), 15.0 + 12.0 * std::sin(a)));
  }
  circle.closed = true;
  layer.paths = {square, triangle, circle};
  d.layers.push_back(layer);
  return d;
}

struct RunRig : MachineRig {
  RunRig() : run(inputs, session) {
    run.setJobDirectory(dir.path());
    Placement placement;
    placement.centerMm = Vec2(0.0, 170.0);
    doc.replaceDrawing(testDrawing(), QStringLiteral("square.svg"), placement);
    preview.replanNow();
  }
  bool planned() {
    return waitUntil([this] { return !preview.busy() &&
                                     preview.result().status == widgets::PreviewStatus::Planned; },
                     30000);
  }
  QTemporaryDir dir;
  session::RunController run;
};

TEST(RunPanel, RunsThePlannedJobToCompletionAndColoursWhatIsDone) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(25.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  widgets::RunLayer layer(rig.run, rig.view);
  ASSERT_TRUE(panel.startButton()->isEnabled());
  // Connected before Start: a fast run may end while the test waits for its first strokes.
  bool finished = false, ok = false;
  QObject::connect(&rig.run, &session::RunController::finished, [&](bool success, const QString&) {
    finished = true;
    ok = success;
  });
  panel.startButton()->click();
  ASSERT_TRUE(rig.run.running()) << rig.run.lastMessage().toStdString();
  EXPECT_TRUE(rig.session.jobActive());
  EXPECT_TRUE(panel.stopButton()->isEnabled());
  // Hold becomes available once the stream has synchronised and runs.
  EXPECT_TRUE(waitUntil([&] { return panel.holdButton()->isEnabled(); }, 10000));
  EXPECT_EQ(rig.run.state(), stream::RunState::Running);
  EXPECT_FALSE(panel.startButton()->isEnabled());
  ASSERT_GT(layer.totalSegments(), 0u);
  // Half-way the canvas shows part of the job as done, not all of it.
  ASSERT_TRUE(waitUntil([&] { return layer.doneSegments() > 0; }, 30000));
  ASSERT_TRUE(waitUntil([&] { return finished; }, 45000));
  EXPECT_TRUE(ok) << rig.run.lastMessage().toStdString();
  EXPECT_EQ(rig.run.state(), stream::RunState::Finished);
  EXPECT_EQ(panel.progressBar()->value(), panel.progressBar()->maximum());
  EXPECT_EQ(layer.doneSegments(), layer.totalSegments());
  EXPECT_FALSE(rig.session.jobActive());
  // The machine ends at the job's last target, within a step; the job file stays, the progress
  // file is gone.
  const stream::JobLine& last = rig.run.job()->lines.back();
  const JointAngles q = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(q.theta1), last.endDeg[0], 1.0 / rig.doc.profile().motors.stepsPerDeg1);
  EXPECT_NEAR(degFromRad(q.theta2), last.endDeg[1], 1.0 / rig.doc.profile().motors.stepsPerDeg2);
  EXPECT_TRUE(QFile::exists(rig.run.jobPath()));
  EXPECT_FALSE(rig.run.savedProgress().has_value());
  // The simulated machine drew strokes.
  ASSERT_NE(rig.session.simulatedTransport(), nullptr);
  EXPECT_GE(rig.session.simulatedTransport()->machine().strokes().size(), 2u);
}

TEST(RunPanel, ResumesAfterTheLinkDropsAlsoAfterARestart) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  // The link drops after 60 lines: the run ends, its progress is saved beside the job.
  ASSERT_TRUE(rig.connect(25.0, sim::Fault{sim::FaultKind::DropAfter, 60}));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(rig.run.start());
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 45000));
  EXPECT_NE(rig.run.state(), stream::RunState::Finished);
  ASSERT_TRUE(waitUntil([&] { return !rig.session.isConnected(); }, 5000));
  const auto saved = rig.run.savedProgress();
  ASSERT_TRUE(saved.has_value());
  EXPECT_GT(saved->lastAckedLine, 0);
  EXPECT_LT(saved->lastCompletedLine, saved->totalLines + 100);

  // "Restart": a new controller and panel on the same job folder offer the resume.
  session::RunController restarted(rig.inputs, rig.session);
  restarted.setJobDirectory(rig.dir.path());
  widgets::RunPanel panel(restarted, rig.view, rig.session);
  ASSERT_TRUE(restarted.savedProgress().has_value());
  EXPECT_FALSE(panel.resumeButton()->isHidden());
  EXPECT_FALSE(panel.resumeButton()->isEnabled());  // not connected yet
  ASSERT_TRUE(rig.connect(25.0));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(waitUntil([&] { return panel.resumeButton()->isEnabled(); }, 3000));
  panel.resumeButton()->click();
  ASSERT_TRUE(restarted.running()) << restarted.lastMessage().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !restarted.running(); }, 45000));
  EXPECT_EQ(restarted.state(), stream::RunState::Finished) << restarted.lastMessage().toStdString();
  EXPECT_FALSE(restarted.savedProgress().has_value());
  const stream::JobLine& last = restarted.job()->lines.back();
  const JointAngles q = *rig.session.motorAngles();
  EXPECT_NEAR(degFromRad(q.theta1), last.endDeg[0], 1.0 / rig.doc.profile().motors.stepsPerDeg1);
  EXPECT_NEAR(degFromRad(q.theta2), last.endDeg[1], 1.0 / rig.doc.profile().motors.stepsPerDeg2);
}


TEST(RunPanel, StartExplainsTheBoardsSettingsMismatchFirst) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(25.0));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));
  EXPECT_TRUE(rig.session.settingDifferences().empty());
  // Someone lowered motor 1's steps per degree on the board: the arms would turn wrongly.
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("$100=10")));
  ASSERT_TRUE(rig.waitIdle());
  rig.session.readBoardSettings();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.settingDifferences().empty(); }, 5000));
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  bool opened = false;
  panel.setOpenSettings([&] { opened = true; });
  QString text;
  test::answerBox(QStringLiteral("settingsMismatch"), QString(), QMessageBox::Cancel, &text);
  panel.startButton()->click();
  EXPECT_TRUE(text.contains(QStringLiteral("$100"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("steps per degree"))) << text.toStdString();
  EXPECT_FALSE(rig.run.running());
  // "Write the profile's settings..." opens the settings dialog instead of starting.
  test::answerBox(QStringLiteral("settingsMismatch"), QStringLiteral("writeSettings"));
  panel.startButton()->click();
  EXPECT_TRUE(opened);
  EXPECT_FALSE(rig.run.running());
  // Put it back: Start runs without a question.
  ASSERT_TRUE(rig.session.sendLine(QStringLiteral("$100=%1").arg(rig.doc.profile().motors.stepsPerDeg1, 0, 'f', 4)));
  ASSERT_TRUE(rig.waitIdle());
  rig.session.readBoardSettings();
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown() && !rig.session.readingBoardSettings() &&
                                     rig.session.settingDifferences().empty(); }, 5000));
  panel.startButton()->click();
  EXPECT_TRUE(rig.run.running()) << rig.run.lastMessage().toStdString();
  rig.run.stop();
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 20000));
}

// A saved run is offered by name; a new Start asks before it discards it (Cancel keeps it).
TEST(RunPanel, StartAsksBeforeItDiscardsTheSavedRun) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(25.0));
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));
  const std::string gcode = writeGcode(*rig.preview.result().job, rig.doc.profile());
  {
    QFile file(rig.run.jobPath());
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(gcode.data(), qint64(gcode.size()));
  }
  stream::JobProgress progress;
  progress.jobHash = stream::sha256Hex(gcode);
  progress.totalLines = 10;
  progress.lastAckedLine = progress.lastCompletedLine = 5;
  progress.reason = "stopped by the user";
  const std::string progressPath = stream::progressPathFor(rig.run.jobPath().toStdString());
  ASSERT_EQ(stream::saveProgress(progress, progressPath), "");
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  EXPECT_FALSE(panel.resumeLabel()->isHidden());
  EXPECT_TRUE(panel.resumeLabel()->text().contains(QStringLiteral("\"square\""))) << panel.resumeLabel()->text().toStdString();
  QString text;
  test::answerBox(QStringLiteral("discardResumeQuestion"), QString(), QMessageBox::Cancel, &text);
  panel.startButton()->click();
  EXPECT_TRUE(text.contains(QStringLiteral("discards this saved progress"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("square"))) << text.toStdString();
  EXPECT_FALSE(rig.run.running());
  EXPECT_TRUE(QFile::exists(QString::fromStdString(progressPath))) << "Cancel keeps the saved run";
  test::answerBox(QStringLiteral("discardResumeQuestion"), QStringLiteral("discardAndStart"));
  panel.startButton()->click();
  EXPECT_TRUE(rig.run.running()) << rig.run.lastMessage().toStdString();
  rig.run.stop();
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 20000));
}

TEST(RunPanel, EtaFollowsThePlanAndStandsStillOnHold) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(2.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  ASSERT_TRUE(rig.run.start());
  const double total = rig.run.etaS();
  ASSERT_GT(total, 0.0);
  // The job's planned time and the G-code time line agree within a few percent.
  const double planned = rig.preview.result().job->summary.estimatedTimeS;
  EXPECT_NEAR(total, planned, 0.1 * planned + 1.0);
  ASSERT_TRUE(waitUntil([&] { return rig.run.snapshot().lastCompleted && *rig.run.snapshot().lastCompleted > 20; }, 30000));
  rig.run.hold();
  ASSERT_TRUE(waitUntil([&] { return rig.run.state() == stream::RunState::Held; }, 10000));
  waitUntil([] { return false; }, 2 * session::RunController::kRefreshMs);  // the held snapshot
  const double held = rig.run.etaS();
  EXPECT_LT(held, total);
  EXPECT_TRUE(panel.etaLabel()->text().contains(QStringLiteral("hold"))) << panel.etaLabel()->text().toStdString();
  const QString label = panel.etaLabel()->text();
  waitUntil([] { return false; }, 1200);
  EXPECT_EQ(rig.run.etaS(), held);
  EXPECT_EQ(panel.etaLabel()->text(), label);
  // One counter: the progress bar counts the executed job lines.
  EXPECT_TRUE(panel.progressBar()->text().contains(rig.run.progressText())) << panel.progressBar()->text().toStdString();
  rig.run.continueRun();
  ASSERT_TRUE(waitUntil([&] { return rig.run.etaS() < held; }, 20000));
  rig.run.stop();
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 20000));
}

// The override buttons send GRBL's real-time bytes through the session; the panel shows what
// the board reports, and the ETA follows it.
TEST(RunPanel, OverridesShowTheReportedValuesAndTheEtaFollowsThem) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(2.0));
  ASSERT_TRUE(rig.waitIdle());
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  widgets::OverrideControls* ov = panel.overrideControls();
  QAbstractButton* minus10 = ov->button(grbl::OverrideCommand::FeedMinus10);
  EXPECT_FALSE(minus10->isEnabled()) << "only during a run";
  ASSERT_TRUE(rig.run.start());
  ASSERT_TRUE(waitUntil([&] { return rig.run.snapshot().lastCompleted && *rig.run.snapshot().lastCompleted > 10; }, 30000));
  EXPECT_TRUE(minus10->isEnabled());
  EXPECT_FALSE(minus10->shortcut().isEmpty());
  const double before = rig.run.etaS();
  for (int i = 0; i < 5; ++i) {
    minus10->click();
    waitUntil([] { return false; }, 30);
  }
  ov->button(grbl::OverrideCommand::RapidQuarter)->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.reportedOverrides() == grbl::MotionOverrides{50, 25}; }, 5000));
  waitUntil([] { return false; }, 2 * session::RunController::kRefreshMs);
  EXPECT_EQ(ov->feedLabel()->text(), QStringLiteral("50 %"));
  EXPECT_EQ(ov->rapidLabel()->text(), QStringLiteral("25 %"));
  EXPECT_GT(rig.run.etaS(), 1.3 * before) << "the time left grows with a slower feed";
  ov->button(grbl::OverrideCommand::FeedReset)->click();
  ov->button(grbl::OverrideCommand::RapidFull)->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.reportedOverrides() == grbl::MotionOverrides{100, 100}; }, 5000));
  rig.run.stop();
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 20000));
  EXPECT_FALSE(minus10->isEnabled());
}

TEST(RunPanel, AlarmThenUnlockThenResumeFinishesAndNewJobsClearTheOldOverlay) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  // ALARM:1 strikes mid-job (after 50 lines the board received).
  ASSERT_TRUE(rig.connect(25.0, sim::Fault{sim::FaultKind::AlarmAfter, 50}));
  ASSERT_TRUE(rig.setReference());
  ASSERT_TRUE(rig.waitIdle());
  widgets::RunPanel panel(rig.run, rig.view, rig.session);
  widgets::RunLayer layer(rig.run, rig.view);
  ASSERT_TRUE(rig.run.start());
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 45000));
  EXPECT_NE(rig.run.state(), stream::RunState::Finished);
  // The alarm's explanation is in the banner; the run panel says what to do, in GUI words.
  EXPECT_FALSE(rig.run.lastMessage().contains(QStringLiteral("--resume"))) << rig.run.lastMessage().toStdString();
  EXPECT_TRUE(rig.run.lastMessage().contains(QStringLiteral("Resume"))) << rig.run.lastMessage().toStdString();
  ASSERT_TRUE(rig.run.savedProgress().has_value());
  EXPECT_TRUE(panel.resumeLabel()->text().contains(QStringLiteral("square"))) << panel.resumeLabel()->text().toStdString();
  // Reset (the board demands it after ALARM:1), unlock, resume: the job finishes.
  QStringList consoleLog;
  QObject::connect(&rig.session, &session::MachineSession::consoleLine, [&](const QString& t, session::ConsoleKind) { consoleLog << t; });
  rig.session.softReset();
  // The reset's banner discards whatever was sent before it: unlock after it.
  ASSERT_TRUE(waitUntil([&] { return consoleLog.join(QLatin1Char('\n')).contains(QStringLiteral("The board reset")); }, 5000));
  ASSERT_TRUE(waitUntil([&] { return !rig.session.problem().needsReset; }, 5000));
  rig.session.unlock();
  ASSERT_TRUE(waitUntil([&] { return rig.session.state() == grbl::MachineState::Idle; }, 5000));
  ASSERT_TRUE(rig.setReference()) << consoleLog.join(QStringLiteral(" | ")).toStdString();  // the hard-limit alarm lost the position
  ASSERT_TRUE(rig.waitIdle());
  ASSERT_TRUE(waitUntil([&] { return panel.resumeButton()->isEnabled(); }, 5000)) << rig.run.resumeOffer().toStdString();
  panel.resumeButton()->click();
  ASSERT_TRUE(rig.run.running()) << rig.run.lastMessage().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !rig.run.running(); }, 45000));
  EXPECT_EQ(rig.run.state(), stream::RunState::Finished) << rig.run.lastMessage().toStdString();
  EXPECT_EQ(layer.doneSegments(), layer.totalSegments());
  // A new placement: the finished run's overlay and status go.
  Placement moved = rig.doc.placement();
  moved.centerMm += Vec2(5.0, 0.0);
  rig.doc.setPlacement(moved);
  EXPECT_EQ(rig.run.job(), nullptr);
  EXPECT_EQ(layer.doneSegments(), 0u);
  EXPECT_TRUE(rig.run.lastMessage().isEmpty());
}

// After "set reference pose" the board checks its soft limits in machine coordinates, shifted
// against the drawing's: Start refuses a job the board would stop with ALARM:2, before any line
// is sent, and says why.
TEST(RunPanel, StartRefusesAJobTheBoardsSoftLimitsWouldStop) {
  RunRig rig;
  ASSERT_TRUE(rig.planned()) << rig.preview.result().message.toStdString();
  ASSERT_TRUE(rig.connect(25.0));
  ASSERT_TRUE(rig.waitIdle());
  // The board: homing and soft limits on, with a travel of 1 deg per motor below the machine's
  // zero (the pose the reference was declared at: the home pose).
  for (const char* line : {"$22=1", "$20=1", "$130=1", "$131=1"})
    ASSERT_TRUE(rig.session.link()->protocol().enqueue(line).ok());
  ASSERT_TRUE(rig.waitIdle());
  rig.session.readBoardSettings();
  ASSERT_TRUE(waitUntil([&] {
    const auto& b = rig.session.boardSettings();
    return !rig.session.readingBoardSettings() && b && b->count(131) && b->at(131) == 1.0 && b->at(20) == 1.0;
  }, 5000));
  ASSERT_TRUE(rig.session.workOffsetDeg().has_value());
  // The stream refuses before a byte: first for the settings that differ from the profile...
  const auto refusal = [&](bool resume) {
    QString why;
    bool finished = false;
    auto c = QObject::connect(&rig.run, &session::RunController::finished, [&](bool, const QString&) { finished = true; });
    const bool launched = resume ? rig.run.resume(&why) : rig.run.start(&why);
    if (launched) waitUntil([&] { return finished; }, 10000);
    QObject::disconnect(c);
    EXPECT_FALSE(rig.run.running());
    return rig.run.lastMessage();
  };
  const QString settings = refusal(false);
  EXPECT_TRUE(settings.contains(QStringLiteral("$130"))) << settings.toStdString();
  // ...and with the expert's "Start anyway", for the board's soft limits, in the user's words.
  rig.run.ignoreSettingsOnce();
  const QString why = refusal(false);
  EXPECT_TRUE(why.contains(QStringLiteral("ALARM:2"))) << why.toStdString();
  EXPECT_TRUE(why.contains(QStringLiteral("machine coordinates"))) << why.toStdString();
  EXPECT_TRUE(why.startsWith(QStringLiteral("Not started"))) << why.toStdString();
  waitUntil([] { return false; }, 300);
  EXPECT_NE(rig.session.state(), grbl::MachineState::Alarm) << "nothing was sent";
  // Resume checks the rest of a saved run the same way: the job file and a progress after its
  // first line.
  {
    const std::string gcode = writeGcode(*rig.preview.result().job, rig.doc.profile());
    QFile file(rig.run.jobPath());
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(gcode.data(), qint64(gcode.size()));
    file.close();
    stream::JobProgress progress;
    progress.jobHash = stream::sha256Hex(gcode);
    progress.totalLines = 10;
    progress.lastAckedLine = progress.lastCompletedLine = 1;
    progress.reason = "stopped by the user";
    ASSERT_EQ(stream::saveProgress(progress, stream::progressPathFor(rig.run.jobPath().toStdString())), "");
    ASSERT_TRUE(rig.run.canResume());
    rig.run.ignoreSettingsOnce();
    const QString resumeWhy = refusal(true);
    EXPECT_TRUE(resumeWhy.contains(QStringLiteral("ALARM:2"))) << resumeWhy.toStdString();
  }
  // With the profile's travel and soft limits off again, the same job starts.
  for (const char* line : {"$20=0"}) ASSERT_TRUE(rig.session.link()->protocol().enqueue(line).ok());
  ASSERT_TRUE(rig.waitIdle());
  rig.session.readBoardSettings();
  ASSERT_TRUE(waitUntil([&] {
    const auto& b = rig.session.boardSettings();
    return !rig.session.readingBoardSettings() && b && b->at(20) == 0.0;
  }, 5000));
  rig.run.ignoreSettingsOnce();  // $22, $130, $131 still differ from the profile
  QString started;
  EXPECT_TRUE(rig.run.start(&started)) << started.toStdString();
  rig.run.stop();
  waitUntil([&] { return !rig.run.running(); }, 10000);
}

}  // namespace
}  // namespace fivebar
