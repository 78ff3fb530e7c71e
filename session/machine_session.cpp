// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/machine_session.hpp"

#include <QTimer>
#include <cctype>

#include "core/kinematics/units.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/protocol/pen_state.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/transport/open_transport.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "drivers/transport/simulated_transport.hpp"
#include "i18n/translated.hpp"

namespace fivebar::session {
namespace {

constexpr int kSimClockMs = 5;

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

// The motion check's reasons in the user's language; their advice names the CLI's commands,
// which in the studio are buttons.
QString MachineSession::studioText(const Message& reason) {
  QString text = translated(reason);
  text.replace(translated(motion::referenceHint()),
               tr("set the reference pose (Machine panel) or home the machine"));
  text.replace(translated(motion::workspaceHint()), tr("choose a target inside the workspace"));
  return text;
}

MachineSession::MachineSession(const StudioInputs& inputs, QObject* parent)
    : QObject(parent), inputs_(inputs) {
  connectTimer_ = new QTimer(this);
  connectTimer_->setSingleShot(true);
  connect(connectTimer_, &QTimer::timeout, this, &MachineSession::onConnectTimeout);
  // Another profile expects other settings: compare again.
  connect(&inputs_, &StudioInputs::profileChanged, this, &MachineSession::boardSettingsChanged);
  connect(&inputs_, &StudioInputs::plannedJobChanged, this, &MachineSession::plannedJobChanged);
}

MachineSession::~MachineSession() {
  tearingDown_ = true;
  settingsSync_.reset();
  if (link_) link_->protocol().removeListener(this);
  link_.reset();
  transport_.reset();
}

bool MachineSession::connectSimulated(double speedup, const sim::Fault& fault, QString* error) {
  sim::SimConfig config;
  config.profile = inputs_.profile();
  config.fault = fault;
  config.trueMachine = simTrueMachine_;
  config.setUp = true;  // a board set up for the profile; it starts at MPos 0,0 (no reference)
  auto transport = std::make_unique<SimulatedTransport>(config, speedup);
  SimulatedTransport* simulated = transport.get();
  if (!openLink(std::move(transport), error)) return false;
  simulated_ = simulated;
  simulated_->startClock(kSimClockMs);
  return true;
}

void MachineSession::setSimulatedTrueMachine(std::optional<MachineProfile> trueMachine) {
  simTrueMachine_ = std::move(trueMachine);
  if (simulated_) simulated_->machine().setTrueMachine(simTrueMachine_);
}

std::vector<std::vector<Vec2>> MachineSession::simulatedDrawnTrace() const {
  if (!simulated_) return {};
  return simulated_->machine().drawnTrace();
}

bool MachineSession::connectSerial(const QString& portPath, int baudRate, QString* error) {
  const QString target = portPath.startsWith(QLatin1String("tcp:")) ? portPath
                                                                     : tr("%1 at %2 baud").arg(portPath).arg(baudRate);
  if (!openLink(makePortTransport(portPath, baudRate), error)) return false;
  connectTarget_ = target;
  return true;
}

bool MachineSession::openLink(std::unique_ptr<Transport> transport, QString* error) {
  if (link_) disconnectMachine();
  QString openError;
  if (!transport->open(&openError)) {
    *error = openError.isEmpty() ? tr("Cannot open %1.").arg(transport->name()) : openError;
    emit consoleLine(*error, ConsoleKind::Problem);
    return false;
  }
  transport_ = std::move(transport);
  link_ = std::make_unique<MachineLink>(*transport_, kPollIntervalS, kTickMs);
  link_->poseTrust().changed = [this] { emit poseKnownChanged(); };
  link_->protocol().addListener(this);
  link_->start();
  answered_ = false;
  connectTarget_ = linkName();
  consoleAbsolute_ = true;
  pen_ = PenState::Unknown;
  boardSettings_.reset();
  emit consoleLine(tr("Opened %1; waiting for the board to answer...").arg(linkName()), ConsoleKind::Info);
  connectTimer_->start(kConnectTimeoutMs);
  emit connectionChanged(false);  // "connecting": panels show it
  return true;
}

void MachineSession::onConnectTimeout() {
  if (!link_ || answered_) return;
  const QString message =
      tr("No GRBL board answered on %1 within %2 s. Check that the port is the machine's, that "
         "the baud rate matches its firmware (GRBL 1.1: usually 115200) and that it is powered.")
          .arg(connectTarget_)
          .arg(kConnectTimeoutMs / 1000);
  teardown(message);
  emit connectFailed(message);
}

void MachineSession::disconnectMachine() { teardown(tr("Disconnected.")); }

void MachineSession::teardown(const QString& reason) {
  if (!link_ || tearingDown_) return;
  tearingDown_ = true;
  emit aboutToDisconnect();
  connectTimer_->stop();
  settingsSync_.reset();
  boardSettings_.reset();
  ignoreSettings_ = false;
  answered_ = false;
  pen_ = PenState::Unknown;
  link_->protocol().removeListener(this);
  link_->stopClock();
  transport_->close();
  link_.reset();
  transport_.reset();
  simulated_ = nullptr;
  userLines_.clear();
  settle_.clear();
  problem_ = {};
  tearingDown_ = false;
  emit consoleLine(reason, ConsoleKind::Info);
  emit problemChanged();
  emit penStateChanged();
  emit boardSettingsChanged();
  emit connectionChanged(false);
}

// The port path, or the built-in simulator in the user's language.
QString MachineSession::linkName() const {
  if (!transport_) return {};
  if (dynamic_cast<const SimulatedTransport*>(transport_.get()) != nullptr)
    return tr("the simulated machine");
  return transport_->name();
}

grbl::MachineState MachineSession::state() const {
  return link_ ? link_->protocol().state() : grbl::MachineState::Unknown;
}

const grbl::StatusReport* MachineSession::lastStatus() const {
  if (!link_ || link_->protocol().statusReportsSeen() == 0) return nullptr;
  return &link_->protocol().lastStatus();
}

std::optional<JointAngles> MachineSession::motorAngles() const {
  if (!link_ || !poseKnown()) return std::nullopt;
  return link_->protocol().motorAngles();
}

bool MachineSession::poseKnown() const { return link_ && link_->poseTrust().known(); }

grbl::PoseDoubt MachineSession::poseDoubt() const {
  return link_ ? link_->poseTrust().doubt() : grbl::PoseDoubt::Disconnected;
}

QString MachineSession::poseDoubtText() const {
  const QString todo = inputs_.profile().hasHomingSwitches
                           ? tr("Home the machine (Home), or put the arms in the home pose and press Set reference pose.")
                           : tr("Put the arms in the home pose by hand and press Set reference pose.");
  switch (poseDoubt()) {
    case grbl::PoseDoubt::None: return {};
    case grbl::PoseDoubt::NotYetRead: return tr("Reading where the machine stands...");
    case grbl::PoseDoubt::NotReferenced:
      return tr("The machine's position is not known: this board has not been referenced from this "
                "computer yet. %1").arg(todo);
    case grbl::PoseDoubt::PositionChanged:
      return tr("The machine's position is not known: the board was powered up or reset since it was "
                "last seen, so the position it reports says nothing about where the arms stand. %1")
          .arg(todo);
    case grbl::PoseDoubt::ResetInMotion:
      return tr("The machine's position is not known: it was reset or stopped hard while moving, and "
                "the motors may have lost steps. %1").arg(todo);
    case grbl::PoseDoubt::HomingFailed:
      return tr("The machine's position is not known: the homing cycle moved the arms and did not "
                "finish. %1").arg(todo);
    case grbl::PoseDoubt::RunInterrupted:
      return tr("The machine's position is not known: it moved while no program watched it (a job "
                "cut off by a crash, a closed connection or another program). %1").arg(todo);
    case grbl::PoseDoubt::Disconnected: return tr("Not connected.");
  }
  return {};
}

std::optional<Vec2> MachineSession::penMm() const {
  const auto q = motorAngles();
  if (!q) return std::nullopt;
  const FkResult fk = forward(inputs_.profile().geometry, *q, inputs_.profile().assembly);
  if (!fk.ok()) return std::nullopt;
  return fk.p;
}

int MachineSession::bytesInFlight() const { return link_ ? link_->protocol().bytesInFlight() : 0; }

std::optional<JointAngles> MachineSession::jogStart() const {
  if (settle_.pendingEnd()) return settle_.pendingEnd();
  return motorAngles();
}

bool MachineSession::canJog() const {
  if (!isConnected() || jobActive_ || settle_.blocked()) return false;
  const grbl::MachineState s = state();
  return (s == grbl::MachineState::Idle || s == grbl::MachineState::Jog) && motorAngles().has_value() &&
         !settingsStopMoves();
}

void MachineSession::dismissProblem() {
  if (problem_.kind == MachineProblem::Kind::Error) setProblem({});
}

void MachineSession::setJobActive(bool active) {
  if (jobActive_ == active) return;
  jobActive_ = active;
  emit jobActiveChanged(active);
}

void MachineSession::setProblem(MachineProblem problem) {
  problem_ = std::move(problem);
  emit problemChanged();
}

void MachineSession::onAck(const grbl::Ack& ack) {
  if (settle_.answered(ack.id, ack.ok()) == jog::JogSettle::AckAction::CancelAgain && link_)
    link_->protocol().sendRealtime(grbl::realtime::kJogCancel);
  const bool user = userLines_.erase(ack.id) > 0;
  if (!user) return;
  if (ack.ok()) {
    if (problem_.kind == MachineProblem::Kind::Error) setProblem({});
    // A setting written from the console: compare the board's settings with the profile anew.
    if (ack.line.size() > 2 && ack.line[0] == '$' && std::isdigit(static_cast<unsigned char>(ack.line[1])) &&
        ack.line.find('=') != std::string::npos)
      QTimer::singleShot(0, this, [this] { readBoardSettings(); });
    return;
  }
  MachineProblem p;
  p.kind = MachineProblem::Kind::Error;
  p.code = ack.errorCode;
  p.text = tr("%1 was rejected: %2").arg(fromStd(ack.line), fromStd(grbl::describeError(ack.errorCode)));
  setProblem(p);
}

void MachineSession::onStatus(const grbl::StatusReport& report) {
  if (!answered_ && link_) {
    answered_ = true;
    connectTimer_->stop();
    emit consoleLine(tr("Connected to %1.").arg(linkName()), ConsoleKind::Info);
    emit connectionChanged(true);
    // Compare the board's $ settings with the profile right away (the machine panel shows
    // the differences; Start explains them).
    readBoardSettings();
  }
  settle_.reported(report.state, report.wco.has_value());
  // The pen as the board reports it (its running spindle state, or Z).
  const auto work = link_ ? link_->protocol().workPositionDeg() : std::nullopt;
  switch (grbl::penFromStatus(inputs_.profile().tool, report,
                              work ? std::optional<double>(work->v[2]) : std::nullopt)) {
    case grbl::BoardPen::Up: setPenState(PenState::Up); break;
    case grbl::BoardPen::Down: setPenState(PenState::Down); break;
    case grbl::BoardPen::Unknown: break;
  }
  if (report.state == grbl::MachineState::Alarm && problem_.kind != MachineProblem::Kind::Alarm) {
    MachineProblem p;
    p.kind = MachineProblem::Kind::Alarm;
    p.text = tr("The machine is locked (alarm state). Unlock it with $X or home it with $H "
                "once you know where it stands.");
    setProblem(p);
  } else if (report.state != grbl::MachineState::Alarm &&
             report.state != grbl::MachineState::Unknown &&
             problem_.kind == MachineProblem::Kind::Alarm) {
    setProblem({});
  }
  emit statusUpdated();
}

void MachineSession::onAlarm(int code, const std::vector<std::uint64_t>& lostIds) {
  for (std::uint64_t id : lostIds) userLines_.erase(id);
  settle_.interrupted(lostIds);
  MachineProblem p;
  p.kind = MachineProblem::Kind::Alarm;
  p.code = code;
  p.text = fromStd(grbl::describeAlarm(code));
  setProblem(p);
}

void MachineSession::onReset(const std::string& version, const std::vector<std::uint64_t>& lostIds,
                             const std::vector<std::uint64_t>& dropped) {
  std::vector<std::uint64_t> lost = lostIds;
  lost.insert(lost.end(), dropped.begin(), dropped.end());
  for (std::uint64_t id : lost) userLines_.erase(id);
  settle_.interrupted(lost);
  consoleAbsolute_ = true;
  setPenState(PenState::Unknown);
  emit consoleLine(tr("The board reset (Grbl %1).").arg(fromStd(version)), ConsoleKind::Info);
  if (problem_.kind == MachineProblem::Kind::Error) {
    setProblem({});
  } else if (problem_.needsReset) {
    problem_.needsReset = false;
    emit problemChanged();
  }
}

void MachineSession::onLine(const grbl::ParsedLine& line) {
  using grbl::LineKind;
  // Status reports are shown by the panel; the banner is logged by onReset.
  if (line.kind == LineKind::Status || line.kind == LineKind::Empty || line.kind == LineKind::Banner) return;
  if (line.kind == LineKind::Ok && jobActive_) return;
  const bool bad = line.kind == LineKind::Error || line.kind == LineKind::Alarm;
  QString text;
  switch (line.kind) {
    case LineKind::Ok: text = QStringLiteral("ok"); break;
    case LineKind::Error: text = fromStd(grbl::describeError(line.code)); break;
    case LineKind::Alarm: text = fromStd(grbl::describeAlarm(line.code)); break;
    case LineKind::Message: text = QStringLiteral("[MSG:%1]").arg(fromStd(line.text)); break;
    case LineKind::Setting:
      text = QStringLiteral("$%1=%2").arg(line.settingId).arg(line.settingValue);
      break;
    default: text = fromStd(line.text); break;
  }
  if (line.kind == LineKind::Message && line.text.find("Reset to continue") != std::string::npos &&
      problem_.kind == MachineProblem::Kind::Alarm) {
    problem_.needsReset = true;
    emit problemChanged();
  }
  emit consoleLine(text, bad ? ConsoleKind::Problem : ConsoleKind::Received);
}

void MachineSession::onDisconnected(const std::string& reason) {
  const QString why = tr("Connection lost: %1").arg(fromStd(reason));
  // Not from inside the transport's signal: the transport is deleted by the teardown.
  QTimer::singleShot(0, this, [this, why] { teardown(why); });
}

}  // namespace fivebar::session
