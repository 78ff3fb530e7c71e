// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/run_controller.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QSaveFile>
#include <QStandardPaths>

#include "core/output/gcode.hpp"
#include "session/board_preflight.hpp"
#include "session/settings_advice.hpp"

namespace fivebar::session {
namespace {

// A count of lines as the user reads it: 12,345 (12.345 in German).
QString count(std::uint64_t n) { return QLocale().toString(qulonglong(n)); }

QString defaultJobDirectory() {
  const QString base = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
  return QDir(base.isEmpty() ? QDir::homePath() : base).filePath(QStringLiteral("jobs"));
}

// Writes text to path atomically (QSaveFile); an error sentence naming the file, or "".
QString writeAtomically(const QString& path, const std::string& text) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) return file.errorString() + QStringLiteral(": ") + path;
  file.write(text.data(), qint64(text.size()));
  if (!file.commit()) return file.errorString() + QStringLiteral(": ") + path;
  return {};
}

}  // namespace

RunController::RunController(const StudioInputs& inputs, MachineSession& session, QObject* parent)
    : QObject(parent), inputs_(inputs), session_(session), jobDir_(defaultJobDirectory()) {
  refresh_.setInterval(kRefreshMs);
  connect(&refresh_, &QTimer::timeout, this, &RunController::refresh);
  connect(&session_, &MachineSession::aboutToDisconnect, this, [this] {
    if (running()) {
      refresh();
      onFinished(false, tr("The connection was closed during the run. The progress is saved "
                           "beside the job: reconnect and resume."));
    }
    dropStream();
  });
  connect(&session_, &MachineSession::connectionChanged, this, &RunController::runChanged);
  connect(&session_, &MachineSession::statusUpdated, this, [this] {
    if (!running()) emit runChanged();
  });
  connect(&inputs_, &StudioInputs::plannedJobChanged, this, [this] {
    hashedPlan_ = nullptr;  // a new plan may live where the old one did
    plannedGcode_.reset();
    emit runChanged();
  });
  connect(&inputs_, &StudioInputs::drawingChanged, this, &RunController::runChanged);
  // A finished or stopped run belongs to the job it ran: when the job, its placement or the
  // profile change, its overlay and status go (its saved progress stays, for Resume).
  connect(&inputs_, &StudioInputs::jobChanged, this, &RunController::clearPreviousRun);
}

void RunController::clearPreviousRun() {
  if (running() || !job_) return;
  job_.reset();
  snapshot_ = {};
  lastState_ = stream::RunState::Ready;
  lastMessage_.clear();
  emit progressChanged();
  emit runChanged();
}

QString RunController::drawingName() const { return QFileInfo(jobPath()).completeBaseName(); }

QString RunController::resumeOffer() const {
  const auto saved = savedProgress();
  if (!saved) return {};
  // The saved line is a file line; count it in job lines, like the progress counter.
  // One count everywhere: the executed job lines, as the progress bar and the stop say it.
  const QString where = tr("line %1 of %2").arg(count(saved->linesDone), count(saved->totalLines));
  QString offer = tr("The run of \"%1\" was interrupted after %2: %3")
                      .arg(drawingName(), where, guiMessage(QString::fromStdString(saved->reason)));
  if (inputs_.plannedJob() != nullptr && !planMatchesSaved())
    offer += QLatin1Char(' ') +
             tr("The drawing, its placement, the machine profile or the tolerance changed since, so "
                "Resume would draw the old job where the canvas no longer shows it: undo the change to "
                "resume, or press Start to draw the new one from the beginning.");
  return offer;
}

// The planned job's G-code, written once per plan: Start and Resume stream it, its hash is the
// plan's identity.
std::shared_ptr<const std::string> RunController::plannedGcode() const {
  const PlannedJob* job = inputs_.plannedJob();
  if (job == nullptr) return nullptr;
  if (job != hashedPlan_ || !plannedGcode_) {
    hashedPlan_ = job;
    plannedGcode_ = std::make_shared<const std::string>(writeGcode(*job, inputs_.profile()));
    planHash_ = QString::fromStdString(stream::sha256Hex(*plannedGcode_));
  }
  return plannedGcode_;
}

QString RunController::planHash() const { return plannedGcode() ? planHash_ : QString(); }

bool RunController::planMatchesSaved() const {
  const auto saved = savedProgress();
  return saved && !planHash().isEmpty() && planHash().toStdString() == saved->jobHash;
}

QString RunController::progressText() const {
  const std::size_t done = snapshot_.lastCompleted ? *snapshot_.lastCompleted + 1 : 0;
  return tr("line %1 of %2").arg(count(done), count(snapshot_.totalLines));
}

