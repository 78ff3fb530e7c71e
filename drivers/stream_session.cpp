#include "stream_session.hpp"

#include <QFile>
#include <cmath>
#include <cstdio>

#include "resume.hpp"

namespace fivebar {

StreamSession::StreamSession(MachineLink& link, StreamOptions options, QObject* parent)
    : QObject(parent), link_(link), options_(std::move(options)) {
  connect(&link_, &MachineLink::ticked, this, &StreamSession::onTick);
}

StreamSession::~StreamSession() = default;

bool StreamSession::begin(std::string* error) {
  const auto text = job::readFile(options_.jobPath, error);
  if (!text) return false;
  jobHash_ = job::sha256Hex(*text);
  const job::JobRules rules = options_.profile ? job::rulesFor(*options_.profile) : job::JobRules{};
  job_ = job::parseJob(*text, rules);
  if (!job_.issues.empty()) {
    *error = options_.jobPath + ": " + job_.issues.front() +
             (job_.issues.size() > 1 ? " (and " + std::to_string(job_.issues.size() - 1) + " more)" : "");
    return false;
  }
  if (options_.resume) {
    resumeFrom_ = job::loadProgress(progressPath(), error);
    if (!resumeFrom_) return false;
    if (resumeFrom_->jobHash != jobHash_) {
      *error = progressPath() + " belongs to a different version of " + options_.jobPath +
               " (the file changed since it was saved); stream it from the start instead";
      return false;
    }
    if (!options_.profile) {
      *error = "resume needs the machine profile (--machine) to plan a safe pen-up travel";
      return false;
    }
  }
  runner_ = std::make_unique<job::JobRunner>(link_.protocol(), job_);
  runner_->changed = [this] { onRunnerChanged(); };
  phase_ = Phase::Sync;
  syncDeadlineS_ = link_.nowS() + options_.syncTimeoutS;
  link_.protocol().sendRealtime(grbl::realtime::kStatus);
  return true;
}

void StreamSession::onTick(double nowS) {
  if (phase_ == Phase::Sync) {
    if (link_.protocol().statusReportsSeen() > 0) {
      if (link_.protocol().state() == grbl::MachineState::Alarm) {
        finish(false, "the machine is in alarm: check it, then unlock with "
                      "'fivebar send --port " + link_.transport().name().toStdString() +
                      " $X' (or home with $H) and stream again");
        return;
      }
      startStreaming(nowS);
    } else if (nowS > syncDeadlineS_) {
      finish(false, "no status report from " + link_.transport().name().toStdString() +
                        " within " + std::to_string(int(options_.syncTimeoutS)) +
                        " s: is it a GRBL 1.1 board at the right baud rate?");
    }
    return;
  }
  if (phase_ != Phase::Streaming) return;
  runner_->tick(nowS);
  if (phase_ == Phase::Streaming && runner_->state() == job::RunState::Running && nowS >= nextSaveS_) {
    save("interrupted while running (host stopped)");
    nextSaveS_ = nowS + options_.saveEveryS;
  }
  if (phase_ == Phase::Streaming && nowS >= nextReportS_) {
    const job::RunSnapshot s = runner_->snapshot();
    char buf[200];
    // The machine state shows an M0 pause or a hold from the board's own button (Hold: send ~).
    const std::string machine(grbl::toString(link_.protocol().state()));
    std::snprintf(buf, sizeof buf, "%s (machine %s): %zu/%zu lines acknowledged, %zu executed%s",
                  job::toString(runner_->state()), machine.c_str(), s.linesAcked, s.totalLines, s.linesCompleted,
                  s.etaS >= 0 ? (", ETA " + std::to_string(long(std::lround(s.etaS))) + " s").c_str() : "");
    emit progress(QString::fromUtf8(buf));
    nextReportS_ = nowS + options_.reportEveryS;
  }
}

void StreamSession::startStreaming(double nowS) {
  phase_ = Phase::Streaming;
  nextSaveS_ = nowS + options_.saveEveryS;
  if (!resumeFrom_) {
    runner_->start(0, {}, nowS);
    return;
  }
  std::optional<std::size_t> point;
  if (resumeFrom_->lastPenDownLine > 0) {
    point = job::indexOfFileLine(job_, resumeFrom_->lastPenDownLine);
    if (!point) {
      finish(false, progressPath() + ": line " + std::to_string(resumeFrom_->lastPenDownLine) +
                        " is not a line of the job");
      return;
    }
  }
  const auto current = link_.protocol().motorAngles();
  const job::ResumePlan plan = job::planResume(job_, point, *options_.profile,
                                               current.value_or(options_.profile->homeAngles));
  if (!plan.ok()) {
    finish(false, "cannot resume: " + plan.message);
    return;
  }
  runner_->start(plan.continueFrom, plan.preamble, nowS);
}

void StreamSession::onRunnerChanged() {
  if (phase_ != Phase::Streaming) return;
  switch (runner_->state()) {
    case job::RunState::Paused:
      save(runner_->problem());
      runner_->stop(link_.nowS());
      return;
    case job::RunState::Stopped:
      save(runner_->problem());
      finish(false, runner_->problem() + " Progress saved to " + progressPath() +
                        "; continue with --resume.");
      return;
    case job::RunState::Finished:
      QFile::remove(QString::fromStdString(progressPath()));
      finish(true, "done: " + std::to_string(job_.lines.size()) + " lines acknowledged, machine Idle");
      return;
    default: return;
  }
}

void StreamSession::save(const std::string& reason) {
  const job::RunSnapshot s = runner_->snapshot();
  job::JobProgress p;
  p.jobHash = jobHash_;
  p.machine = options_.machineName;
  p.totalLines = int(job_.lines.size());
  const auto fileLine = [&](std::optional<std::size_t> i) { return i ? job_.lines[*i].fileLine : 0; };
  p.lastAckedLine = fileLine(s.lastAcked);
  p.lastCompletedLine = fileLine(s.lastCompleted);
  p.lastPenDownLine = fileLine(s.lastPenDownPoint);
  if (s.lastPenDownPoint) p.penDownAnglesDeg = job_.lines[*s.lastPenDownPoint].endDeg;
  p.reason = reason;
  const std::string err = job::saveProgress(p, progressPath());
  if (!err.empty()) emit progress(QString::fromStdString("warning: " + err));
}

void StreamSession::finish(bool ok, const std::string& message) {
  if (phase_ == Phase::Done) return;
  phase_ = Phase::Done;
  emit finished(ok, QString::fromStdString(message));
}

}  // namespace fivebar
