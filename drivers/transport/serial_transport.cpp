// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial_transport.hpp"

#include <QFileInfo>
#include <QSerialPortInfo>
#include <QTimer>

namespace fivebar {

QString SerialTransport::boardKey() const {
  return portPath_.contains(QLatin1Char('/')) ? QFileInfo(portPath_).absoluteFilePath() : portPath_;
}


SerialTransport::SerialTransport(QString portPath, int baudRate, QObject* parent)
    : Transport(parent), portPath_(std::move(portPath)), baudRate_(baudRate) {
  connect(&port_, &QSerialPort::readyRead, this, [this] {
    const QByteArray bytes = port_.readAll();
    if (!bytes.isEmpty()) emit bytesReceived(bytes);
  });
  connect(&port_, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

SerialTransport::~SerialTransport() { port_.close(); }

std::vector<SerialPortInfo> SerialTransport::availablePorts() {
  std::vector<SerialPortInfo> out;
  for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
    out.push_back({info.portName(), info.systemLocation(), info.description(), info.manufacturer()});
  return out;
}

bool SerialTransport::open(QString* error) {
  lost_ = false;
  port_.setPortName(portPath_);
  port_.setBaudRate(baudRate_);
  port_.setDataBits(QSerialPort::Data8);
  port_.setParity(QSerialPort::NoParity);
  port_.setStopBits(QSerialPort::OneStop);
  port_.setFlowControl(QSerialPort::NoFlowControl);
  if (!port_.open(QIODevice::ReadWrite)) {
    if (error) *error = QString("cannot open serial port %1: %2").arg(portPath_, port_.errorString());
    return false;
  }
  return true;
}

void SerialTransport::close() {
  if (port_.isOpen()) port_.close();
}

void SerialTransport::write(const QByteArray& bytes) {
  if (!port_.isOpen() || lost_) return;
  port_.write(bytes);
}

void SerialTransport::onError(QSerialPort::SerialPortError error) {
  const bool fatal = error == QSerialPort::ReadError || error == QSerialPort::ResourceError ||
                     error == QSerialPort::WriteError || error == QSerialPort::PermissionError;
  if (!fatal || lost_) return;
  lost_ = true;
  // QSerialPort's errorString() is the errno text of the last system call ("File exists",
  // "Input/output error"), which tells a user nothing: name what happened instead.
  const bool vanished = !QFileInfo::exists(portPath_) ||
                        error == QSerialPort::ResourceError || error == QSerialPort::ReadError;
  const QString reason =
      error == QSerialPort::PermissionError
          ? QString("no permission to use %1 any more").arg(portPath_)
      : vanished ? QString("the port %1 vanished or stopped working (cable unplugged, board powered "
                           "off or reset by the USB host, simulator ended)")
                       .arg(portPath_)
                 : QString("writing to %1 failed (the board may have been unplugged)").arg(portPath_);
  // Closing inside the error handler re-enters QSerialPort; close on the next event loop turn.
  QTimer::singleShot(0, this, [this] { close(); });
  emit disconnected(reason);
}

}  // namespace fivebar
