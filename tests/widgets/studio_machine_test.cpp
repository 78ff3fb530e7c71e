// SPDX-License-Identifier: GPL-3.0-or-later
// The machine side inside the whole main window, offscreen: the quit prompt while a job runs,
// the canvas linkage following the connected machine with the simulation as a ghost, and an
// import error never covered by the import's progress dialog; --port at start.
#include <gtest/gtest.h>
#include <pty.h>
#include <unistd.h>

#include <QAbstractButton>
#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <functional>

#include "app/studio/file_actions.hpp"
#include "app/studio/main_window.hpp"
#include "app/studio/startup.hpp"
#include "drivers/jog/jog.hpp"
#include "machine_test_support.hpp"
#include "session/machine_side.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/machine/port_box.hpp"

namespace fivebar {
namespace {

using test::answerBox;
using test::waitUntil;

constexpr int kWaitMs = 60000;

// A window with the demo drawing planned and the simulated machine connected, idle, at the
// reference (home) pose.
struct StudioWithMachine {
  explicit StudioWithMachine(double speedup) : window(*preset("maker-plotter")) {
    window.resize(1400, 900);
    window.show();
    window.machine().run().setJobDirectory(jobs.path());
    window.files().setAsk([](const QString&) { return QMessageBox::Discard; });
    window.importer().setInteractive(false);
    QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
    if (demo.open(QIODevice::ReadOnly))
      window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
    window.machine().connectSimulated(speedup);
  }
  bool ready() {
    session::MachineSession& s = window.machine().session();
    const MachineProfile& p = window.document().profile();
    return waitUntil([&] {
      const auto q = s.motorAngles();
      return window.document().hasDrawing() && !window.preview().busy() &&
             window.preview().result().status == widgets::PreviewStatus::Planned &&
             s.state() == grbl::MachineState::Idle && s.jogSettled() && q &&
             std::abs(q->theta1 - p.homeAngles.theta1) < 1e-3 && std::abs(q->theta2 - p.homeAngles.theta2) < 1e-3;
    }, kWaitMs);
  }
  QTemporaryDir jobs;
  studio::MainWindow window;
};

TEST(StudioMachine, QuitWhileRunningAsksAndStopsOnlyWhenTold) {
  StudioWithMachine studio(1.0);  // real time: the demo job runs for minutes
  ASSERT_TRUE(studio.ready());
  session::RunController& run = studio.window.machine().run();
  ASSERT_TRUE(run.start());
  ASSERT_TRUE(waitUntil([&] { return run.snapshot().linesCompleted > 0; }, 20000));

  // Keep running: the window stays and the job goes on.
  QString asked;
  answerBox(QStringLiteral("quitWhileRunning"), QStringLiteral("keepRunning"), QMessageBox::Cancel, &asked);
  EXPECT_FALSE(studio.window.close());
  EXPECT_TRUE(studio.window.isVisible());
  EXPECT_TRUE(asked.contains(QStringLiteral("fivebar-demo"))) << asked.toStdString();
  const std::size_t doneBefore = run.snapshot().linesCompleted;
  ASSERT_TRUE(run.running());
  EXPECT_TRUE(waitUntil([&] { return run.snapshot().linesCompleted > doneBefore; }, 20000))
      << "the job should still be streaming";

  // Hold, stop and quit: the run ends (its progress saved for Resume) and the window closes.
  answerBox(QStringLiteral("quitWhileRunning"), QStringLiteral("stopAndQuit"));
  EXPECT_TRUE(studio.window.close());
  EXPECT_FALSE(studio.window.isVisible());
  EXPECT_FALSE(run.running());
  EXPECT_TRUE(run.savedProgress().has_value()) << "the stopped run can be resumed later";
}

// The quit question follows the job: when the job ends while it is open, it no longer says a
// job is running, and Quit quits without a stop.
TEST(StudioMachine, TheQuitQuestionUpdatesWhenTheJobEnds) {
  StudioWithMachine studio(1.0);
  ASSERT_TRUE(studio.ready());
  session::RunController& run = studio.window.machine().run();
  ASSERT_TRUE(run.start());
  ASSERT_TRUE(waitUntil([&] { return run.snapshot().linesCompleted > 0; }, 20000));
  QString before, after, title, quitText;
  bool stopped = false;
  int polls = 0;
  QTimer probe;
  QObject::connect(&probe, &QTimer::timeout, [&] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box == nullptr || box->objectName() != QLatin1String("quitWhileRunning")) return;
    if (!stopped) {
      before = box->text();
      stopped = true;
      run.stop();  // the job ends while the question is open
      return;
    }
    // Until the job has ended and the question has had its chance to say so (20 s at most).
    if ((run.running() || !box->text().contains(QStringLiteral("has ended"))) && ++polls < 1000) return;
    after = box->text();
    title = box->windowTitle();
    auto* quit = box->findChild<QAbstractButton*>(QStringLiteral("stopAndQuit"));
    quitText = quit->text();
    probe.stop();
    quit->click();
  });
  probe.start(20);
  EXPECT_TRUE(studio.window.close());
  EXPECT_TRUE(before.contains(QStringLiteral("is drawing"))) << before.toStdString();
  EXPECT_FALSE(after.contains(QStringLiteral("is drawing"))) << after.toStdString();
  EXPECT_TRUE(after.contains(QStringLiteral("has ended"))) << after.toStdString();
  EXPECT_NE(title, QStringLiteral("A job is running"));
  EXPECT_EQ(quitText, QStringLiteral("Quit"));
  EXPECT_FALSE(run.running());
}

