#include "widgets/machine/run_controller.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

#include "core/output/gcode.hpp"

namespace fivebar::widgets {
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

RunController::RunController(const StudioDocument& doc, const PreviewController& preview,
                             MachineSession& session, QObject* parent)
    : QObject(parent), doc_(doc), preview_(preview), session_(session), jobDir_(defaultJobDirectory()) {
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
  connect(&preview_, &PreviewController::resultChanged, this, &RunController::runChanged);
  connect(&doc_, &StudioDocument::drawingChanged, this, &RunController::runChanged);
}

RunController::~RunController() { dropStream(); }

void RunController::setJobDirectory(const QString& dir) {
  jobDir_ = dir;
  emit runChanged();
}

QString RunController::jobPath() const {
  QString base = QFileInfo(doc_.fileName()).completeBaseName();
  if (base.isEmpty()) base = QStringLiteral("drawing");
  return QDir(jobDir_).filePath(base + QStringLiteral(".gcode"));
}

bool RunController::running() const { return stream_ != nullptr && !finished_; }

bool RunController::canStart() const {
  return session_.isConnected() && !running() && session_.state() == grbl::MachineState::Idle &&
         preview_.result().status == PreviewStatus::Planned && preview_.result().job != nullptr;
}

const PlannedJob* RunController::plannedJob() const {
  return preview_.result().status == PreviewStatus::Planned ? preview_.result().job.get() : nullptr;
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
    const std::string gcode = writeGcode(*preview_.result().job, doc_.profile());
    why = writeAtomically(jobPath(), gcode);
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
  } else if (launch(true, &why)) {
    return true;
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
  options.profile = doc_.profile();
  options.machineName = doc_.profile().name;
  stream_ = std::make_unique<StreamSession>(*session_.link(), options);
  connect(stream_.get(), &StreamSession::finished, this, &RunController::onFinished);
  std::string why;
  if (!stream_->begin(&why)) {
    *error = QString::fromStdString(why);
    stream_.reset();
    return false;
  }
  job_ = std::make_shared<const job::GcodeJob>(stream_->job());
  snapshot_ = {};
  snapshot_.totalLines = job_->lines.size();
  finished_ = false;
  lastMessage_ = resume ? tr("Resuming %1…").arg(jobPath()) : tr("Running %1…").arg(jobPath());
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
  lastMessage_ = message;
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
  emit finished(ok, message);
}

void RunController::dropStream() {
  // The stream's runner listens to the protocol: it must go while the link still exists.
  stream_.reset();
}

}  // namespace fivebar::widgets
