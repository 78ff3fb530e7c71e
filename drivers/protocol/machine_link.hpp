// SPDX-License-Identifier: GPL-3.0-or-later
// MachineLink: wires a Transport to a GrblProtocol and gives the protocol a clock (a QTimer
// that polls status and drives time-outs). The composition point for the CLI, the studio and
// the end-to-end tests; the protocol logic itself stays pure.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>

#include "grbl_protocol.hpp"
#include "pose_trust.hpp"
#include "drivers/transport/transport.hpp"

namespace fivebar {

class MachineLink : public QObject {
  Q_OBJECT
 public:
  // tickMs: period of the clock that polls status (at pollIntervalS) and emits ticked().
  explicit MachineLink(Transport& transport, double pollIntervalS = 0.2, int tickMs = 10,
                       QObject* parent = nullptr);
  ~MachineLink() override;

  grbl::GrblProtocol& protocol() { return protocol_; }
  // Whether the host knows where the arms are (pose_trust.hpp), remembered under the
  // transport's boardKey().
  grbl::PoseTrust& poseTrust() { return *trust_; }
  const grbl::PoseTrust& poseTrust() const { return *trust_; }
  Transport& transport() { return transport_; }
  double nowS() const { return double(clock_.nsecsElapsed()) * 1e-9; }
  void start() { timer_.start(); }
  void stopClock() { timer_.stop(); }

 signals:
  void ticked(double nowS);

 private:
  Transport& transport_;
  grbl::GrblProtocol protocol_;
  std::unique_ptr<grbl::PoseTrust> trust_;
  QTimer timer_;
  QElapsedTimer clock_;
};

}  // namespace fivebar
