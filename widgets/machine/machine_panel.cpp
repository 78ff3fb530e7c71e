// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/machine_panel.hpp"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/kinematics/units.hpp"
#include "widgets/machine/machine_banner.hpp"
#include "widgets/machine/port_box.hpp"
#include "session/port_names.hpp"
#include "session/settings_advice.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kBaudRates[] = {9600, 19200, 38400, 57600, 115200, 230400, 250000};

QString colourOfState(grbl::MachineState s) {
  using grbl::MachineState;
  switch (s) {
    case MachineState::Idle: return QStringLiteral("#15803d");
    case MachineState::Run:
    case MachineState::Jog:
    case MachineState::Home: return QStringLiteral("#1d4ed8");
    case MachineState::Hold:
    case MachineState::Door: return QStringLiteral("#b45309");
    case MachineState::Alarm: return QStringLiteral("#dc2626");
    default: return QStringLiteral("#6b7280");
  }
}

}  // namespace

QString stateName(grbl::MachineState state) {
  using grbl::MachineState;
  switch (state) {
    case MachineState::Idle: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Idle");
    case MachineState::Run: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Running");
    case MachineState::Hold: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "On hold");
    case MachineState::Jog: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Jogging");
    case MachineState::Alarm: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Alarm");
    case MachineState::Door: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Door open");
    case MachineState::Check: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Check mode");
    case MachineState::Home: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Homing");
    case MachineState::Sleep: return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Sleeping");
    case MachineState::Unknown: break;
  }
  return QCoreApplication::translate("fivebar::widgets::MachinePanel", "Unknown");
}

MachinePanel::MachinePanel(session::MachineView& view, session::ConnectionPort& link,
                           session::RecoveryPort& recovery, QWidget* parent)
    : QWidget(parent), view_(view), connection_(link) {
  setObjectName(QStringLiteral("machinePanel"));
  QGroupBox* connection = makeConnectionBox();
  banner_ = new MachineBanner(view_, recovery, this);
  QGroupBox* status = makeStatusBox();
  makeSettingsWarning();
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(banner_);  // first: a problem is the first thing to see
  layout->addWidget(settingsWarning_);
  layout->addWidget(connection);
  layout->addWidget(status);
  layout->addStretch(1);

  connectControls();
  refreshConnection();
  refreshStatus();
  refreshSettings();
}

// Port, baud rate, Connect / Disconnect and what the link is.
QGroupBox* MachinePanel::makeConnectionBox() {
  ports_ = new PortBox(this);
  refresh_ = new QPushButton(tr("Refresh"), this);
  refresh_->setToolTip(tr("List the serial ports again"));
  baud_ = new QComboBox(this);
  for (int rate : kBaudRates) baud_->addItem(QString::number(rate), rate);
  baud_->setCurrentIndex(baud_->findData(view_.profile().baudRate));
  connect_ = new QPushButton(tr("Connect"), this);
  disconnect_ = new QPushButton(tr("Disconnect"), this);
  link_ = new QLabel(this);
  link_->setWordWrap(true);

  auto* portRow = new QHBoxLayout;
  portRow->addWidget(ports_, 1);
  portRow->addWidget(refresh_);
  auto* baudRow = new QHBoxLayout;
  baudRow->addWidget(new QLabel(tr("Baud"), this));
  baudRow->addWidget(baud_, 1);
  auto* buttonRow = new QHBoxLayout;
  buttonRow->addWidget(connect_);
  buttonRow->addWidget(disconnect_);
  auto* connection = new QGroupBox(tr("Connection"), this);
  auto* connectionLayout = new QVBoxLayout(connection);
  connectionLayout->addLayout(portRow);
  connectionLayout->addLayout(baudRow);
  connectionLayout->addLayout(buttonRow);
  connectionLayout->addWidget(link_);
  return connection;
}

