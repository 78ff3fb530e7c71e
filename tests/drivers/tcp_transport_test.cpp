// SPDX-License-Identifier: GPL-3.0-or-later
// The network port (drivers/transport/tcp_transport, "tcp:HOST:PORT") against a QTcpServer in the test:
// names parsed strictly, bytes both ways, the peer closing reported once as a disconnect (our
// own close never), refused and malformed ports named in the error, the factory choosing the
// transport by name, and the GRBL protocol running over it to the simulated machine bridged
// the way ser2net bridges a board.
#include <gtest/gtest.h>

#include "tcp_bridge.hpp"

#include <QTcpServer>
#include <QTcpSocket>
#include <memory>
#include <vector>

#include "core/machine/profile.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/transport/open_transport.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "drivers/transport/simulated_transport.hpp"
#include "drivers/transport/tcp_transport.hpp"
#include "tests/widgets/event_wait.hpp"

namespace fivebar {
namespace {

using test::waitUntil;

// The disconnects a transport reported, in order.
struct Losses {
  explicit Losses(Transport& t) {
    QObject::connect(&t, &Transport::disconnected, [this](const QString& reason) { reasons.push_back(reason); });
  }
  std::vector<QString> reasons;
};

QString nameOf(const QTcpServer& server) {
  return QStringLiteral("tcp:127.0.0.1:%1").arg(server.serverPort());
}

// A listening server and the transport connected to it; `peer` is the server's end.
struct Connected {
  QTcpServer server;
  std::unique_ptr<TcpTransport> transport;
  QTcpSocket* peer = nullptr;
  QString error;
  bool open() {
    if (!server.listen(QHostAddress::LocalHost)) return false;
    transport = std::make_unique<TcpTransport>(nameOf(server));
    if (!transport->open(&error)) return false;
    if (!server.waitForNewConnection(3000)) return false;
    peer = server.nextPendingConnection();
    return peer != nullptr;
  }
};

TEST(TcpTransport, NamesAreParsedStrictly) {
  const auto a = parseTcpPortName(QStringLiteral("tcp:192.168.1.20:23"));
  ASSERT_TRUE(a);
  EXPECT_EQ(a->host, QStringLiteral("192.168.1.20"));
  EXPECT_EQ(a->port, 23);
  const auto named = parseTcpPortName(QStringLiteral("TCP:fluidnc.local:8080"));
  ASSERT_TRUE(named);
  EXPECT_EQ(named->host, QStringLiteral("fluidnc.local"));
  const auto v6 = parseTcpPortName(QStringLiteral("tcp:[::1]:2000"));
  ASSERT_TRUE(v6);
  EXPECT_EQ(v6->host, QStringLiteral("::1"));
  EXPECT_EQ(v6->port, 2000);
  for (const char* bad : {"tcp:", "tcp:host", "tcp::23", "tcp:host:", "tcp:host:0", "tcp:host:65536",
                          "tcp:host:+23", "tcp:host:2 3", "tcp:my host:23", "/dev/ttyUSB0", "host:23"})
    EXPECT_FALSE(parseTcpPortName(QString::fromLatin1(bad))) << bad;
  EXPECT_TRUE(isTcpPortName(QStringLiteral("tcp:host")));  // meant as one, even malformed
  EXPECT_FALSE(isTcpPortName(QStringLiteral("/dev/ttyUSB0")));
}

TEST(TcpTransport, CarriesBytesBothWays) {
  Connected c;
  ASSERT_TRUE(c.open()) << c.error.toStdString();
  EXPECT_TRUE(c.transport->isOpen());
  EXPECT_EQ(c.transport->name(), nameOf(c.server));
  // Host to board: a line and a real-time byte, unframed.
  c.transport->write(QByteArray("$$\n?"));
  QByteArray atBoard;
  ASSERT_TRUE(waitUntil([&] {
    atBoard += c.peer->readAll();
    return atBoard.size() >= 4;
  }, 3000));
  EXPECT_EQ(atBoard, QByteArray("$$\n?"));
  // Board to host.
  QByteArray atHost;
  QObject::connect(c.transport.get(), &Transport::bytesReceived, [&](const QByteArray& b) { atHost += b; });
  c.peer->write("<Idle|MPos:0.000,0.000,0.000|FS:0,0>\r\nok\r\n");
  c.peer->flush();
  ASSERT_TRUE(waitUntil([&] { return atHost.endsWith("ok\r\n"); }, 3000));
  EXPECT_EQ(atHost, QByteArray("<Idle|MPos:0.000,0.000,0.000|FS:0,0>\r\nok\r\n"));
}

TEST(TcpTransport, ThePeerClosingIsOneDisconnect) {
  Connected c;
  ASSERT_TRUE(c.open()) << c.error.toStdString();
  Losses lost(*c.transport);
  c.peer->close();  // the bridge stops / the board resets
  ASSERT_TRUE(waitUntil([&] { return !lost.reasons.empty(); }, 3000));
  test::settle(200);  // error and disconnected both came from the socket: still one report
  c.transport->write(QByteArray("?"));  // writing after the loss is harmless and reports nothing
  test::settle(100);
  ASSERT_EQ(lost.reasons.size(), 1u);
  const QString reason = lost.reasons.front();
  EXPECT_TRUE(reason.contains(nameOf(c.server))) << reason.toStdString();
  EXPECT_TRUE(reason.contains(QStringLiteral("closed"))) << reason.toStdString();
  EXPECT_FALSE(c.transport->isOpen());
  // Opened again, the next loss is reported again (once per open()).
  ASSERT_TRUE(c.transport->open(&c.error)) << c.error.toStdString();
  ASSERT_TRUE(c.server.waitForNewConnection(3000));
  QTcpSocket* again = c.server.nextPendingConnection();
  ASSERT_NE(again, nullptr);
  again->abort();
  ASSERT_TRUE(waitUntil([&] { return lost.reasons.size() == 2; }, 3000));
}

TEST(TcpTransport, OurOwnCloseIsNoDisconnect) {
  Connected c;
  ASSERT_TRUE(c.open()) << c.error.toStdString();
  Losses lost(*c.transport);
  c.transport->close();
  EXPECT_FALSE(c.transport->isOpen());
  ASSERT_TRUE(waitUntil([&] { return c.peer->state() != QAbstractSocket::ConnectedState; }, 3000));
  test::settle(100);
  EXPECT_TRUE(lost.reasons.empty());
}

TEST(TcpTransport, ARefusedOrMalformedPortIsNamed) {
  quint16 freePort = 0;
  {
    QTcpServer probe;
    ASSERT_TRUE(probe.listen(QHostAddress::LocalHost));
    freePort = probe.serverPort();
  }  // closed: nothing listens there now
  const QString name = QStringLiteral("tcp:127.0.0.1:%1").arg(freePort);
  TcpTransport refused(name);
  QString error;
  EXPECT_FALSE(refused.open(&error));
  EXPECT_TRUE(error.contains(name)) << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("refused"))) << error.toStdString();
  EXPECT_FALSE(refused.isOpen());

