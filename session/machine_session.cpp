#include "session/machine_session.hpp"

#include <QTimer>

#include "core/kinematics/units.hpp"
#include "drivers/gcode_job.hpp"
#include "drivers/grbl_codes.hpp"
#include "drivers/jog.hpp"
#include "drivers/motion_check.hpp"
#include "drivers/serial_transport.hpp"
#include "drivers/simulated_transport.hpp"
#include "session/core_message.hpp"

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

namespace {

}  // namespace

MachineSession::MachineSession(const StudioInputs& inputs, QObject* parent)
    : QObject(parent), inputs_(inputs) {
  connectTimer_ = new QTimer(this);
  connectTimer_->setSingleShot(true);
  connect(connectTimer_, &QTimer::timeout, this, &MachineSession::onConnectTimeout);
  // Another profile expects other settings: compare again.
  connect(&inputs_, &StudioInputs::profileChanged, this, &MachineSession::boardSettingsChanged);
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
  const QString target = tr("%1 at %2 baud").arg(portPath).arg(baudRate);
  if (!openLink(std::make_unique<SerialTransport>(portPath, baudRate), error)) return false;
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
  if (!link_) return std::nullopt;
  return link_->protocol().motorAngles();
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
  return (s == grbl::MachineState::Idle || s == grbl::MachineState::Jog) && motorAngles().has_value();
}

bool MachineSession::enqueueUserLine(const std::string& line, bool log) {
  if (!link_) {
    emit consoleLine(tr("Not connected: %1 was not sent.").arg(fromStd(line)), ConsoleKind::Problem);
    return false;
  }
  const grbl::EnqueueResult r = link_->protocol().enqueue(line);
  if (!r.ok()) {
    emit consoleLine(tr("Not sent (%1): %2").arg(fromStd(grbl::describe(r.status)), fromStd(line)),
                     ConsoleKind::Problem);
    return false;
  }
  userLines_.insert(r.id);
  if (log) emit consoleLine(fromStd(line), ConsoleKind::Sent);
  return true;
}

bool MachineSession::sendLine(const QString& line, QString* refusal) {
  const std::string text = line.trimmed().toStdString();
  if (text.empty()) return false;
  if (jobActive_) {
    const QString why = tr("A job is running: %1 was not sent.").arg(fromStd(text));
    if (refusal) *refusal = why;
    emit consoleLine(why, ConsoleKind::Problem);
    return false;
  }
  if (!unchecked_) {
    QString why;
    if (!checkConsoleLine(text, &why)) {
      if (refusal) *refusal = why;
      emit consoleLine(tr("Not sent: %1").arg(fromStd(text)), ConsoleKind::Problem);
      emit consoleLine(why, ConsoleKind::Problem);
      emit lineRefused(why);
      return false;
    }
  } else {
    emit consoleLine(tr("Unchecked: %1").arg(fromStd(text)), ConsoleKind::Info);
  }
  return enqueueUserLine(text, true);
}

// The one motion check (drivers/motion_check) from the board's reported pose. A motion line
// needs a machine standing still with nothing of ours in flight, so the pose it starts from is
// the pose the board reports.
bool MachineSession::checkConsoleLine(const std::string& line, QString* refusal) {
  const auto reported = link_ ? motion::boardPoseOf(link_->protocol()) : std::nullopt;
  motion::BoardPose pose = reported.value_or(motion::BoardPose{});
  pose.absolute = consoleAbsolute_;
  const motion::LineCheck interpreted = motion::interpretLine(line, pose);
  if (!interpreted.ok()) {
    *refusal = studioText(interpreted.reason);
    return false;
  }
  if (interpreted.verdict == motion::Verdict::Motion) {
    if (!reported) {
      *refusal = tr("The machine's position is not known yet (no status report with its work "
                    "position): wait a moment, or set the reference pose.");
      return false;
    }
    if (!userLines_.empty() || state() != grbl::MachineState::Idle || !jogSettled()) {
      *refusal = tr("The machine is still moving or busy: send a move when it stands still "
                    "(Idle), so it can be checked from where the machine really is.");
      return false;
    }
    const motion::LineCheck checked = motion::checkLine(inputs_.profile(), line, pose);
    if (!checked.ok()) {
      *refusal = studioText(checked.reason);
      return false;
    }
  }
  motion::BoardPose after = pose;
  motion::applyLine(line, interpreted, after);
  consoleAbsolute_ = after.absolute;
  return true;
}