// The board's state, pen, position, motor angles and buffers.
QGroupBox* MachinePanel::makeStatusBox() {
  state_ = new QLabel(this);
  state_->setObjectName(QStringLiteral("machineState"));
  QFont big = state_->font();
  big.setBold(true);
  big.setPointSizeF(big.pointSizeF() * 1.3);
  state_->setFont(big);
  xy_ = new QLabel(this);
  angles_ = new QLabel(this);
  buffers_ = new QLabel(this);
  for (QLabel* l : {xy_, angles_, buffers_}) l->setTextInteractionFlags(Qt::TextSelectableByMouse);
  buffers_->setWordWrap(true);
  pen_ = new QLabel(this);
  pen_->setObjectName(QStringLiteral("machinePen"));
  auto* status = new QGroupBox(tr("Status"), this);
  auto* form = new QFormLayout(status);
  form->addRow(tr("State"), state_);
  form->addRow(tr("Pen"), pen_);
  form->addRow(tr("Pen (X, Y)"), xy_);
  form->addRow(tr("Motors (θ1, θ2)"), angles_);
  form->addRow(tr("Buffers"), buffers_);
  return status;
}

// "The board's settings differ from the profile": shown while they do, with Review and write...
void MachinePanel::makeSettingsWarning() {
  settingsWarning_ = new QFrame(this);
  settingsWarning_->setObjectName(QStringLiteral("settingsWarning"));
  settingsWarning_->setStyleSheet(QStringLiteral(
      "#settingsWarning { background: #fef3c7; border: 1px solid #d97706; border-radius: 4px; }"));
  settingsText_ = new QLabel(settingsWarning_);
  settingsText_->setWordWrap(true);
  settingsButton_ = new QPushButton(tr("Review and write..."), settingsWarning_);
  settingsButton_->setToolTip(tr("Compare the board's settings with the profile and write the "
                                 "differences (a backup is saved first)"));
  auto* warningLayout = new QVBoxLayout(settingsWarning_);
  warningLayout->setContentsMargins(8, 6, 8, 6);
  warningLayout->addWidget(settingsText_);
  warningLayout->addWidget(settingsButton_, 0, Qt::AlignLeft);
  settingsWarning_->hide();
  connect(settingsButton_, &QPushButton::clicked, this, [this] {
    if (openSettings_) openSettings_();
  });
}

void MachinePanel::connectControls() {
  connect(refresh_, &QPushButton::clicked, this, &MachinePanel::refreshPorts);
  connect(connect_, &QPushButton::clicked, this, &MachinePanel::connectSelected);
  connect(disconnect_, &QPushButton::clicked, this, [this] { connection_.disconnectMachine(); });
  connect(ports_, &QComboBox::currentIndexChanged, this, &MachinePanel::refreshConnection);
  connect(ports_, &QComboBox::editTextChanged, this, &MachinePanel::refreshConnection);
  connect(ports_->lineEdit(), &QLineEdit::returnPressed, this, [this] {
    if (connect_->isEnabled()) connectSelected();
  });
  connect(&view_, &session::MachineView::connectionChanged, this, &MachinePanel::onConnectionChanged);
  connect(&view_, &session::MachineView::connectionChanged, this, &MachinePanel::refreshStatus);
  connect(&view_, &session::MachineView::statusUpdated, this, &MachinePanel::refreshStatus);
  connect(&view_, &session::MachineView::penStateChanged, this, &MachinePanel::refreshStatus);
  connect(&view_, &session::MachineView::boardSettingsChanged, this, &MachinePanel::refreshSettings);
  connect(&view_, &session::MachineView::connectFailed, this, &MachinePanel::onConnectFailed);
}

void MachinePanel::onConnectionChanged() {
  if (view_.isConnected() && !pending_.isEmpty()) {
    ports_->remember(pending_);  // it answered: worth offering first next time
    pending_.clear();
  }
  refreshConnection();
}

