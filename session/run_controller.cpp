#include "session/run_controller.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

#include "core/output/gcode.hpp"
#include "session/board_preflight.hpp"

namespace fivebar::session {
namespace {

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
  connect(&inputs_, &StudioInputs::plannedJobChanged, this, &RunController::runChanged);
  connect(&inputs_, &StudioInputs::drawingChanged, this, &RunController::runChanged);
  // A finished or stopped run belongs to the job it ran: when the job, its placement or the
  // profile change, its overlay and status go (its saved progress stays, for Resume).
  connect(&inputs_, &StudioInputs::jobChanged, this, &RunController::clearPreviousRun);
}

void RunController::clearPreviousRun() {
  if (running() || !job_) return;
  job_.reset();
  timeline_ = {};
  snapshot_ = {};
  lastState_ = job::RunState::Ready;
  lastMessage_.clear();
  emit progressChanged();
  emit runChanged();
}

QString RunController::drawingName() const { return QFileInfo(jobPath()).completeBaseName(); }

QString RunController::resumeOffer() const {
  const auto saved = savedProgress();
  if (!saved) return {};
  // The saved line is a file line; count it in job lines, like the progress counter.
  QString where;
  QFile file(jobPath());
  if (file.open(QIODevice::ReadOnly)) {
    const QByteArray bytes = file.readAll();
    const job::GcodeJob j =
        job::parseJob(std::string_view(bytes.constData(), std::size_t(bytes.size())), job::rulesFor(inputs_.profile()));
    std::size_t done = 0;
    for (const job::JobLine& line : j.lines)
      if (line.fileLine <= saved->lastCompletedLine) ++done;
    where = tr("line %1 of %2").arg(done).arg(j.lines.size());
  }
  return tr("The run of \"%1\" was interrupted at %2: %3")
      .arg(drawingName(), where, guiMessage(QString::fromStdString(saved->reason)));
}

QString RunController::progressText() const {
  const std::size_t done = snapshot_.lastCompleted ? *snapshot_.lastCompleted + 1 : 0;
  return tr("line %1 of %2").arg(done).arg(snapshot_.totalLines);
}

// The drivers' messages are written for the command line: say it with the studio's buttons,
// and leave the alarm's explanation to the banner (it is shown there once).
QString RunController::guiMessage(const QString& message) const {
  QString text = message;
  text.replace(QStringLiteral("; continue with --resume."), QStringLiteral("."));
  text.replace(QStringLiteral("stream it again with --resume"), tr("press Resume"));
  text.replace(QStringLiteral("--resume"), tr("Resume"));
  const MachineProblem& p = session_.problem();
  if (p.kind == MachineProblem::Kind::Alarm || text.startsWith(QStringLiteral("ALARM")))
    return tr("The machine raised an alarm and the job stopped (the banner in the Machine panel "
              "says why). The progress is saved: clear the alarm (Reset, Unlock), check the pen "
              "stands where the studio shows it, then press Resume.");
  return text;
}

RunController::~RunController() { dropStream(); }

QString RunController::boardLimitProblem(const std::string& gcode, int afterLine) const {
  const QString why = session::boardLimitProblem(session_, inputs_.profile(), gcode, afterLine);
  return why.isEmpty() ? why : tr("Not started: %1").arg(why);
}

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
  return session_.isConnected() && !running() && session_.state() == grbl::MachineState::Idle &&
         inputs_.plannedJob() != nullptr;
}

const PlannedJob* RunController::plannedJob() const {
  return inputs_.plannedJob();
}

bool RunController::canResume() const {
  return session_.isConnected() && !running() && session_.state() == grbl::MachineState::Idle &&
         savedProgress().has_value();
}

std::optional<job::JobProgress> RunController::savedProgress() const {
  const std::string path = jobPath().toStdString();
  if (!QFile::exists(QString::fromStdString(job::progressPathFor(path))) || !QFile::exists(jobPath()))
    return std::nullopt;
  std::string error;
  return job::loadProgress(job::progressPathFor(path), &error);
}