  TcpTransport malformed(QStringLiteral("tcp:board"));
  error.clear();
  EXPECT_FALSE(malformed.open(&error));
  EXPECT_TRUE(error.contains(QStringLiteral("tcp:board"))) << error.toStdString();
  EXPECT_TRUE(error.contains(QStringLiteral("tcp:HOST:PORT"))) << error.toStdString();
}

TEST(PortTransport, TheNameChoosesTheTransport) {
  const auto network = makePortTransport(QStringLiteral("tcp:127.0.0.1:23"), 115200);
  EXPECT_NE(dynamic_cast<TcpTransport*>(network.get()), nullptr);
  EXPECT_EQ(network->name(), QStringLiteral("tcp:127.0.0.1:23"));
  EXPECT_FALSE(portHasBaudRate(QStringLiteral("tcp:127.0.0.1:23")));
  for (const char* serial : {"/dev/ttyUSB0", "ttyACM0", "/dev/serial/by-id/usb-1a86_USB_Serial-if00-port0",
                             "/tmp/grblpty"}) {
    const auto port = makePortTransport(QString::fromLatin1(serial), 115200);
    EXPECT_NE(dynamic_cast<SerialTransport*>(port.get()), nullptr) << serial;
    EXPECT_EQ(port->name(), QString::fromLatin1(serial));
    EXPECT_TRUE(portHasBaudRate(QString::fromLatin1(serial)));
  }
}

// The simulated machine behind a TCP bridge (as ser2net puts a board on the network): the
// protocol over the network port gets the board's status reports and acks.
TEST(TcpTransport, TheGrblProtocolRunsOverIt) {
  test::TcpBridge bridge(*preset("maker-plotter"));
  ASSERT_TRUE(bridge.listening());
  QString error;
  const auto port = makePortTransport(bridge.portName(), 115200);
  ASSERT_TRUE(port->open(&error)) << error.toStdString();
  MachineLink link(*port);
  link.start();
  ASSERT_TRUE(waitUntil([&] { return link.protocol().state() == grbl::MachineState::Idle; }, 5000));
  ASSERT_NE(link.protocol().requestSettings(), 0u);  // a line and its answer: the $$ listing
  ASSERT_TRUE(waitUntil([&] { return link.protocol().boardSettings().count(100) == 1; }, 5000));
}

}  // namespace
}  // namespace fivebar
