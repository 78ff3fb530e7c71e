// SPDX-License-Identifier: GPL-3.0-or-later
// The machine's ports as the studio offers them (the session is the widgets' only door to the
// drivers): the serial ports found on this computer, and network ports written tcp:HOST:PORT.
#pragma once

#include <QString>
#include <vector>

namespace fivebar::session {

struct PortInfo {
  QString systemPath;   // e.g. "/dev/ttyUSB0"
  QString description;  // e.g. "USB2.0-Serial"; may be empty
};

// The serial ports of this computer (QSerialPortInfo), in its order.
std::vector<PortInfo> availableSerialPorts();
// True for a name that means a network port ("tcp:" prefix), well written or not.
bool isNetworkPortName(const QString& name);
// True when a network port's name is well written (tcp:HOST:PORT with a port number).
bool isValidNetworkPortName(const QString& name);
// True when the port has a baud rate to choose (a serial port; not a network port).
bool portHasBaudRate(const QString& name);

}  // namespace fivebar::session