// The alarm's explanation is the banner's (shown there once): the run panel says what to do.
QString RunController::alarmMessage() {
  return tr("The machine raised an alarm and the job stopped (the banner in the Machine panel "
            "says why). The progress is saved: clear the alarm (Reset, Unlock), check the pen "
            "stands where the studio shows it, then press Resume.");
}

// A drivers' message the studio has no words of its own for; an alarm is said once, above.
QString RunController::guiMessage(const QString& message) const {
  if (session_.problem().kind == MachineProblem::Kind::Alarm || message.startsWith(QStringLiteral("ALARM")))
    return alarmMessage();
  return message;
}

// The end of a run in the studio's words, from the drivers' structured stop.
QString RunController::stopMessage(bool ok, const QString& message) const {
  if (ok) return tr("\"%1\" is drawn.").arg(drawingName());
  if (!stream_) return guiMessage(message);
  const StreamStop& stop = stream_->stop();
  switch (stop.kind) {
    case StreamStop::Kind::PoseUnknown: return tr("Not started: %1").arg(session_.poseDoubtText());
    case StreamStop::Kind::BoardLimits:
      if (stop.limitHit) return tr("Not started: %1").arg(softLimitAdvice(*stop.limitHit));
      return guiMessage(message);
    case StreamStop::Kind::SettingsDiffer: {
      QStringList items;
      for (const SettingAdvice& a : adviseOnSettings(stop.settings)) items << a.text;
      return tr("Not started: the board's settings differ from the profile. %1 Write the profile's "
                "settings (Machine settings...), or choose Start anyway when Start asks.")
          .arg(items.join(QLatin1Char(' ')));
    }
    case StreamStop::Kind::Interrupted:
      if (stop.linesDone == 0 && !stop.progressSaved) return tr("Stopped before the first move: nothing was sent.");
      return (stop.penLifted ? tr("Stopped after line %1 of %2; the pen is up and the machine at rest.")
                             : tr("Stopped after line %1 of %2; the pen could not be lifted.")).arg(count(stop.linesDone), count(stop.totalLines)) +
             QLatin1Char(' ') + tr("The progress is saved: press Resume to continue.");
    case StreamStop::Kind::RunProblem:
      if (session_.problem().kind == MachineProblem::Kind::Alarm) return alarmMessage();
      return tr("Stopped after line %1 of %2: %3 The progress is saved: press Resume to continue.")
          .arg(count(stop.linesDone))
          .arg(count(stop.totalLines))
          .arg(QString::fromStdString(stop.problem));
    default: return guiMessage(message);
  }
}

RunController::~RunController() { dropStream(); }

void RunController::setJobDirectory(const QString& dir) {
  jobDir_ = dir;
  emit runChanged();
}

QString RunController::jobPath() const {
  QString base = QFileInfo(inputs_.drawingFileName()).completeBaseName();
  if (base.isEmpty()) base = QStringLiteral("drawing");
  return QDir(jobDir_).filePath(base + QStringLiteral(".gcode"));
}

bool RunController::running() const { return stream_ != nullptr && !finished_; }

bool RunController::canStart() const {
  // Not while another controller's job (the calibration pattern's, or the document's) runs.
  return session_.isConnected() && !running() && !session_.jobActive() &&
         session_.state() == grbl::MachineState::Idle && inputs_.plannedJob() != nullptr;
}

const PlannedJob* RunController::plannedJob() const {
  return inputs_.plannedJob();
}

bool RunController::canResume() const {
  return session_.isConnected() && !running() && session_.state() == grbl::MachineState::Idle &&
         planMatchesSaved();
}

std::optional<stream::JobProgress> RunController::savedProgress() const {
  const std::string path = jobPath().toStdString();
  if (!QFile::exists(QString::fromStdString(stream::progressPathFor(path))) || !QFile::exists(jobPath()))
    return std::nullopt;
  std::string error;
  return stream::loadProgress(stream::progressPathFor(path), &error);
}

stream::RunState RunController::state() const {
  if (stream_ && stream_->runner() && !finished_) return stream_->runner()->state();
  return lastState_;
}

bool RunController::start(QString* error) {
  QString why;
  if (!canStart()) {
    why = tr("Cannot start: connect the machine, wait until it is idle, and let the job plan first.");
  } else if (!session_.poseKnown()) {
    why = tr("Not started: %1").arg(session_.poseDoubtText());
  } else if (!QDir().mkpath(jobDir_)) {
    why = tr("Cannot create the job folder %1.").arg(jobDir_);
  } else {
    // The job is written once: the file is the resume record, the stream reads the same text
    // from memory. The board's soft limits are checked by the stream itself, before a byte.
    const auto gcode = plannedGcode();
    why = writeAtomically(jobPath(), *gcode);
    if (why.isEmpty()) {
      QFile::remove(QString::fromStdString(stream::progressPathFor(jobPath().toStdString())));
      if (launch(false, gcode, &why)) return true;
    }
  }
  lastMessage_ = why;
  if (error) *error = why;
  emit runChanged();
  return false;
}

