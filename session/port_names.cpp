// SPDX-License-Identifier: GPL-3.0-or-later
// The machine's ports. Contract: port_names.hpp.
#include "session/port_names.hpp"

#include "drivers/transport/open_transport.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "drivers/transport/tcp_transport.hpp"

namespace fivebar::session {

std::vector<PortInfo> availableSerialPorts() {
  std::vector<PortInfo> out;
  for (const SerialPortInfo& p : SerialTransport::availablePorts()) out.push_back({p.systemPath, p.description});
  return out;
}

bool isNetworkPortName(const QString& name) { return isTcpPortName(name); }

bool isValidNetworkPortName(const QString& name) { return parseTcpPortName(name).has_value(); }

bool portHasBaudRate(const QString& name) { return fivebar::portHasBaudRate(name); }

}  // namespace fivebar::session
