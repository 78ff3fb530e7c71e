// SPDX-License-Identifier: GPL-3.0-or-later
// The transport seam under the protocol: something bytes can be written to and that reports
// bytes received and, once, that it went away. Implementations: SerialTransport (a real or
// pseudo serial port), TcpTransport (a network port, tcp:HOST:PORT), SimulatedTransport (the
// in-process simulated machine), test fakes. makePortTransport (open_transport.hpp) picks the
// first two by the port's name.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace fivebar {

class Transport : public QObject {
  Q_OBJECT
 public:
  using QObject::QObject;
  ~Transport() override = default;
  // Opens the link; on failure returns false and sets *error to a sentence naming the port.
  virtual bool open(QString* error) = 0;
  virtual void close() = 0;
  virtual bool isOpen() const = 0;
  virtual void write(const QByteArray& bytes) = 0;
  virtual QString name() const = 0;
  // The name under which the host remembers where this board last stood (pose_trust.hpp); ""
  // for a board that is new at every open (the in-process simulated machine).
  virtual QString boardKey() const { return name(); }

 signals:
  void bytesReceived(const QByteArray& bytes);
  // Emitted at most once per open(): the link is gone (cable pulled, port vanished, peer closed).
  void disconnected(const QString& reason);
};

}  // namespace fivebar
