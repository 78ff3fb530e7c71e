// SPDX-License-Identifier: GPL-3.0-or-later
// A board on the network for tests: the in-process simulated machine behind a QTcpServer on
// localhost, bytes passed both ways, as ser2net puts a serial board on the network. One copy for
// tests/drivers and tests/widgets.
#pragma once

#include <QHostAddress>
#include <QString>
#include <QTcpServer>
#include <QTcpSocket>

#include "drivers/transport/simulated_transport.hpp"

namespace fivebar::test {

class TcpBridge {
 public:
  explicit TcpBridge(const MachineProfile& profile, double speedup = 4.0) : board_(configFor(profile), speedup) {
    QString error;
    opened_ = board_.open(&error) && server_.listen(QHostAddress::LocalHost);
    board_.startClock(5);
    QObject::connect(&server_, &QTcpServer::newConnection, [this] {
      wire_ = server_.nextPendingConnection();
      QObject::connect(wire_, &QTcpSocket::readyRead, [this] { board_.write(wire_->readAll()); });
    });
    QObject::connect(&board_, &Transport::bytesReceived, [this](const QByteArray& bytes) {
      if (wire_) wire_->write(bytes);
    });
  }
  bool listening() const { return opened_; }
  // "tcp:127.0.0.1:PORT"
  QString portName() const { return QStringLiteral("tcp:127.0.0.1:%1").arg(server_.serverPort()); }
  // The connection of the port under test (nullptr before it connected).
  QTcpSocket* wire() const { return wire_; }

 private:
  static sim::SimConfig configFor(const MachineProfile& profile) {
    sim::SimConfig config;
    config.profile = profile;
    config.setUp = true;
    return config;
  }
  SimulatedTransport board_;
  QTcpServer server_;
  QTcpSocket* wire_ = nullptr;
  bool opened_ = false;
};

}  // namespace fivebar::test