void MachineSession::setUncheckedConsole(bool on) {
  if (unchecked_ == on) return;
  unchecked_ = on;
  emit consoleLine(on ? tr("Console lines are sent UNCHECKED from now on.")
                      : tr("Console lines are checked again."),
                   on ? ConsoleKind::Problem : ConsoleKind::Info);
  emit uncheckedConsoleChanged(on);
}

void MachineSession::setPenState(PenState pen) {
  if (pen_ == pen) return;
  pen_ = pen;
  emit penStateChanged();
}

void MachineSession::readBoardSettings() {
  if (!link_ || jobActive_) return;
  if (!settingsSync_) {
    settingsSync_ = std::make_unique<setup::SettingsSync>(link_->protocol());
    settingsSync_->changed = [this] {
      const setup::SetupState s = settingsSync_->state();
      if (s == setup::SetupState::Done) boardSettings_ = settingsSync_->board();
      if (s == setup::SetupState::Done || s == setup::SetupState::Failed) emit boardSettingsChanged();
    };
  }
  if (readingBoardSettings()) return;
  settingsSync_->read();
}

std::unique_ptr<setup::SettingsSync> MachineSession::makeSettingsSync() {
  if (!link_) return nullptr;
  return std::make_unique<setup::SettingsSync>(link_->protocol());
}

bool MachineSession::readingBoardSettings() const {
  return settingsSync_ && (settingsSync_->state() == setup::SetupState::Reading ||
                           settingsSync_->state() == setup::SetupState::Writing);
}

std::optional<std::array<double, 2>> MachineSession::workOffsetDeg() const {
  if (!link_ || !link_->protocol().workOffset()) return std::nullopt;
  const grbl::Axes& wco = *link_->protocol().workOffset();
  return std::array<double, 2>{wco.x(), wco.y()};
}

std::vector<setup::SettingDiff> MachineSession::settingDifferences() const {
  if (!boardSettings_) return {};
  return setup::compare(*boardSettings_, setup::expectedSettings(inputs_.profile()));
}

jog::JogPlan MachineSession::boardChecked(jog::JogPlan plan, bool clip) const {
  if (!plan.ok() || !link_) return plan;
  std::optional<motion::BoardPose> pose = motion::boardPoseOf(link_->protocol());
  const auto start = jogStart();
  if (!pose || !start) return plan;
  pose->workDeg[0] = degFromRad(start->theta1);
  pose->workDeg[1] = degFromRad(start->theta2);
  pose->absolute = consoleAbsolute_;
  const motion::LinesCheck c = motion::checkBoardLines(plan.lines, *pose);
  if (c.ok(plan.lines.size())) return plan;
  std::size_t motionLines = 0;
  for (std::size_t i = 0; i < c.passing; ++i)
    if (motion::interpretLine(plan.lines[i], motion::BoardPose{}).verdict == motion::Verdict::Motion)
      ++motionLines;
  const bool keep = clip && motionLines > 0;
  plan.lines.resize(keep ? c.passing : 0);
  plan.targets.resize(keep ? std::min(motionLines, plan.targets.size()) : 0);
  plan.status = keep ? jog::JogStatus::Clipped : jog::JogStatus::Blocked;
  plan.reason = c.reason;
  return plan;
}

