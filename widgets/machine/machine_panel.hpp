// SPDX-License-Identifier: GPL-3.0-or-later
// The machine panel: connection (the built-in simulated machine, or any port by name in the
// editable PortBox: a serial port found on the system, one typed, a pseudo-terminal, a network
// port tcp:HOST:PORT; recent ones remembered), the baud rate, the alarm / error banner, and the
// status the board reports: state, pen XY (mm), motor angles (deg), planner blocks and RX buffer
// bytes free.
// It shows the session's state (MachineView) and never stores it; it may only connect and
// disconnect (ConnectionPort) and, in the banner, recover (RecoveryPort).
#pragma once

#include <QWidget>

class QGroupBox;

#include "session/machine_ports.hpp"
#include "session/machine_view.hpp"

#include <functional>
#include <optional>

class QComboBox;
class QFrame;
class QLabel;
class QPushButton;

namespace fivebar::widgets {

class MachineBanner;
class PortBox;

class MachinePanel : public QWidget {
  Q_OBJECT
 public:
  MachinePanel(session::MachineView& view, session::ConnectionPort& connection,
               session::RecoveryPort& recovery, QWidget* parent = nullptr);

  // Speed-up of the simulated machine connected from this panel (1 = real time).
  void setSimulationSpeedup(double speedup) { simSpeedup_ = speedup; }

  PortBox* portBox() const { return ports_; }
  QComboBox* baudBox() const { return baud_; }
  QPushButton* connectButton() const { return connect_; }
  QPushButton* disconnectButton() const { return disconnect_; }
  MachineBanner* banner() const { return banner_; }
  QLabel* stateLabel() const { return state_; }
  QLabel* linkLabel() const { return link_; }
  QLabel* penLabel() const { return pen_; }
  QLabel* positionLabel() const { return xy_; }
  // The warning shown while the board's $ settings differ from the profile's.
  QFrame* settingsWarning() const { return settingsWarning_; }
  QLabel* settingsWarningText() const { return settingsText_; }
  // What "Review and write..." opens (the machine settings dialog).
  void setOpenSettings(std::function<void()> open) { openSettings_ = std::move(open); }

 public slots:
  void refreshPorts();
  // Connect: opens what the port box names (chosenPort) at the baud box's rate; a port that
  // cannot be opened is said in the link line and a message box, naming it. A port that
  // answered goes first in the recent list.
  void connectSelected();
  // Puts `port` in the port box (and `baudRate` in the baud box, when given), then connects
  // as the Connect button does (fivebar-studio --port PATH [--baud N]).
  void connectTo(const QString& port, std::optional<int> baudRate = std::nullopt);
  void refreshStatus();

 private:
  // The constructor's parts.
  QGroupBox* makeConnectionBox();
  QGroupBox* makeStatusBox();
  void makeSettingsWarning();
  void connectControls();
  void refreshConnection();
  void refreshSettings();
  void onConnectFailed(const QString& message);
  void showConnectProblem(const QString& message);
  void onConnectionChanged();

  session::MachineView& view_;
  session::ConnectionPort& connection_;
  double simSpeedup_ = 1.0;
  PortBox* ports_ = nullptr;
  QComboBox* baud_ = nullptr;
  QPushButton* refresh_ = nullptr;
  QPushButton* connect_ = nullptr;
  QPushButton* disconnect_ = nullptr;
  QLabel* link_ = nullptr;
  MachineBanner* banner_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* xy_ = nullptr;
  QLabel* angles_ = nullptr;
  QLabel* buffers_ = nullptr;
  QLabel* pen_ = nullptr;
  QFrame* settingsWarning_ = nullptr;
  QLabel* settingsText_ = nullptr;
  QPushButton* settingsButton_ = nullptr;
  std::function<void()> openSettings_;
  QString failure_;  // why the last connection attempt failed (shown until the next one)
  QString pending_;  // the port being connected, remembered once the board answers
};

// A readable (translated) name of a GRBL state.
QString stateName(grbl::MachineState state);

}  // namespace fivebar::widgets
