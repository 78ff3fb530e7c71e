// SPDX-License-Identifier: GPL-3.0-or-later
#include "tcp_transport.hpp"

#include <QTcpSocket>
#include <QTimer>

namespace fivebar {
namespace {

const QString kPrefix = QStringLiteral("tcp:");

// Why a connection could not be made or broke, in words a maker can act on.
QString reasonOf(QAbstractSocket::SocketError error, const QString& host, const QString& detail) {
  switch (error) {
    case QAbstractSocket::ConnectionRefusedError:
      return QStringLiteral("the connection was refused (nothing listens on that port: is the bridge "
                            "or the board's server running, and is the port number right?)");
    case QAbstractSocket::HostNotFoundError:
      return QStringLiteral("the host %1 was not found (check the name or use its IP address)").arg(host);
    case QAbstractSocket::SocketTimeoutError:
      return QStringLiteral("no answer within %1 s (is the board on and on this network?)")
          .arg(TcpTransport::kConnectTimeoutMs / 1000);
    case QAbstractSocket::NetworkError:
      return QStringLiteral("the network is unreachable (%1)").arg(detail);
    case QAbstractSocket::RemoteHostClosedError:
      return QStringLiteral("the other end closed the connection (bridge stopped, board reset or powered off)");
    default:
      return detail;
  }
}

}  // namespace

bool isTcpPortName(const QString& name) { return name.startsWith(kPrefix, Qt::CaseInsensitive); }

std::optional<TcpAddress> parseTcpPortName(const QString& name) {
  if (!isTcpPortName(name)) return std::nullopt;
  const QString rest = name.mid(kPrefix.size());
  const qsizetype colon = rest.lastIndexOf(u':');
  if (colon <= 0) return std::nullopt;
  QString host = rest.left(colon);
  if (host.startsWith(u'[') && host.endsWith(u']')) host = host.mid(1, host.size() - 2);
  if (host.isEmpty() || host.contains(u' ') || host.contains(u'\t')) return std::nullopt;
  const QString portText = rest.mid(colon + 1);
  bool ok = false;
  const uint port = portText.toUInt(&ok);
  // Digits only: toUInt accepts a leading '+' and blanks, a port number has neither.
  for (const QChar c : portText)
    if (!c.isDigit()) ok = false;
  if (!ok || port == 0 || port > 65535) return std::nullopt;
  return TcpAddress{host, static_cast<quint16>(port)};
}

TcpTransport::TcpTransport(QString name, QObject* parent)
    : Transport(parent), name_(std::move(name)), socket_(std::make_unique<QTcpSocket>()) {
  connect(socket_.get(), &QTcpSocket::readyRead, this, [this] {
    const QByteArray bytes = socket_->readAll();
    if (!bytes.isEmpty()) emit bytesReceived(bytes);
  });
  connect(socket_.get(), &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError error) {
    const auto address = parseTcpPortName(name_);
    lose(QStringLiteral("the connection to %1 broke: %2")
             .arg(name_, reasonOf(error, address ? address->host : name_, socket_->errorString())));
  });
  connect(socket_.get(), &QTcpSocket::disconnected, this, [this] {
    lose(QStringLiteral("the connection to %1 was closed by the other end (bridge stopped, board "
                        "reset or powered off)")
             .arg(name_));
  });
}

TcpTransport::~TcpTransport() {
  lost_ = true;
  socket_->disconnect(this);
  socket_->abort();
}

bool TcpTransport::open(QString* error) {
  close();
  const auto address = parseTcpPortName(name_);
  if (!address) {
    if (error)
      *error = QStringLiteral("%1 is not a network port: expected tcp:HOST:PORT, e.g. tcp:192.168.1.20:23")
                   .arg(name_);
    return false;
  }
  socket_->connectToHost(address->host, address->port);
  if (!socket_->waitForConnected(kConnectTimeoutMs)) {
    if (error)
      *error = QStringLiteral("cannot connect to %1: %2")
                   .arg(name_, reasonOf(socket_->error(), address->host, socket_->errorString()));
    socket_->abort();
    return false;
  }
  // Real-time bytes ('?', '!', '~', 0x18) must leave at once, not wait for Nagle's algorithm.
  socket_->setSocketOption(QAbstractSocket::LowDelayOption, 1);
  socket_->setSocketOption(QAbstractSocket::KeepAliveOption, 1);
  lost_ = false;
  return true;
}

bool TcpTransport::isOpen() const { return socket_->state() == QAbstractSocket::ConnectedState; }

void TcpTransport::close() {
  lost_ = true;  // our own close is not a disconnect
  if (socket_->state() == QAbstractSocket::ConnectedState) socket_->flush();
  socket_->abort();
}

void TcpTransport::write(const QByteArray& bytes) {
  if (lost_ || socket_->state() != QAbstractSocket::ConnectedState) return;
  socket_->write(bytes);
  socket_->flush();
}

void TcpTransport::lose(const QString& reason) {
  if (lost_) return;
  lost_ = true;
  // Aborting inside the socket's own signal re-enters it: close on the next event loop turn.
  QTimer::singleShot(0, this, [this] { socket_->abort(); });
  emit disconnected(reason);
}

}  // namespace fivebar
