// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/console_port.hpp"

namespace fivebar::session {

ConsolePort::ConsolePort(MachineSession& session, QObject* parent) : QObject(parent), session_(session) {
  connect(&session_, &MachineSession::consoleLine, this, &ConsolePort::consoleLine);
  connect(&session_, &MachineSession::uncheckedConsoleChanged, this, &ConsolePort::uncheckedConsoleChanged);
  connect(&session_, &MachineSession::connectionChanged, this, &ConsolePort::canSendChanged);
  connect(&session_, &MachineSession::jobActiveChanged, this, &ConsolePort::canSendChanged);
}

}  // namespace fivebar::session
