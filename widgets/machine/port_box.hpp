// SPDX-License-Identifier: GPL-3.0-or-later
// PortBox: the machine panel's port box. Editable: any name can be typed (a device path, a
// /dev/serial/by-id link, a pseudo-terminal such as the firmware simulator's, or a network port
// tcp:HOST:PORT). It offers the built-in simulated machine, the ports connected to lately
// (QSettings, most recent first, kRecentPorts kept) and the serial ports found on the system.
// The three groups are apart (separators). It chooses nothing by itself beyond the most recent
// port at start; Connect asks chosenPort().
#pragma once

#include <QComboBox>
#include <QString>
#include <QStringList>

namespace fivebar::widgets {

class PortBox : public QComboBox {
  Q_OBJECT
 public:
  static constexpr int kRecentPorts = 6;
  static const QString kSimulated;  // the built-in simulated machine's id ("sim:")

  explicit PortBox(QWidget* parent = nullptr);

  // Lists the ports again (the ones found now and the recent ones), keeping the choice or the
  // text typed.
  void refresh();
  // What Connect opens: kSimulated, a listed port's path, or the name typed (trimmed; empty
  // when nothing is typed).
  QString chosenPort() const;
  // Shows `port` as the choice: its entry when listed, else the name as typed.
  void choose(const QString& port);
  // `port` (the simulated machine included) goes first in the recent list, which is listed again.
  void remember(const QString& port);

  // The recent list, most recent first (kSimulated may be in it).
  static QStringList recentPorts();
  static void forgetRecentPorts();

  // The list opens as wide as its longest name (a /dev/serial/by-id link is long), not only as
  // wide as the box in a narrow dock.
  void showPopup() override;
};

// Why `port` cannot be opened, found before trying (in the user's language, naming the port):
// nothing typed, a malformed tcp: name, a path that does not exist, is a file or a folder, or
// may not be used. Empty when opening it is worth a try.
QString portProblem(const QString& port);

}  // namespace fivebar::widgets
