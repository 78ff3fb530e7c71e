// SPDX-License-Identifier: GPL-3.0-or-later
// A network port typed in the machine panel (issue 23): "tcp:127.0.0.1:PORT" reaches the
// simulated machine behind a TCP bridge in the test (as ser2net puts a board on the network);
// the board vanishing from the network is a disconnect the panel shows, naming the port.
#include <gtest/gtest.h>

#include <QLabel>
#include <QPushButton>
#include <QTcpServer>
#include <QTcpSocket>

#include "drivers/transport/simulated_transport.hpp"
#include "machine_test_support.hpp"
#include "tests/drivers/tcp_bridge.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/port_box.hpp"

namespace fivebar {
namespace {

using test::MachineRig;
using test::waitUntil;

TEST(MachinePanel, ConnectsToANetworkPortAndShowsItsLoss) {
  widgets::PortBox::forgetRecentPorts();
  test::TcpBridge bridge(test::makerPlotter());
  ASSERT_TRUE(bridge.listening());
  const QString port = bridge.portName();
  MachineRig rig;
  widgets::MachinePanel panel(rig.view, rig.session, rig.session);
  panel.connectTo(port);
  ASSERT_TRUE(waitUntil([&] { return rig.session.isConnected(); }, 8000)) << panel.linkLabel()->text().toStdString();
  EXPECT_EQ(rig.session.linkName(), port);
  EXPECT_EQ(widgets::PortBox::recentPorts().value(0), port);
  ASSERT_TRUE(waitUntil([&] { return rig.session.boardSettingsKnown(); }, 5000));  // $$ over the network
  ASSERT_NE(bridge.wire(), nullptr);
  bridge.wire()->abort();  // the bridge goes away
  ASSERT_TRUE(waitUntil([&] { return !rig.session.isConnected(); }, 5000));
  EXPECT_TRUE(panel.connectButton()->isEnabled());
  widgets::PortBox::forgetRecentPorts();
}

}  // namespace
}  // namespace fivebar
