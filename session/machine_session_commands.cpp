// SPDX-License-Identifier: GPL-3.0-or-later
// MachineSession's commands: console lines (checked unless the expert switch is on), checked
// jogs and go-to moves, board settings, recovery (unlock, home, reference, reset), feed hold,
// cycle start and the pen. Every move passes the motion check (drivers/check/motion_check) first.
#include "session/machine_session.hpp"
#include "session/frame.hpp"


#include "core/kinematics/units.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/stream/stream_session.hpp"
#include "i18n/translated.hpp"

namespace fivebar::session {
namespace {

QString fromStd(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

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

// The one motion check (drivers/check/motion_check) from the board's reported pose. A motion line
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
    if (!poseKnown() && reported) {
      *refusal = poseDoubtText();
      return false;
    }
    if (settingsStopMoves()) {
      *refusal = moveRefusal();
      return false;
    }
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
  if (interpreted.verdict == motion::Verdict::Motion && link_) link_->poseTrust().aboutToMove();
  return true;
}

bool MachineSession::settingsStopMoves() const {
  return !ignoreSettings_ && boardSettings_ && !movingSettingDiffs(*boardSettings_, inputs_.profile()).empty();
}

void MachineSession::setIgnoreSettingDifferences(bool on) {
  if (ignoreSettings_ == on) return;
  ignoreSettings_ = on;
  if (on)
    emit consoleLine(tr("Moves are sent although the board's settings differ from the profile (expert "
                        "override)."),
                     ConsoleKind::Problem);
  emit boardSettingsChanged();
}

QString MachineSession::moveRefusal() const {
  if (!isConnected()) return tr("The machine is not connected.");
  if (jobActive_) return tr("A job is running.");
  if (!poseKnown()) return poseDoubtText();
  if (settingsStopMoves()) {
    QStringList ids;
    for (const setup::SettingDiff& d : movingSettingDiffs(*boardSettings_, inputs_.profile()))
      ids << QStringLiteral("$%1").arg(d.id);
    return tr("The board's settings %1 differ from the profile, so the machine would not move as "
              "planned: write the profile's settings (Machine settings...) first.")
        .arg(ids.join(QStringLiteral(", ")));
  }
  return tr("The machine is not idle.");
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
    emit consoleLine(tr("Jog refused: %1").arg(moveRefusal()), ConsoleKind::Problem);
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
  link_->poseTrust().aboutToMove();
  std::vector<std::uint64_t> ids;
  bool sent = true;
  for (const std::string& line : plan.lines) {
    if (!(sent = enqueueUserLine(line, logEach))) break;
    ids.push_back(*userLines_.rbegin());
  }
  settle_.jogSent(ids, sent && !plan.targets.empty() ? std::optional(plan.targets.back()) : std::nullopt);
  if (!sent) return false;
  // The board's distance mode after these lines (a go-to sets G90 first), read as the console's
  // checks read every line.
  motion::BoardPose modal;
  modal.absolute = consoleAbsolute_;
  for (const std::string& line : plan.lines) motion::applyLine(line, motion::interpretLine(line, modal), modal);
  consoleAbsolute_ = modal.absolute;
  if (!logEach)
    emit consoleLine(tr("%1 (jog in %n checked move(s))", nullptr, int(plan.lines.size()))
                         .arg(QString::fromStdString(plan.lines.back())),
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
    if (why) *why = moveRefusal();
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
  return true;
}

bool MachineSession::canFrame() const { return canJog() && inputs_.plannedJob() != nullptr; }

bool MachineSession::frameJob(QString* why) {
  const auto from = jogStart();
  const PlannedJob* job = inputs_.plannedJob();
  if (!canJog() || !from || job == nullptr) {
    if (why) *why = job == nullptr ? tr("No job is planned: open a drawing and let it plan first.") : moveRefusal();
    return false;
  }
  const jog::JogPlan plan = planJobFrame(*this, inputs_.profile(), *from, *job);
  if (!plan.ok()) {
    if (why) *why = tr("No checked frame of the job: %1").arg(studioText(plan.reason));
    return false;
  }
  if (!sendJog(plan)) {
    if (why) *why = tr("The frame was not sent (see the console).");
    return false;
  }
  emit consoleLine(tr("Frame: the job's outline, %1 mm, pen up").arg(QString::number(plan.lengthMm, 'f', 0)),
                   ConsoleKind::Info);
  return true;
}

void MachineSession::setReferencePose() {
  if (!enqueueUserLine(jog::referencePoseCommand(inputs_.profile()), true)) return;
  settle_.referenceSent(*userLines_.rbegin());
  link_->poseTrust().confirmed();  // the maker declared it: known from the next report at rest
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

void MachineSession::sendOverride(grbl::OverrideCommand command) {
  if (!link_) return;
  link_->protocol().sendRealtime(grbl::overrideByte(command));
  static const char* const kWords[] = {
      QT_TR_NOOP("[feed override 100 %]"), QT_TR_NOOP("[feed override +10 %]"),
      QT_TR_NOOP("[feed override -10 %]"), QT_TR_NOOP("[feed override +1 %]"),
      QT_TR_NOOP("[feed override -1 %]"),  QT_TR_NOOP("[rapid override 100 %]"),
      QT_TR_NOOP("[rapid override 50 %]"), QT_TR_NOOP("[rapid override 25 %]")};
  emit consoleLine(tr(kWords[int(command)]), ConsoleKind::Sent);
}

std::optional<grbl::MotionOverrides> MachineSession::reportedOverrides() const {
  if (!link_) return std::nullopt;
  return link_->protocol().reportedOverrides();
}

void MachineSession::cycleStart() {
  if (!link_) return;
  link_->protocol().sendRealtime(grbl::realtime::kCycleStart);
  emit consoleLine(tr("[cycle start]"), ConsoleKind::Sent);
}

bool MachineSession::penUp() { return sendPen(stream::penUpCommands(inputs_.profile().tool)); }

bool MachineSession::penDown() {
  return sendPen(stream::penDownCommands(inputs_.profile().tool));
}

bool MachineSession::sendPen(const std::vector<std::string>& lines) {
  if (!canJog()) return false;
  // The pen shown follows the board's own reports (onStatus), not this command.
  for (const std::string& line : lines)
    if (!enqueueUserLine(line, true)) return false;
  return true;
}

}  // namespace fivebar::session
