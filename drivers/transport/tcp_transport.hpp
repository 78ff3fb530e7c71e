// SPDX-License-Identifier: GPL-3.0-or-later
// TcpTransport: a GRBL board behind a network port, "tcp:HOST:PORT" (a ser2net bridge in raw
// mode, a FluidNC or grblHAL board's telnet/raw TCP server). The bytes are the serial stream's,
// unframed; there is no baud rate. Like SerialTransport, the first socket error or the peer
// closing the connection ends the link: disconnected() is emitted once and the socket closed.
#pragma once

#include <QString>
#include <memory>
#include <optional>

#include "transport.hpp"

class QTcpSocket;  // Qt Network stays inside fivebar_drivers (linked PRIVATE)

namespace fivebar {

// HOST and PORT of a network port name.
struct TcpAddress {
  QString host;  // a name or an address; an IPv6 address in brackets: tcp:[::1]:23
  quint16 port = 0;
};

// True when `name` is meant as a network port (it starts with "tcp:"), well formed or not.
bool isTcpPortName(const QString& name);
// "tcp:HOST:PORT" -> its host and port (1..65535); nullopt for anything else.
std::optional<TcpAddress> parseTcpPortName(const QString& name);

class TcpTransport : public Transport {
  Q_OBJECT
 public:
  // How long open() waits for the connection (a board on the LAN answers in milliseconds).
  static constexpr int kConnectTimeoutMs = 3000;

  // `name` is "tcp:HOST:PORT"; a malformed name fails in open() with a sentence saying so.
  explicit TcpTransport(QString name, QObject* parent = nullptr);
  ~TcpTransport() override;

  // Connects (blocking, at most kConnectTimeoutMs); false with *error naming the port.
  bool open(QString* error) override;
  void close() override;
  bool isOpen() const override;
  void write(const QByteArray& bytes) override;
  QString name() const override { return name_; }

 private:
  void lose(const QString& reason);

  QString name_;
  std::unique_ptr<QTcpSocket> socket_;
  bool lost_ = true;  // no disconnect may be reported: not open, closed by us, or already reported
};

}  // namespace fivebar
