// SPDX-License-Identifier: GPL-3.0-or-later
// SimulatedTransport: the in-process simulated machine behind the transport seam. Time is
// driven by a QTimer (real time times the speed-up factor) once started, or stepped
// deterministically with step() in tests.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <memory>

#include "drivers/sim/sim_machine.hpp"
#include "transport.hpp"

namespace fivebar {

class SimulatedTransport : public Transport {
  Q_OBJECT
 public:
  explicit SimulatedTransport(const sim::SimConfig& config, double speedup = 1.0,
                              QObject* parent = nullptr);

  bool open(QString* error) override;
  void close() override;
  bool isOpen() const override { return open_; }
  void write(const QByteArray& bytes) override;
  QString name() const override { return QStringLiteral("simulated machine"); }
  QString boardKey() const override { return {}; }

  // Advances machine time by dtS (s) and delivers the machine's output.
  void step(double dtS);
  // Starts / stops the real-time QTimer (period in ms).
  void startClock(int periodMs = 5);
  void stopClock() { timer_.stop(); }
  sim::SimMachine& machine() { return *machine_; }

 private:
  void deliver();

  std::unique_ptr<sim::SimMachine> machine_;
  double speedup_;
  bool open_ = false;
  bool dropReported_ = false;
  bool deliverPending_ = false;
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 lastNs_ = 0;
};

}  // namespace fivebar
