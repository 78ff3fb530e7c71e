// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/port_box.hpp"

#include <QAbstractItemView>
#include <QCompleter>
#include <QScreen>
#include <QScrollBar>
#include <QFileInfo>
#include <QLineEdit>
#include <QSettings>

#include "session/port_names.hpp"

namespace fivebar::widgets {
namespace {

const char* const kRecentKey = "machine/recentPorts";

// The device a serial port name stands for: QSerialPort opens a bare name ("ttyUSB0") in /dev.
QString devicePath(const QString& port) {
#ifdef Q_OS_UNIX
  if (!port.startsWith(u'/') && !port.startsWith(u'.')) return QStringLiteral("/dev/") + port;
#endif
  return port;
}

}  // namespace

const QString PortBox::kSimulated = QStringLiteral("sim:");

PortBox::PortBox(QWidget* parent) : QComboBox(parent) {
  setObjectName(QStringLiteral("machinePorts"));
  setEditable(true);
  setInsertPolicy(QComboBox::NoInsert);
  // Suggestions in a popup, never completed inline: /dev/pts/2 must not silently become
  // /dev/pts/21 because that one was used before.
  completer()->setCompletionMode(QCompleter::PopupCompletion);
  completer()->setCaseSensitivity(Qt::CaseSensitive);
  lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0 or tcp:HOST:PORT"));
  setToolTip(tr("The board's port: pick one, or type any name: a serial device, a "
                "/dev/serial/by-id link, a pseudo-terminal (e.g. the firmware simulator's) or a "
                "network port tcp:HOST:PORT (ser2net, a FluidNC or grblHAL board)"));
  setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  setMinimumContentsLength(16);
  refresh();
  const QStringList recent = recentPorts();
  choose(recent.isEmpty() ? kSimulated : recent.front());
}

void PortBox::refresh() {
  const QString chosen = count() > 0 ? chosenPort() : QString();
  clear();
  addItem(tr("Simulated machine (built in)"), kSimulated);
  std::vector<session::PortInfo> found = session::availableSerialPorts();
  const auto labelOf = [](const session::PortInfo& port) {
    return port.description.isEmpty() ? port.systemPath
                                      : QStringLiteral("%1 (%2)").arg(port.systemPath, port.description);
  };
  const auto separate = [this] {
    if (count() > 0 && !itemText(count() - 1).isEmpty()) insertSeparator(count());
  };
  separate();
  for (const QString& port : recentPorts()) {
    if (port == kSimulated) continue;
    QString label = port;
    for (const session::PortInfo& f : found)
      if (f.systemPath == port) label = labelOf(f);
    addItem(label, port);
    setItemData(count() - 1, tr("Connected to recently"), Qt::ToolTipRole);
  }
  separate();
  for (const session::PortInfo& port : found)
    if (findData(port.systemPath) < 0) addItem(labelOf(port), port.systemPath);
  if (itemText(count() - 1).isEmpty()) removeItem(count() - 1);  // no trailing separator
  if (!chosen.isEmpty()) choose(chosen);
}

QString PortBox::chosenPort() const {
  const QString text = currentText().trimmed();
  if (text.isEmpty()) return {};
  const int index = findText(text);
  return index >= 0 ? itemData(index).toString() : text;
}

void PortBox::choose(const QString& port) {
  const int index = findData(port);
  if (index >= 0) setCurrentIndex(index);
  else setEditText(port);
}

void PortBox::remember(const QString& port) {
  if (port.isEmpty()) return;
  QStringList recent = recentPorts();
  recent.removeAll(port);
  recent.prepend(port);
  while (recent.size() > kRecentPorts) recent.removeLast();
  QSettings().setValue(kRecentKey, recent);
  refresh();
}

void PortBox::showPopup() {
  const int widest = view()->sizeHintForColumn(0) + 2 * view()->frameWidth() +
                     view()->verticalScrollBar()->sizeHint().width();
  const int room = screen() ? screen()->availableGeometry().width() / 2 : widest;
  view()->setMinimumWidth(qMin(qMax(width(), widest), qMax(width(), room)));
  QComboBox::showPopup();
}

QStringList PortBox::recentPorts() { return QSettings().value(kRecentKey).toStringList(); }

void PortBox::forgetRecentPorts() { QSettings().remove(kRecentKey); }

QString portProblem(const QString& port) {
  if (port.isEmpty())
    return PortBox::tr("Choose a port or type its name, for example /dev/ttyUSB0, a pseudo-terminal "
                       "such as /tmp/grblpty, or a network port tcp:HOST:PORT.");
  if (port == PortBox::kSimulated) return {};
  if (session::isNetworkPortName(port)) {
    if (session::isValidNetworkPortName(port)) return {};
    return PortBox::tr("%1 is not a network port: write it as tcp:HOST:PORT, for example "
                       "tcp:192.168.1.20:23.")
        .arg(port);
  }
  const QFileInfo device(devicePath(port));
  if (!device.exists())
    return PortBox::tr("There is no port %1. Check the name, that the board is plugged in and "
                       "powered, or that the simulator is running (Refresh lists the serial ports "
                       "found).")
        .arg(port);
  if (device.isDir())
    return PortBox::tr("%1 is a folder, not a port: choose the board's serial port (e.g. "
                       "/dev/ttyUSB0) or type a network port tcp:HOST:PORT.")
        .arg(port);
  if (device.isFile())
    return PortBox::tr("%1 is a file, not a port: choose the board's serial port (e.g. "
                       "/dev/ttyUSB0) or type a network port tcp:HOST:PORT.")
        .arg(port);
  if (!device.isReadable() || !device.isWritable())
    return PortBox::tr("No permission to use %1: add your user to the group that owns it (usually "
                       "dialout: sudo adduser $USER dialout), then log out and in again.")
        .arg(port);
  return {};
}

}  // namespace fivebar::widgets
