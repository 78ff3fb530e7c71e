// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_machine_screenshots OUTDIR: screenshots of the studio's machine panels for the docs,
// taken from the real main window driving the built-in simulated machine (not a test; run it
// under xvfb-run -a -s "-screen 0 1600x1000x24"):
//   machine-pose-unknown.png  a board fresh from power-up: position unknown, no linkage drawn
//   machine-start-refused.png ... and Start refuses, saying why and what to do
//   machine-run.png      the demo job running, the executed part coloured on the canvas
//   run-overrides.png    the Run panel during the run: feed 120 %, rapid 50 % as the board reports
//   machine-goto.png     a go-to previewed on the canvas, waiting for confirmation
//   machine-frame.png    Frame: the planned job's outline traced pen up (jog panel), and the
//                        recovery bar (Reset, Unlock, Set reference pose) in the status bar
//   machine-alarm.png    an alarm banner with its way out, and the profile editor's inline message
//   machine-quit-while-running.png  quitting while a job runs asks first
//   machine-reference-question.png  "Set reference pose" asks first
//   machine-settings-warning.png    the board's $ settings differ from the profile (machine panel)
//   machine-settings-mismatch.png   ... and Start explains it before the machine moves
#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QTimer>
#include <QToolButton>
#include "drivers/stream/job_progress.hpp"
#include "widgets/machine/machine_dialogs.hpp"
#include "widgets/machine/override_controls.hpp"
#include "widgets/machine/run_panel.hpp"
#include <QPushButton>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "app/studio/main_window.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/panels/profile_editor.hpp"

namespace {

using fivebar::test::grab;
using fivebar::test::settle;
using fivebar::test::waitUntil;

// Grabs the next modal message box with this object name into path, then cancels it.
void grabNextBox(const QString& name, const QString& path, int tries = 300) {
  QTimer::singleShot(20, [=] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box == nullptr || box->objectName() != name) {
      if (tries > 0) grabNextBox(name, path, tries - 1);
      return;
    }
    QTimer::singleShot(300, [box, path] {
      const bool ok = box->grab().save(path);
      std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
      if (QAbstractButton* cancel = box->button(QMessageBox::Cancel)) cancel->click();
      else box->reject();
    });
  });
}

