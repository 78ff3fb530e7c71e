// SPDX-License-Identifier: GPL-3.0-or-later
#include "machine_link.hpp"

namespace fivebar {

MachineLink::MachineLink(Transport& transport, double pollIntervalS, int tickMs, QObject* parent)
    : QObject(parent),
      transport_(transport),
      protocol_([this](std::string_view bytes) {
        transport_.write(QByteArray(bytes.data(), qsizetype(bytes.size())));
      }) {
  trust_ = std::make_unique<grbl::PoseTrust>(protocol_, transport_.boardKey().toStdString());
  clock_.start();
  protocol_.setPollInterval(pollIntervalS);
  connect(&transport_, &Transport::bytesReceived, this, [this](const QByteArray& bytes) {
    protocol_.receive(std::string_view(bytes.constData(), size_t(bytes.size())));
  });
  connect(&transport_, &Transport::disconnected, this,
          [this](const QString& reason) { protocol_.disconnected(reason.toStdString()); });
  timer_.setInterval(tickMs);
  connect(&timer_, &QTimer::timeout, this, [this] {
    const double now = nowS();
    protocol_.tick(now);
    emit ticked(now);
  });
}

MachineLink::~MachineLink() {
  timer_.stop();
  trust_.reset();  // it listens to the protocol
}

}  // namespace fivebar