void MachinePanel::showConnectProblem(const QString& message) {
  failure_ = message;
  refreshConnection();
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot connect"), message, QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("connectProblemMessage"));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

void MachinePanel::onConnectFailed(const QString& message) {
  failure_ = message;
  refreshConnection();
  auto* box = new QMessageBox(QMessageBox::Warning, tr("No answer from the machine"), message,
                              QMessageBox::Ok, this);
  box->setObjectName(QStringLiteral("connectFailedMessage"));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

void MachinePanel::refreshSettings() {
  const auto diffs = view_.settingDifferences();
  settingsWarning_->setVisible(view_.isConnected() && !diffs.empty());
  if (diffs.empty()) return;
  settingsText_->setText(session::settingsWarningText(diffs));
}

void MachinePanel::refreshPorts() {
  ports_->refresh();
  refreshConnection();
}

void MachinePanel::connectSelected() {
  const QString port = ports_->chosenPort();
  failure_.clear();
  pending_.clear();
  if (const QString problem = portProblem(port); !problem.isEmpty()) {
    showConnectProblem(problem);
    return;
  }
  pending_ = port;
  QString error;
  const bool ok = port == PortBox::kSimulated
                      ? connection_.connectSimulated(simSpeedup_, sim::Fault{}, &error)
                      : connection_.connectSerial(port, baud_->currentData().toInt(), &error);
  if (!ok) {
    pending_.clear();
    showConnectProblem(error.isEmpty() ? tr("Cannot open %1.").arg(port) : error);
  }
}

void MachinePanel::connectTo(const QString& port, std::optional<int> baudRate) {
  ports_->choose(port);
  if (baudRate) {
    if (baud_->findData(*baudRate) < 0) baud_->addItem(QString::number(*baudRate), *baudRate);
    baud_->setCurrentIndex(baud_->findData(*baudRate));
  }
  connectSelected();
}

void MachinePanel::refreshConnection() {
  const bool connected = view_.isConnected();
  const QString port = ports_->chosenPort();
  const bool hasBaud = port != PortBox::kSimulated && session::portHasBaudRate(port);
  refresh_->setEnabled(!connected);
  baud_->setEnabled(!connected && hasBaud);
  const bool connecting = view_.isConnecting();
  connect_->setEnabled(!connected && !connecting);
  disconnect_->setEnabled(connected || connecting);
  ports_->setEnabled(!connected && !connecting);
  link_->setStyleSheet(!connected && !connecting && !failure_.isEmpty() ? QStringLiteral("color: #b91c1c")
                                                                        : QString());
  if (connected) link_->setText(tr("Connected to %1").arg(view_.linkName()));
  else if (connecting) link_->setText(tr("Connecting to %1: waiting for the board to answer...").arg(view_.linkName()));
  else link_->setText(failure_.isEmpty() ? tr("Not connected") : failure_);
}

void MachinePanel::refreshStatus() {
  const grbl::StatusReport* report = view_.lastStatus();
  const grbl::MachineState s = view_.isConnected() ? view_.state() : grbl::MachineState::Unknown;
  state_->setText(view_.isConnected() ? stateName(s) : tr("Offline"));
  state_->setStyleSheet(QStringLiteral("color: %1").arg(colourOfState(s)));
  switch (view_.isConnected() ? view_.penState() : session::PenState::Unknown) {
    case session::PenState::Up: pen_->setText(tr("up")); break;
    case session::PenState::Down: pen_->setText(tr("down (drawing)")); break;
    case session::PenState::Unknown: pen_->setText(view_.isConnected() ? tr("not known yet") : QStringLiteral("–")); break;
  }
  const auto pen = view_.penMm();
  const bool unknown = view_.isConnected() && report != nullptr && !view_.poseKnown();
  xy_->setText(pen       ? tr("%1, %2 mm").arg(QLocale().toString(pen->x(), 'f', 2)).arg(QLocale().toString(pen->y(), 'f', 2))
               : unknown ? tr("unknown (set the reference pose)")
                         : QStringLiteral("–"));
  const auto q = view_.motorAngles();
  // Single poses are shown normalised to (-180, 180] (conventions.md).
  angles_->setText(q ? tr("%1°, %2°")
                           .arg(QLocale().toString(normalizeDeg(degFromRad(q->theta1)), 'f', 2))
                           .arg(QLocale().toString(normalizeDeg(degFromRad(q->theta2)), 'f', 2))
                     : QStringLiteral("–"));
  if (report && report->plannerBlocksFree && report->rxBytesFree) {
    buffers_->setText(tr("planner %1 of %2 blocks free, RX %3 of %4 bytes free")
                          .arg(*report->plannerBlocksFree)
                          .arg(grbl::kPlannerBlocks)
                          .arg(*report->rxBytesFree)
                          .arg(grbl::kRxBufferBytes));
  } else {
    buffers_->setText(QStringLiteral("–"));
  }
}

}  // namespace fivebar::widgets
