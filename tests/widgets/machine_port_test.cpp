// SPDX-License-Identifier: GPL-3.0-or-later
// The studio connects to any port by name (issue 23): the machine panel's port box is editable
// (a typed pseudo-terminal reaches the fivebar-sim executable), offers the simulated machine,
// the recent ports (QSettings, most recent first, a handful kept) and the listed ones; Connect
// opens what is typed; a port that cannot be opened is named in the panel and a message box.
#include <gtest/gtest.h>

#include <QApplication>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include "machine_test_support.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/port_box.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;
using widgets::PortBox;

// fivebar-sim on a pseudo-terminal, a board set up and referenced for the maker plotter.
class SimOnPty {
 public:
  explicit SimOnPty(const QTemporaryDir& dir) : pty_(dir.filePath(QStringLiteral("grblpty"))) {
    process_.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    process_.start(QStringLiteral(FIVEBAR_SIM_EXE),
                   {QStringLiteral("--pty"), pty_, QStringLiteral("--machine"), QStringLiteral("maker-plotter"),
                    QStringLiteral("--set-up"), QStringLiteral("--referenced")});
    waitUntil([this] { return QFile::exists(pty_); }, 5000);
  }
  ~SimOnPty() {
    process_.terminate();
    process_.waitForFinished(5000);
  }
  bool ready() const { return QFile::exists(pty_); }
  const QString& pty() const { return pty_; }

 private:
  QString pty_;
  QProcess process_;
};

// The panel's "Cannot connect" box, once it is shown (nullptr before); its text in *text.
QMessageBox* problemBox(widgets::MachinePanel& panel) {
  return panel.findChild<QMessageBox*>(QStringLiteral("connectProblemMessage"));
}

void typeInto(PortBox* box, const QString& text) {
  box->lineEdit()->clear();
  QTest::keyClicks(box->lineEdit(), text);
}

struct ForgetRecent {  // every test starts and ends with no recent ports
  ForgetRecent() { PortBox::forgetRecentPorts(); }
  ~ForgetRecent() { PortBox::forgetRecentPorts(); }
};

TEST(PortBox, IsEditableAndOffersTheRecentPortsMostRecentFirst) {
  ForgetRecent clean;
  {
    PortBox fresh;
    EXPECT_TRUE(fresh.isEditable());
    EXPECT_EQ(fresh.itemData(0).toString(), PortBox::kSimulated);
    EXPECT_EQ(fresh.chosenPort(), PortBox::kSimulated);  // nothing used yet: the simulated machine
  }
  PortBox box;
  for (int i = 0; i < PortBox::kRecentPorts + 2; ++i) box.remember(QStringLiteral("/tmp/pty%1").arg(i));
  box.remember(QStringLiteral("tcp:192.168.1.20:23"));
  box.remember(QStringLiteral("/tmp/pty5"));  // used again: moves to the front, not listed twice
  const QStringList recent = PortBox::recentPorts();
  ASSERT_EQ(recent.size(), PortBox::kRecentPorts);
  EXPECT_EQ(recent[0], QStringLiteral("/tmp/pty5"));
  EXPECT_EQ(recent[1], QStringLiteral("tcp:192.168.1.20:23"));
  EXPECT_EQ(recent[2], QStringLiteral("/tmp/pty7"));
  EXPECT_EQ(recent.count(QStringLiteral("/tmp/pty5")), 1);
  EXPECT_FALSE(recent.contains(QStringLiteral("/tmp/pty0")));  // the oldest fell off
  // Listed after the simulated machine, in that order; a new box starts at the most recent.
  PortBox next;
  EXPECT_GT(next.findData(recent[0]), 0);
  for (int i = 1; i < recent.size(); ++i) EXPECT_LT(next.findData(recent[i - 1]), next.findData(recent[i]));
  EXPECT_EQ(next.chosenPort(), recent[0]);
  // What is typed is what Connect opens; a listed entry's text means its port.
  next.setEditText(QStringLiteral("  /dev/serial/by-id/usb-1a86_USB_Serial-if00-port0 "));
  EXPECT_EQ(next.chosenPort(), QStringLiteral("/dev/serial/by-id/usb-1a86_USB_Serial-if00-port0"));
  next.setEditText(next.itemText(0));
  EXPECT_EQ(next.chosenPort(), PortBox::kSimulated);
  // Refresh keeps a typed name.
  next.setEditText(QStringLiteral("/tmp/typed"));
  next.refresh();
  EXPECT_EQ(next.chosenPort(), QStringLiteral("/tmp/typed"));
}

