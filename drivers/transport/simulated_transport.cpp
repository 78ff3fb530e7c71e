// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulated_transport.hpp"

namespace fivebar {

SimulatedTransport::SimulatedTransport(const sim::SimConfig& config, double speedup,
                                       QObject* parent)
    : Transport(parent), machine_(std::make_unique<sim::SimMachine>(config)), speedup_(speedup) {
  connect(&timer_, &QTimer::timeout, this, [this] {
    const qint64 now = clock_.nsecsElapsed();
    step(double(now - lastNs_) * 1e-9 * speedup_);
    lastNs_ = now;
  });
}

bool SimulatedTransport::open(QString* /*error*/) {
  open_ = true;
  dropReported_ = false;
  QTimer::singleShot(0, this, [this] { deliver(); });  // the power-up banner
  return true;
}

void SimulatedTransport::close() {
  open_ = false;
  timer_.stop();
}

void SimulatedTransport::write(const QByteArray& bytes) {
  if (!open_) return;
  machine_->receive(std::string_view(bytes.constData(), size_t(bytes.size())));
  // Deliver the answer on the next event-loop turn, never from inside the caller's write():
  // the protocol reacts to answers by writing again, which must not recurse.
  if (!deliverPending_) {
    deliverPending_ = true;
    QTimer::singleShot(0, this, [this] {
      deliverPending_ = false;
      deliver();
    });
  }
}

void SimulatedTransport::step(double dtS) {
  if (!open_) return;
  machine_->advance(dtS);
  deliver();
}

void SimulatedTransport::startClock(int periodMs) {
  clock_.start();
  lastNs_ = 0;
  timer_.start(periodMs);
}

void SimulatedTransport::deliver() {
  if (!open_) return;
  const std::string out = machine_->takeOutput();
  if (!out.empty()) emit bytesReceived(QByteArray(out.data(), qsizetype(out.size())));
  if (machine_->linkDropped() && !dropReported_) {
    dropReported_ = true;
    open_ = false;
    emit disconnected(QStringLiteral("simulated machine: link dropped"));
  }
}

}  // namespace fivebar