void raiseDock(fivebar::studio::MainWindow& window, const char* name) {
  if (auto* dock = window.dock(QString::fromLatin1(name))) dock->raise();
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: fivebar_machine_screenshots OUTDIR\n");
    return 2;
  }
  const QString outDir = QString::fromLocal8Bit(argv[1]);
  QDir().mkpath(outDir);
  QTemporaryDir settingsDir;  // a fresh dock layout, not the user's
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QApplication::setApplicationName(QStringLiteral("FiveBar Studio"));

  using namespace fivebar;
  studio::MainWindow window(*preset("maker-plotter"));
  window.resize(1600, 1000);
  window.show();
  session::MachineSide* machine = &window.machine();
  widgets::MachinePanels& panels = window.machinePanels();
  machine->run().setJobDirectory(settingsDir.filePath(QStringLiteral("jobs")));
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  if (!demo.open(QIODevice::ReadOnly)) return 1;
  window.importer().setInteractive(false);
  window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  // A board fresh from power-up, as a real one: its position is not known.
  session::MachineSession& session = machine->session();
  QString connectError;
  session.connectSimulated(6.0, {}, &connectError);
  const bool ready = waitUntil([&] {
    return window.preview().result().status == widgets::PreviewStatus::Planned && !window.preview().busy() &&
           session.state() == grbl::MachineState::Idle && session.poseDoubt() != grbl::PoseDoubt::NotYetRead;
  }, 60000);
  if (!ready) {
    std::fprintf(stderr, "the demo job did not plan or the machine did not report\n");
    return 1;
  }
  int status = 0;
  // 0. The unknown position: no linkage drawn, the banner and the panel say what to do; Start
  // refuses and says why.
  raiseDock(window, "dockMachine");
  if (!grab(window, outDir + QStringLiteral("/machine-pose-unknown.png"))) status = 1;
  raiseDock(window, "dockRun");
  panels.runPanel()->startButton()->click();
  if (!grab(window, outDir + QStringLiteral("/machine-start-refused.png"))) status = 1;
  session.setReferencePose();
  waitUntil([&] { return session.poseKnown() && session.canJog(); }, 10000);
  // 1. A run in progress.
  if (!machine->run().start()) return 1;
  waitUntil([&] {
    const auto& s = machine->run().snapshot();
    return s.totalLines > 0 && s.linesCompleted * 100 >= s.totalLines * 45;
  }, 120000);
  if (!grab(window, outDir + QStringLiteral("/machine-run.png"))) status = 1;
  // 1a. Overrides during the run: two clicks on +10 % and one on rapid 50 %; the panel shows
  // what the board reports.
  {
    widgets::OverrideControls* ov = panels.runPanel()->overrideControls();
    for (int i = 0; i < 2; ++i) {
      ov->button(grbl::OverrideCommand::FeedPlus10)->click();
      settle(60);
    }
    ov->button(grbl::OverrideCommand::RapidHalf)->click();
    waitUntil([&] { return session.reportedOverrides() == grbl::MotionOverrides{120, 50}; }, 5000);
    QDockWidget* dock = window.dock(QStringLiteral("dockRun"));
    if (dock != nullptr) window.resizeDocks({dock}, {460}, Qt::Horizontal);
    if (dock == nullptr || !grab(*dock, outDir + QStringLiteral("/run-overrides.png"), 600)) status = 1;
    ov->button(grbl::OverrideCommand::FeedReset)->click();
    ov->button(grbl::OverrideCommand::RapidFull)->click();
  }
  // 1b. Quitting while it runs asks first ("Keep running" is the default; the grab rejects it).
  grabNextBox(QStringLiteral("quitWhileRunning"), outDir + QStringLiteral("/machine-quit-while-running.png"));
  window.close();
  if (!window.isVisible() || !machine->run().running()) status = 1;
  machine->run().stop();
  waitUntil([&] { return !machine->run().running(); }, 30000);
  waitUntil([&] { return session.state() == grbl::MachineState::Idle && session.jogSettled(); }, 10000);

  // 2a. The reference pose is asked for; the board's settings differ from the profile.
  grabNextBox(QStringLiteral("referencePoseQuestion"), outDir + QStringLiteral("/machine-reference-question.png"));
  widgets::requestReferencePose(&window, session.profile(), session);
  QFile::remove(QString::fromStdString(stream::progressPathFor(machine->run().jobPath().toStdString())));
  session.sendLine(QStringLiteral("$100=10"));
  waitUntil([&] { return session.state() == grbl::MachineState::Idle; }, 5000);
  settle(300);
  session.readBoardSettings();
  waitUntil([&] { return !session.settingDifferences().empty(); }, 5000);
  raiseDock(window, "dockMachine");
  if (!grab(window, outDir + QStringLiteral("/machine-settings-warning.png"))) status = 1;
  raiseDock(window, "dockRun");
  grabNextBox(QStringLiteral("settingsMismatch"), outDir + QStringLiteral("/machine-settings-mismatch.png"));
  panels.runPanel()->startButton()->click();
  session.sendLine(QStringLiteral("$100=%1").arg(session.profile().motors.stepsPerDeg1, 0, 'f', 4));
  waitUntil([&] { return session.state() == grbl::MachineState::Idle; }, 5000);

  // 2. A go-to previewed on the canvas.
  raiseDock(window, "dockJog");
  widgets::JogPanel* jog = panels.jogPanel();
  jog->goToButton()->setChecked(true);
  if (const auto pen = session.penMm()) jog->goToTool().pick(QPointF(pen->x() - 45.0, pen->y() - 60.0));
  if (!grab(window, outDir + QStringLiteral("/machine-goto.png"))) status = 1;
  jog->goToButton()->setChecked(false);
  waitUntil([&] { return session.state() == grbl::MachineState::Idle && session.jogSettled(); }, 10000);

  // 2b. Frame: the demo job's outline traced pen up, the recovery bar in the status bar.
  waitUntil([&] { return jog->frameButton()->isEnabled(); }, 10000);
  jog->frameButton()->click();
  // Grabbed once the pen is on the outline (the demo's circle), past the travel to its corner.
  const Vec2 centre(window.document().placement().centerMm.x(), window.document().placement().centerMm.y());
  waitUntil([&] {
    const auto pen = session.penMm();
    return session.state() == grbl::MachineState::Run && pen && (*pen - centre).norm() > 30.0;
  }, 10000);
  if (!grab(window, outDir + QStringLiteral("/machine-frame.png"), 60)) status = 1;
  waitUntil([&] { return session.state() == grbl::MachineState::Idle && session.jogSettled(); }, 30000);

  // 3. An alarm (a hard limit tripped on the first line) and a bad profile value.
  session.disconnectMachine();
  QString error;
  session.connectSimulated(6.0, sim::Fault{sim::FaultKind::AlarmAfter, 0}, &error);
  waitUntil([&] { return session.state() != grbl::MachineState::Unknown; }, 5000);
  session.sendLine(QStringLiteral("G4P0.01"));
  waitUntil([&] { return session.problem().kind == session::MachineProblem::Kind::Alarm; }, 5000);
  raiseDock(window, "dockMachine");
  raiseDock(window, "dockProfile");
  if (auto* editor = panels.profileEditor()) {
    if (auto* a1 = editor->numberField("geometry.a1")) a1->setValue(0.0);
  }
  if (!grab(window, outDir + QStringLiteral("/machine-alarm.png"))) status = 1;
  // 4. Quitting while a job runs is asked about.
  session.disconnectMachine();
  return status;
}