TEST(StudioMachine, QuitWithoutAJobRunningDoesNotAsk) {
  StudioWithMachine studio(4.0);
  ASSERT_TRUE(studio.ready());
  bool asked = false;
  QTimer probe;
  QObject::connect(&probe, &QTimer::timeout, [&] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      asked = true;
      box->reject();
    }
  });
  probe.start(5);
  EXPECT_TRUE(studio.window.close());
  EXPECT_FALSE(asked);
}

TEST(StudioMachine, CanvasLinkageFollowsTheMachineAndTheSimulationIsAGhost) {
  StudioWithMachine studio(8.0);
  ASSERT_TRUE(studio.ready());
  session::MachineSession& s = studio.window.machine().session();
  widgets::MachineLayer& layer = studio.window.machineLayer();
  const MachineProfile& p = studio.window.document().profile();
  // Turn motor 2 by -6 deg: the canvas linkage follows the reported pose, not the simulation's.
  ASSERT_TRUE(s.sendJog(jog::planMotorJog(p, *s.motorAngles(), 2, -6.0, 20.0 * 60.0)));
  ASSERT_TRUE(waitUntil([&] { return !s.jogSettled(); }, 2000));
  ASSERT_TRUE(waitUntil([&] { return s.state() == grbl::MachineState::Idle && s.jogSettled(); }, 10000));
  const JointAngles q = *s.motorAngles();
  EXPECT_NEAR(q.theta2, p.homeAngles.theta2 - radFromDeg(6.0), 1e-3);
  ASSERT_TRUE(waitUntil([&] { return layer.pose() && std::abs(layer.pose()->q.theta2 - q.theta2) < 1e-9; }, 2000));
  EXPECT_NEAR(layer.pose()->q.theta1, q.theta1, 1e-9);
  EXPECT_FALSE(layer.ghost().has_value()) << "no simulation used yet";
  // Scrubbing the simulation shows its pose as a ghost; the machine's pose stays the one drawn.
  widgets::SimulationController& sim = studio.window.simulation();
  ASSERT_GT(sim.durationS(), 1.0);
  sim.setTimeS(0.5 * sim.durationS());
  ASSERT_TRUE(waitUntil([&] { return layer.ghost().has_value(); }, 2000));
  EXPECT_GT(std::abs(layer.ghost()->q.theta2 - q.theta2) + std::abs(layer.ghost()->q.theta1 - q.theta1), 1e-3)
      << "mid-drawing the simulation stands elsewhere than the machine";
  EXPECT_NEAR(layer.pose()->q.theta2, q.theta2, 1e-9);
  // Disconnected: the simulation's pose is the linkage again, no ghost.
  s.disconnectMachine();
  ASSERT_TRUE(waitUntil([&] { return !layer.ghost().has_value(); }, 2000));
  EXPECT_GT(std::abs(layer.pose()->q.theta2 - q.theta2) + std::abs(layer.pose()->q.theta1 - q.theta1), 1e-3);
}

