// SPDX-License-Identifier: GPL-3.0-or-later
#include "open_transport.hpp"

#include "serial_transport.hpp"
#include "tcp_transport.hpp"

namespace fivebar {

std::unique_ptr<Transport> makePortTransport(const QString& name, int baudRate) {
  if (isTcpPortName(name)) return std::make_unique<TcpTransport>(name);
  return std::make_unique<SerialTransport>(name, baudRate);
}

bool portHasBaudRate(const QString& name) { return !isTcpPortName(name); }

}  // namespace fivebar