bool RunController::resume(QString* error) {
  QString why;
  if (!savedProgress()) {
    why = tr("Nothing to resume: there is no saved progress beside %1.").arg(jobPath());
  } else if (inputs_.plannedJob() == nullptr) {
    why = tr("Not resumed: the job is not planned yet; wait for the preview.");
  } else if (!planMatchesSaved()) {
    why = tr("Not resumed: the drawing, its placement, the machine profile or the tolerance changed "
             "since the run was interrupted, so Resume would draw the old job where the canvas no "
             "longer shows it. Undo the change to resume, or press Start to draw the new one from "
             "the beginning.");
  } else if (!canResume()) {
    why = tr("Cannot resume: connect the machine and wait until it is idle.");
  } else if (!session_.poseKnown()) {
    why = tr("Not resumed: %1").arg(session_.poseDoubtText());
  } else {
    // The planned job is the interrupted one (same G-code, planMatchesSaved): streamed from memory.
    if (launch(true, plannedGcode(), &why)) return true;
  }
  lastMessage_ = why;
  if (error) *error = why;
  emit runChanged();
  return false;
}

bool RunController::launch(bool resume, std::shared_ptr<const std::string> gcode, QString* error) {
  dropStream();
  StreamOptions options;
  options.jobPath = jobPath().toStdString();
  options.jobText = std::move(gcode);
  options.resume = resume;
  options.profile = inputs_.profile();
  options.machineName = inputs_.profile().name;
  options.checkSettings = !ignoreSettings_;
  ignoreSettings_ = false;
  options.portName = session_.linkName().toStdString();
  stream_ = std::make_unique<StreamSession>(*session_.link(), options);
  connect(stream_.get(), &StreamSession::finished, this, &RunController::onFinished);
  std::string why;
  if (!stream_->begin(&why)) {
    *error = QString::fromStdString(why);
    stream_.reset();
    return false;
  }
  job_ = std::make_shared<const stream::GcodeJob>(stream_->job());
  snapshot_ = {};
  snapshot_.totalLines = job_->lines.size();
  if (stream_->runner()) snapshot_.etaS = stream_->runner()->snapshot().etaS;
  finished_ = false;
  lastMessage_ = resume ? tr("Resuming \"%1\"…").arg(drawingName()) : tr("Running \"%1\"…").arg(drawingName());
  session_.setJobActive(true);
  refresh_.start();
  emit runChanged();
  emit progressChanged();
  return true;
}

void RunController::hold() {
  if (running() && stream_->runner()) stream_->runner()->hold();
  refresh();
}

void RunController::continueRun() {
  if (running() && stream_->runner()) stream_->runner()->resume();
  refresh();
}

// The drivers' stop: feed hold, wait for the hold, soft reset (position kept), pen up, progress
// saved (StreamSession::requestStop).
void RunController::stop() {
  if (running()) stream_->requestStop();
  refresh();
}

void RunController::sendOverride(grbl::OverrideCommand command) {
  if (running()) session_.sendOverride(command);
}

void RunController::refresh() {
  if (!stream_ || !stream_->runner()) return;
  // The ETA in it is the drivers' (JobRunner: the plan's time line of the last executed line,
  // under the reported overrides; unchanged while held), the same as `fivebar stream` prints.
  snapshot_ = stream_->runner()->snapshot();
  const stream::RunState s = stream_->runner()->state();
  const bool changed = s != lastState_;
  lastState_ = s;
  emit progressChanged();
  if (changed) emit runChanged();
}

void RunController::onFinished(bool ok, const QString& message) {
  if (finished_) return;
  refresh();
  finished_ = true;
  refresh_.stop();
  lastMessage_ = stopMessage(ok, message);
  if (ok) {
    lastState_ = stream::RunState::Finished;
    snapshot_.lastCompleted = job_ && !job_->lines.empty()
                                  ? std::optional<std::size_t>(job_->lines.size() - 1)
                                  : std::nullopt;
    snapshot_.linesCompleted = snapshot_.totalLines;
    snapshot_.etaS = 0.0;
  }
  session_.setJobActive(false);
  // The next jog session compares the board's settings as they are now (the run may have met a
  // board that was reset or rewritten).
  session_.readBoardSettings();
  emit progressChanged();
  emit runChanged();
  emit finished(ok, lastMessage_);
}

void RunController::dropStream() {
  // The stream's runner listens to the protocol: it must go while the link still exists.
  stream_.reset();
}

}  // namespace fivebar::session
