// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_port_screenshots OUTDIR: screenshots of the machine panel's port box, taken from the
// real main window (not a test; run it under xvfb-run -a -s "-screen 0 1600x1000x24": the list
// is a window of its own, so the pictures are grabs of the screen around the panel):
//   machine-port-typed.png      a pseudo-terminal's path typed, the list open (the simulated
//                               machine, the recent ports, the serial ports found)
//   machine-port-connected.png  Connect pressed: connected to fivebar-sim on that pty
#include <QAbstractItemView>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QTemporaryDir>
#include <cstdio>

#include "app/studio/main_window.hpp"
#include "session/machine_side.hpp"
#include "tests/widgets/event_wait.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/machine/port_box.hpp"

namespace {

// The screen around the machine dock (with its title) down to the panel's status, and the
// port list when it is open.
bool grabPanel(fivebar::studio::MainWindow& window, const QString& path) {
  fivebar::test::settle(500);
  fivebar::widgets::MachinePanel* panel = window.machinePanels().machinePanel();
  QWidget* framed = window.dock(QStringLiteral("dockMachine"));
  if (framed == nullptr) framed = panel;
  QRect area = framed->rect().translated(framed->mapToGlobal(QPoint(0, 0)));
  area.setBottom(panel->stateLabel()->mapToGlobal(QPoint(0, 0)).y() + 140);
  QWidget* popup = panel->portBox()->view()->window();
  if (popup && popup->isVisible()) area = area.united(popup->frameGeometry());
  area = area.adjusted(-8, -8, 8, 8).intersected(window.screen()->geometry());
  const QPixmap shot = window.screen()->grabWindow(0, area.x(), area.y(), area.width(), area.height());
  const bool ok = !shot.isNull() && shot.save(path);
  std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: fivebar_port_screenshots OUTDIR\n");
    return 2;
  }
  const QString outDir = QString::fromLocal8Bit(argv[1]);
  QDir().mkpath(outDir);
  QTemporaryDir settingsDir;  // a fresh dock layout and recent list, not the user's
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QApplication::setApplicationName(QStringLiteral("FiveBar Studio"));

  using namespace fivebar;
  // Ports a maker connected to before, the last one first.
  widgets::PortBox::forgetRecentPorts();
  {
    widgets::PortBox remember;
    remember.remember(QStringLiteral("tcp:192.168.1.20:23"));
    remember.remember(QStringLiteral("/dev/serial/by-id/usb-1a86_USB2.0-Serial-if00-port0"));
    remember.remember(QStringLiteral("/tmp/fivebar-pty"));
  }
  // A simulated board on the pty the maker types (fivebar-sim --pty; the firmware simulator's
  // start.sh makes the same kind of link).
  // /tmp/grblpty unless another simulator uses that name now.
  const QString pty = QFileInfo(QStringLiteral("/tmp/grblpty")).exists()
                          ? settingsDir.filePath(QStringLiteral("grblpty"))
                          : QStringLiteral("/tmp/grblpty");
  QProcess sim;
  sim.start(QStringLiteral(FIVEBAR_SIM_EXE), {QStringLiteral("--pty"), pty, QStringLiteral("--machine"),
                                             QStringLiteral("hoang2015"), QStringLiteral("--set-up")});
  test::waitUntil([&] { return QFile::exists(pty); }, 5000);

  studio::MainWindow window(*preset("hoang2015"));
  window.resize(1600, 1000);
  window.show();
  if (QDockWidget* dock = window.dock(QStringLiteral("dockMachine"))) dock->raise();
  widgets::MachinePanel* panel = window.machinePanels().machinePanel();
  widgets::PortBox* box = panel->portBox();
  test::settle(500);
  box->setFocus();
  box->lineEdit()->setText(pty);
  box->showPopup();
  int status = grabPanel(window, outDir + QStringLiteral("/machine-port-typed.png")) ? 0 : 1;
  box->hidePopup();
  panel->connectButton()->click();
  if (!test::waitUntil([&] { return window.machine().session().isConnected(); }, 8000)) status = 1;
  if (!grabPanel(window, outDir + QStringLiteral("/machine-port-connected.png"))) status = 1;
  window.machine().session().disconnectMachine();
  sim.terminate();
  sim.waitForFinished(5000);
  return status;
}
