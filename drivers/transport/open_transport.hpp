// SPDX-License-Identifier: GPL-3.0-or-later
// The transport for a port name as a maker types it, the one place that tells the kinds apart:
// "tcp:HOST:PORT" is a network port (TcpTransport; the baud rate does not apply), anything else
// a serial device or pseudo-terminal (SerialTransport at baudRate): /dev/ttyUSB0, ttyACM0,
// /dev/serial/by-id/..., a pty link such as fivebar-sim's or grbl-sim's. The studio and the CLI
// both open their ports through it. Nothing is opened here: Transport::open() says why not.
#pragma once

#include <QString>
#include <memory>

#include "transport.hpp"

namespace fivebar {

std::unique_ptr<Transport> makePortTransport(const QString& name, int baudRate);

// True when the baud rate means something for this port (not for a network port).
bool portHasBaudRate(const QString& name);

}  // namespace fivebar