// The import's progress dialog is gone before the error box opens: the box is the active modal
// window and no progress dialog shows up while it is open (its minimum-duration timer would show
// it over the box otherwise).
TEST(StudioMachine, ImportErrorIsNotCoveredByTheProgressDialog) {
  QWidget parent;
  parent.resize(600, 400);
  parent.show();
  widgets::StudioDocument doc(*preset("maker-plotter"));
  widgets::ImportController importer(doc, &parent);
  importer.setInteractive(true);
  QString boxText;
  bool boxActive = false;
  int progressVisible = -1;
  std::function<void(int)> answer = [&](int tries) {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (box == nullptr) {
      if (tries > 0) QTimer::singleShot(10, [&, tries] { answer(tries - 1); });
      return;
    }
    // Look again after the dialog's minimum duration (300 ms) has passed under the open box.
    QTimer::singleShot(600, [&, box] {
      boxActive = QApplication::activeModalWidget() == box;
      boxText = box->text();
      progressVisible = 0;
      for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<QProgressDialog*>(w)) progressVisible += d->isVisible();
      for (QProgressDialog* d : parent.findChildren<QProgressDialog*>()) progressVisible += d->isVisible();
      box->accept();
    });
  };
  QTimer::singleShot(0, [&] { answer(1000); });
  QSignalSpy finished(&importer, &widgets::ImportController::finished);
  importer.openData(QByteArray("<svg this is not xml"), QStringLiteral("broken.svg"));
  ASSERT_TRUE(waitUntil([&] { return finished.count() > 0; }, kWaitMs));
  EXPECT_FALSE(finished.front().at(0).toBool());
  EXPECT_TRUE(boxActive) << "the error box is the window in front";
  EXPECT_EQ(progressVisible, 0) << "a progress dialog shows over the error";
  EXPECT_FALSE(boxText.isEmpty());
  // And none appears afterwards either.
  waitUntil([] { return false; }, 500);
  for (QProgressDialog* d : parent.findChildren<QProgressDialog*>()) EXPECT_FALSE(d->isVisible());
}

// fivebar-studio --port PORT [--baud N]: the window's machine panel connects PORT once the event
// loop runs, as its Connect button does (a pty that never answers stays "connecting" to it); a
// bad --baud or one without --port is refused, naming it, and nothing is connected.
TEST(StudioStart, PortConnectsThroughTheMachinePanel) {
  widgets::PortBox::forgetRecentPorts();
  studio::MainWindow window(*preset("maker-plotter"));
  EXPECT_EQ(studio::connectAtStart(window, QString(), QStringLiteral("fast")),
            QStringLiteral("--baud: expected a positive whole number of bits per second, got 'fast'"));
  EXPECT_EQ(studio::connectAtStart(window, QStringLiteral("/dev/ttyUSB0"), QStringLiteral("-9600")),
            QStringLiteral("--baud: expected a positive whole number of bits per second, got '-9600'"));
  EXPECT_EQ(studio::connectAtStart(window, QString(), QStringLiteral("9600")), QStringLiteral("--baud needs --port"));
  EXPECT_TRUE(studio::connectAtStart(window, QString(), QString()).isEmpty());
  waitUntil([] { return false; }, 50);
  EXPECT_FALSE(window.machine().session().isConnecting());  // none of those connected anything
  int master = -1, slave = -1;
  char name[256] = {};
  ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
  const QString pty = QString::fromLatin1(name);
  EXPECT_TRUE(studio::connectAtStart(window, pty, QStringLiteral("57600")).isEmpty());
  EXPECT_FALSE(window.machine().session().isConnecting());  // not before the event loop runs
  ASSERT_TRUE(waitUntil([&] { return window.machine().session().isConnecting(); }, 2000));
  EXPECT_EQ(window.machine().session().linkName(), pty);
  widgets::MachinePanel* panel = window.machinePanels().machinePanel();
  EXPECT_EQ(panel->portBox()->chosenPort(), pty);
  EXPECT_EQ(panel->baudBox()->currentData().toInt(), 57600);
  window.machine().session().disconnectMachine();
  ::close(slave);
  ::close(master);
}

}  // namespace
}  // namespace fivebar