bool MachineSession::sendJog(const jog::JogPlan& plan) {
  if (!canJog()) {
    emit consoleLine(tr("Jog refused: the machine is not idle, not connected or a job is running."),
                     ConsoleKind::Problem);
    return false;
  }
  if (!plan.ok()) return false;
  // The one motion check's board part, whoever planned the move (jog, go-to, home pose, frame).
  if (const jog::JogPlan checked = boardChecked(plan, false); !checked.ok()) {
    const QString why = studioText(checked.reason);
    emit consoleLine(tr("Move not sent: %1").arg(why), ConsoleKind::Problem);
    emit lineRefused(why);
    return false;
  }
  const bool logEach = plan.lines.size() <= 3;
  std::vector<std::uint64_t> ids;
  bool sent = true;
  for (const std::string& line : plan.lines) {
    if (!(sent = enqueueUserLine(line, logEach))) break;
    ids.push_back(*userLines_.rbegin());
  }
  settle_.jogSent(ids, sent && !plan.targets.empty() ? std::optional(plan.targets.back()) : std::nullopt);
  if (!sent) return false;
  if (!logEach)
    emit consoleLine(tr("%1 (jog in %2 checked moves)")
                         .arg(QString::fromStdString(plan.lines.back()))
                         .arg(plan.lines.size()),
                     ConsoleKind::Sent);
  return true;
}

void MachineSession::cancelJog() {
  if (!link_) return;
  const std::vector<std::uint64_t> dropped = link_->protocol().dropQueued();
  for (std::uint64_t id : dropped) userLines_.erase(id);
  link_->protocol().sendRealtime(grbl::realtime::kJogCancel);
  settle_.cancelled(dropped);
}

void MachineSession::unlock() { enqueueUserLine("$X", true); }

void MachineSession::home() {
  if (inputs_.profile().hasHomingSwitches) {
    enqueueUserLine("$H", true);
  } else {
    // Without switches the reference is declared; G10 is refused in alarm, so unlock first.
    if (state() == grbl::MachineState::Alarm) unlock();
    setReferencePose();
  }
}

bool MachineSession::goToHomePose(QString* why) {
  const auto from = jogStart();
  if (!canJog() || !from) {
    if (why) *why = tr("The machine must be connected, idle and its position known.");
    return false;
  }
  const MachineProfile& p = inputs_.profile();
  const FkResult home = forward(p.geometry, p.homeAngles, p.assembly);
  if (!home.ok()) {
    if (why) *why = tr("The profile's home pose does not close the linkage.");
    return false;
  }
  const jog::JogPlan plan = boardChecked(jog::planGoTo(p, *from, home.p), false);
  if (!plan.ok()) {
    if (why) *why = tr("No checked move to the home pose: %1").arg(studioText(plan.reason));
    return false;
  }
  if (!sendJog(plan)) {
    if (why) *why = tr("The move was not sent (see the console).");
    return false;
  }
  pen_ = PenState::Up;
  emit penStateChanged();
  return true;
}

void MachineSession::setReferencePose() {
  if (enqueueUserLine(jog::referencePoseCommand(inputs_.profile()), true))
    settle_.referenceSent(*userLines_.rbegin());
}

void MachineSession::softReset() {
  if (!link_) return;
  link_->protocol().sendRealtime(grbl::realtime::kSoftReset);
  emit consoleLine(tr("[soft reset]"), ConsoleKind::Sent);
}

void MachineSession::feedHold() {
  if (!link_) return;
  link_->protocol().sendRealtime(grbl::realtime::kFeedHold);
  emit consoleLine(tr("[feed hold]"), ConsoleKind::Sent);
}

void MachineSession::cycleStart() {
  if (!link_) return;
  link_->protocol().sendRealtime(grbl::realtime::kCycleStart);
  emit consoleLine(tr("[cycle start]"), ConsoleKind::Sent);
}

bool MachineSession::penUp() {
  if (!canJog()) return false;
  for (const std::string& line : job::penUpCommands(inputs_.profile().tool))
    if (!enqueueUserLine(line, true)) return false;
  setPenState(PenState::Up);
  return true;
}

bool MachineSession::penDown() {
  if (!canJog()) return false;
  for (const std::string& line : job::penDownCommands(inputs_.profile().tool))
    if (!enqueueUserLine(line, true)) return false;
  setPenState(PenState::Down);
  return true;
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
