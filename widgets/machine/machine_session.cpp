#include "widgets/machine/machine_session.hpp"

#include <QTimer>

#include "core/kinematics/units.hpp"
#include "drivers/gcode_job.hpp"
#include "drivers/grbl_codes.hpp"
#include "drivers/jog.hpp"
#include "drivers/serial_transport.hpp"
#include "drivers/simulated_transport.hpp"

namespace fivebar::widgets {
namespace {

// Status reports (Idle, nothing in flight) that must arrive after a jog before its end is
// forgotten and jogs start from the reported position again. Two, because at most one '?' is
// outstanding: the second report was certainly requested after the last jog answer.
constexpr int kReportsToSettle = 2;
constexpr int kSimClockMs = 5;

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

MachineSession::MachineSession(const StudioDocument& doc, QObject* parent)
    : QObject(parent), doc_(doc) {}

MachineSession::~MachineSession() {
  tearingDown_ = true;
  if (link_) link_->protocol().removeListener(this);
  link_.reset();
  transport_.reset();
}

bool MachineSession::connectSimulated(double speedup, const sim::Fault& fault, QString* error) {
  sim::SimConfig config;
  config.profile = doc_.profile();
  config.fault = fault;
  config.setUp = true;  // a board set up for the profile; it starts at MPos 0,0 (no reference)
  auto transport = std::make_unique<SimulatedTransport>(config, speedup);
  SimulatedTransport* simulated = transport.get();
  if (!openLink(std::move(transport), error)) return false;
  simulated_ = simulated;
  simulated_->startClock(kSimClockMs);
  return true;
}

bool MachineSession::connectSerial(const QString& portPath, int baudRate, QString* error) {
  return openLink(std::make_unique<SerialTransport>(portPath, baudRate), error);
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
  emit consoleLine(tr("Connected to %1.").arg(linkName()), ConsoleKind::Info);
  emit connectionChanged(true);
  return true;
}

void MachineSession::disconnectMachine() { teardown(tr("Disconnected.")); }

void MachineSession::teardown(const QString& reason) {
  if (!link_ || tearingDown_) return;
  tearingDown_ = true;
  emit aboutToDisconnect();
  link_->protocol().removeListener(this);
  link_->stopClock();
  transport_->close();
  link_.reset();
  transport_.reset();
  simulated_ = nullptr;
  userLines_.clear();
  jogLines_.clear();
  cancelAfter_.clear();
  jogEnd_.reset();
  settleReports_ = 0;
  settleBlocked_ = false;
  referenceLine_.reset();
  awaitWco_ = false;
  problem_ = {};
  tearingDown_ = false;
  emit consoleLine(reason, ConsoleKind::Info);
  emit problemChanged();
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
  const FkResult fk = forward(doc_.profile().geometry, *q, doc_.profile().assembly);
  if (!fk.ok()) return std::nullopt;
  return fk.p;
}

int MachineSession::bytesInFlight() const { return link_ ? link_->protocol().bytesInFlight() : 0; }

std::optional<JointAngles> MachineSession::jogStart() const {
  if (jogEnd_) return jogEnd_;
  return motorAngles();
}

bool MachineSession::canJog() const {
  if (!link_ || jobActive_ || settleBlocked_) return false;
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

bool MachineSession::sendLine(const QString& line) {
  const std::string text = line.trimmed().toStdString();
  if (text.empty()) return false;
  if (jobActive_) {
    emit consoleLine(tr("A job is running: %1 was not sent.").arg(fromStd(text)), ConsoleKind::Problem);
    return false;
  }
  return enqueueUserLine(text, true);
}

bool MachineSession::sendJog(const JogPlan& plan) {
  if (!canJog()) {
    emit consoleLine(tr("Jog refused: the machine is not idle, not connected or a job is running."),
                     ConsoleKind::Problem);
    return false;
  }
  if (!plan.ok()) return false;
  const bool logEach = plan.lines.size() <= 3;
  for (const std::string& line : plan.lines) {
    if (!enqueueUserLine(line, logEach)) return false;
    jogLines_.insert(*userLines_.rbegin());
  }
  if (!plan.targets.empty()) jogEnd_ = plan.targets.back();
  if (!logEach)
    emit consoleLine(tr("%1 (jog in %2 checked moves)")
                         .arg(QString::fromStdString(plan.lines.back()))
                         .arg(plan.lines.size()),
                     ConsoleKind::Sent);
  settleReports_ = kReportsToSettle;
  return true;
}

void MachineSession::cancelJog() {
  if (!link_) return;
  for (std::uint64_t id : link_->protocol().dropQueued()) {
    userLines_.erase(id);
    jogLines_.erase(id);
  }
  link_->protocol().sendRealtime(grbl::realtime::kJogCancel);
  cancelAfter_ = jogLines_;
  // Where the machine stops is known only from the next reports: no jog until then.
  jogEnd_.reset();
  settleBlocked_ = true;
  settleReports_ = kReportsToSettle;
}

void MachineSession::unlock() { enqueueUserLine("$X", true); }

void MachineSession::home() {
  if (doc_.profile().hasHomingSwitches) {
    enqueueUserLine("$H", true);
  } else {
    // Without switches the reference is declared; G10 is refused in alarm, so unlock first.
    if (state() == grbl::MachineState::Alarm) unlock();
    setReferencePose();
  }
}

void MachineSession::setReferencePose() {
  if (enqueueUserLine(jog::referencePoseCommand(doc_.profile()), true)) {
    referenceLine_ = *userLines_.rbegin();
    awaitWco_ = true;
    jogEnd_.reset();
    settleBlocked_ = true;
    settleReports_ = kReportsToSettle;
  }
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
  for (const std::string& line : job::penUpCommands(doc_.profile().tool))
    if (!enqueueUserLine(line, true)) return false;
  return true;
}

bool MachineSession::penDown() {
  if (!canJog()) return false;
  for (const std::string& line : job::penDownCommands(doc_.profile().tool))
    if (!enqueueUserLine(line, true)) return false;
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
  if (referenceLine_ && ack.id == *referenceLine_) {
    referenceLine_.reset();
    if (!ack.ok()) awaitWco_ = false;
  }
  const bool user = userLines_.erase(ack.id) > 0;
  const bool jog = jogLines_.erase(ack.id) > 0;
  if (cancelAfter_.erase(ack.id) > 0 && cancelAfter_.empty() && link_)
    link_->protocol().sendRealtime(grbl::realtime::kJogCancel);
  if (!user) return;
  if (ack.ok()) {
    if (problem_.kind == MachineProblem::Kind::Error) setProblem({});
    return;
  }
  if (jog) jogEnd_.reset();
  MachineProblem p;
  p.kind = MachineProblem::Kind::Error;
  p.code = ack.errorCode;
  p.text = tr("%1 was rejected: %2").arg(fromStd(ack.line), fromStd(grbl::describeError(ack.errorCode)));
  setProblem(p);
}

void MachineSession::onStatus(const grbl::StatusReport& report) {
  if (awaitWco_ && !referenceLine_ && report.wco) awaitWco_ = false;
  const bool quiet = report.state == grbl::MachineState::Idle && jogLines_.empty() && !awaitWco_;
  if (quiet && settleReports_ > 0 && --settleReports_ == 0) {
    jogEnd_.reset();
    settleBlocked_ = false;
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
  for (std::uint64_t id : lostIds) {
    userLines_.erase(id);
    jogLines_.erase(id);
  }
  cancelAfter_.clear();
  jogEnd_.reset();
  settleBlocked_ = false;
  settleReports_ = 0;
  referenceLine_.reset();
  awaitWco_ = false;
  MachineProblem p;
  p.kind = MachineProblem::Kind::Alarm;
  p.code = code;
  p.text = fromStd(grbl::describeAlarm(code));
  setProblem(p);
}

void MachineSession::onReset(const std::string& version, const std::vector<std::uint64_t>& lostIds,
                             const std::vector<std::uint64_t>& dropped) {
  for (const auto* ids : {&lostIds, &dropped}) {
    for (std::uint64_t id : *ids) {
      userLines_.erase(id);
      jogLines_.erase(id);
    }
  }
  cancelAfter_.clear();
  jogEnd_.reset();
  settleBlocked_ = false;
  settleReports_ = 0;
  referenceLine_.reset();
  awaitWco_ = false;
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

}  // namespace fivebar::widgets