TEST(MachinePanel, ConnectsToATypedPseudoTerminalAndRemembersIt) {
  ForgetRecent clean;
  QTemporaryDir dir;
  SimOnPty sim(dir);
  ASSERT_TRUE(sim.ready()) << "fivebar-sim did not create " << sim.pty().toStdString();
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  typeInto(panel.portBox(), sim.pty());
  EXPECT_TRUE(panel.baudBox()->isEnabled());  // a serial port has a baud rate
  panel.connectButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 8000)) << panel.linkLabel()->text().toStdString();
  EXPECT_EQ(rig.session.linkName(), sim.pty());
  EXPECT_TRUE(panel.linkLabel()->text().contains(sim.pty())) << panel.linkLabel()->text().toStdString();
  EXPECT_FALSE(panel.portBox()->isEnabled());  // not while connected
  ASSERT_EQ(PortBox::recentPorts().value(0), sim.pty());
  panel.disconnectButton()->click();
  EXPECT_FALSE(rig.session.isConnected());
  // Offered first next time, and connected again from the list as typed before.
  widgets::MachinePanel again(rig.view, rig.session, rig.session);
  EXPECT_EQ(again.portBox()->chosenPort(), sim.pty());
  again.connectButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 8000));
  again.disconnectButton()->click();
}

// --port PATH [--baud N] goes through this door: the same as typing and pressing Connect.
TEST(MachinePanel, ConnectToIsTheConnectButtonForANamedPort) {
  ForgetRecent clean;
  QTemporaryDir dir;
  SimOnPty sim(dir);
  ASSERT_TRUE(sim.ready());
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  panel.connectTo(sim.pty(), 250000);
  EXPECT_EQ(panel.baudBox()->currentData().toInt(), 250000);
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 8000));  // a pty takes any rate
  EXPECT_EQ(panel.portBox()->chosenPort(), sim.pty());
  panel.disconnectButton()->click();
}

TEST(MachinePanel, APortThatCannotBeOpenedIsNamedAndNotRemembered) {
  ForgetRecent clean;
  QTemporaryDir dir;
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  QFile plain(dir.filePath(QStringLiteral("job.gcode")));
  ASSERT_TRUE(plain.open(QIODevice::WriteOnly));
  plain.close();
  const struct {
    QString port;
    QString says;
  } cases[] = {
      {QStringLiteral("/dev/ttyUSB-not-there"), QStringLiteral("There is no port /dev/ttyUSB-not-there")},
      {QStringLiteral("ttyACM-not-there"), QStringLiteral("There is no port ttyACM-not-there")},
      {plain.fileName(), plain.fileName() + QStringLiteral(" is a file, not a port")},
      {QStringLiteral("tcp:board"), QStringLiteral("tcp:HOST:PORT")},
      {QString(), QStringLiteral("type its name")},
  };
  for (const auto& c : cases) {
    typeInto(panel.portBox(), c.port);
    panel.connectButton()->click();
    EXPECT_FALSE(rig.session.isConnecting()) << c.port.toStdString();
    EXPECT_TRUE(panel.linkLabel()->text().contains(c.says)) << panel.linkLabel()->text().toStdString();
    QMessageBox* box = problemBox(panel);
    ASSERT_NE(box, nullptr) << c.port.toStdString();
    EXPECT_TRUE(box->isVisible());
    EXPECT_TRUE(box->text().contains(c.says)) << box->text().toStdString();
    box->close();  // deletes itself
    QApplication::processEvents();
    QApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
  }
  EXPECT_TRUE(PortBox::recentPorts().isEmpty());
  // A network port has no baud rate to choose.
  typeInto(panel.portBox(), QStringLiteral("tcp:192.168.1.20:23"));
  EXPECT_FALSE(panel.baudBox()->isEnabled());
  panel.portBox()->setCurrentIndex(0);  // the simulated machine: none either
  EXPECT_FALSE(panel.baudBox()->isEnabled());
}

}  // namespace
}  // namespace fivebar
