// A network port typed in the machine panel (issue 23): "tcp:127.0.0.1:PORT" reaches the
// simulated machine behind a TCP bridge in the test (as ser2net puts a board on the network);
// the board vanishing from the network is a disconnect the panel shows, naming the port.
#include <gtest/gtest.h>

#include <QLabel>
#include <QPushButton>
#include <QTcpServer>
#include <QTcpSocket>

#include "drivers/simulated_transport.hpp"
#include "machine_test_support.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/port_box.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

TEST(MachinePanel, ConnectsToANetworkPortAndShowsItsLoss) {
  widgets::PortBox::forgetRecentPorts();
  sim::SimConfig config;
  config.profile = test::makerPlotter();
  config.setUp = true;
  SimulatedTransport board(config, 4.0);
  QString error;
  ASSERT_TRUE(board.open(&error)) << error.toStdString();
  board.startClock(5);
  QTcpServer bridge;
  ASSERT_TRUE(bridge.listen(QHostAddress::LocalHost));
  QTcpSocket* wire = nullptr;
  QObject::connect(&bridge, &QTcpServer::newConnection, [&] {
    wire = bridge.nextPendingConnection();
    QObject::connect(wire, &QTcpSocket::readyRead, [&] { board.write(wire->readAll()); });
  });
  QObject::connect(&board, &Transport::bytesReceived, [&](const QByteArray& bytes) {
    if (wire) wire->write(bytes);
  });
  const QString port = QStringLiteral("tcp:127.0.0.1:%1").arg(bridge.serverPort());
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  panel.connectTo(port);
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 8000)) << panel.linkLabel()->text().toStdString();
  EXPECT_EQ(rig.session.linkName(), port);
  EXPECT_EQ(widgets::PortBox::recentPorts().value(0), port);
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));  // $$ over the network
  wire->abort();  // the bridge goes away
  ASSERT_TRUE(waitUntil([&] { return !rig.session.isConnected(); }, 5000));
  EXPECT_TRUE(panel.connectButton()->isEnabled());
  widgets::PortBox::forgetRecentPorts();
}

}  // namespace
}  // namespace fivebar