job::RunState RunController::state() const {
  if (stream_ && stream_->runner() && !finished_) return stream_->runner()->state();
  return lastState_;
}

bool RunController::start(QString* error) {
  QString why;
  if (!canStart()) {
    why = tr("Cannot start: connect the machine, wait until it is idle, and let the job plan first.");
  } else if (!QDir().mkpath(jobDir_)) {
    why = tr("Cannot create the job folder %1.").arg(jobDir_);
  } else {
    const std::string gcode = writeGcode(*inputs_.plannedJob(), inputs_.profile());
    why = boardLimitProblem(gcode);
    if (why.isEmpty()) why = writeAtomically(jobPath(), gcode);
    if (why.isEmpty()) {
      QFile::remove(QString::fromStdString(job::progressPathFor(jobPath().toStdString())));
      if (launch(false, &why)) return true;
    }
  }
  lastMessage_ = why;
  if (error) *error = why;
  emit runChanged();
  return false;
}

bool RunController::resume(QString* error) {
  QString why;
  if (!canResume()) {
    why = tr("Nothing to resume: there is no saved progress beside %1.").arg(jobPath());
  } else {
    // The rest of the job against the board's soft limits first (after an alarm the reference
    // may have changed).
    QFile file(jobPath());
    const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    why = boardLimitProblem(bytes.toStdString(), savedProgress()->lastCompletedLine);
    if (why.isEmpty() && launch(true, &why)) return true;
  }
  lastMessage_ = why;
  if (error) *error = why;
  emit runChanged();
  return false;
}

bool RunController::launch(bool resume, QString* error) {
  dropStream();
  StreamOptions options;
  options.jobPath = jobPath().toStdString();
  options.resume = resume;
  options.profile = inputs_.profile();
  options.machineName = inputs_.profile().name;
  stream_ = std::make_unique<StreamSession>(*session_.link(), options);
  connect(stream_.get(), &StreamSession::finished, this, &RunController::onFinished);
  std::string why;
  if (!stream_->begin(&why)) {
    *error = QString::fromStdString(why);
    stream_.reset();
    return false;
  }
  job_ = std::make_shared<const job::GcodeJob>(stream_->job());
  timeline_ = job::timelineOf(*job_, inputs_.profile());
  snapshot_ = {};
  snapshot_.totalLines = job_->lines.size();
  snapshot_.etaS = timeline_.totalS();
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

void RunController::stop() {
  if (running() && stream_->runner() && session_.link())
    stream_->runner()->stop(session_.link()->nowS());
  refresh();
}

void RunController::refresh() {
  if (!stream_ || !stream_->runner()) return;
  snapshot_ = stream_->runner()->snapshot();
  // The time left by the plan's time line of the last executed line (unchanged while held).
  snapshot_.etaS = timeline_.lineEndS.empty() ? -1.0 : timeline_.remainingS(snapshot_.lastCompleted);
  if (job_ && snapshot_.lastCompleted && *snapshot_.lastCompleted < job_->lines.size())
    session_.setPenState(job_->lines[*snapshot_.lastCompleted].penDownAfter ? PenState::Down : PenState::Up);
  const job::RunState s = stream_->runner()->state();
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
  lastMessage_ = ok ? tr("\"%1\" is drawn.").arg(drawingName()) : guiMessage(message);
  if (ok) {
    lastState_ = job::RunState::Finished;
    snapshot_.lastCompleted = job_ && !job_->lines.empty()
                                  ? std::optional<std::size_t>(job_->lines.size() - 1)
                                  : std::nullopt;
    snapshot_.linesCompleted = snapshot_.totalLines;
    snapshot_.etaS = 0.0;
  }
  session_.setJobActive(false);
  emit progressChanged();
  emit runChanged();
  emit finished(ok, lastMessage_);
}

void RunController::dropStream() {
  // The stream's runner listens to the protocol: it must go while the link still exists.
  stream_.reset();
}

}  // namespace fivebar::session
