// SPDX-License-Identifier: GPL-3.0-or-later
// ConsolePort: the console panel's narrow view of the machine session: send a (checked) line,
// the expert switch for unchecked lines, whether lines can be sent now, and the console's lines.
// The panel sees nothing else of the session (no jog, run, settings or transport).
#pragma once

#include <QObject>
#include <QString>

#include "session/machine_session.hpp"

namespace fivebar::session {

class ConsolePort : public QObject {
  Q_OBJECT
 public:
  // session must outlive the port.
  explicit ConsolePort(MachineSession& session, QObject* parent = nullptr);

  // Lines can be sent now: connected and no job streaming.
  bool canSend() const { return session_.isConnected() && !session_.jobActive(); }
  bool uncheckedConsole() const { return session_.uncheckedConsole(); }
  // MachineSession::sendLine: checked unless the expert switch is on; false with *refusal.
  bool sendLine(const QString& line, QString* refusal = nullptr) { return session_.sendLine(line, refusal); }

 public slots:
  void setUncheckedConsole(bool on) { session_.setUncheckedConsole(on); }

 signals:
  void canSendChanged();
  void consoleLine(const QString& text, fivebar::session::ConsoleKind kind);
  void uncheckedConsoleChanged(bool on);

 private:
  MachineSession& session_;
};

}  // namespace fivebar::session
