// SPDX-License-Identifier: GPL-3.0-or-later
// SerialTransport: a QSerialPort (USB serial board or a pseudo-terminal such as fivebar-sim's).
// The first ReadError / ResourceError / WriteError ends the link: disconnected() is emitted
// once and the port is closed, however many errors QSerialPort keeps reporting.
#pragma once

#include <QSerialPort>
#include <QString>
#include <vector>

#include "transport.hpp"

namespace fivebar {

struct SerialPortInfo {
  QString portName;     // e.g. "ttyUSB0"
  QString systemPath;   // e.g. "/dev/ttyUSB0"
  QString description;  // e.g. "USB2.0-Serial"
  QString manufacturer;
};

class SerialTransport : public Transport {
  Q_OBJECT
 public:
  SerialTransport(QString portPath, int baudRate, QObject* parent = nullptr);
  ~SerialTransport() override;

  static std::vector<SerialPortInfo> availablePorts();

  bool open(QString* error) override;
  void close() override;
  bool isOpen() const override { return port_.isOpen(); }
  void write(const QByteArray& bytes) override;
  QString name() const override { return portPath_; }
  // A path is remembered absolute (a pty link, /dev/serial/by-id/...), a bare name as it is.
  QString boardKey() const override;

 private:
  void onError(QSerialPort::SerialPortError error);

  QString portPath_;
  int baudRate_;
  QSerialPort port_;
  bool lost_ = false;  // a disconnect was already reported for this open()
};

}  // namespace fivebar
