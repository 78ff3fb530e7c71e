#include "stream_session.hpp"

#include <QFile>
#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "soft_limits.hpp"
#include "core/planning/safety.hpp"
#include "motion_check.hpp"
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
    *error = options_.jobPath + ": refused, nothing was sent: " + job_.issues.front() +
             (job_.issues.size() > 1 ? " (and " + std::to_string(job_.issues.size() - 1) + " more)" : "");
    return false;
  }
  if (options_.checked && !checkJob(*text, error)) return false;
  if (options_.resume) {
    resumeFrom_ = job::loadProgress(progressPath(), error);
    if (!resumeFrom_) return false;
    if (resumeFrom_->jobHash != jobHash_ && !sameResumePoint(*resumeFrom_)) {
      *error = progressPath() + " was saved for another version of " + options_.jobPath +
               " and the resume point (line " + std::to_string(resumeFrom_->lastPenDownLine) +
               ") is not the same in the changed file; stream it from the start instead";
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
  poseSync_ = std::make_unique<grbl::PoseSync>(link_.protocol(), options_.syncTimeoutS);
  poseSync_->wantSettings(options_.checked);  // the board's soft limits
  return true;
}

bool StreamSession::checkJob(const std::string& text, std::string* error) {
  if (!options_.profile) {
    *error = "the job's moves are checked against the machine profile before the first byte: "
             "give --machine PRESET|FILE (or --unchecked to stream without the check)";
    return false;
  }
  const MachineProfile& p = *options_.profile;
  const motion::JobHeader header = motion::readJobHeader(text);
  if (header.profileName && *header.profileName != p.name && !options_.forceProfile) {
    *error = options_.jobPath + " was planned for the profile '" + *header.profileName +
             "', not '" + p.name + "': plan it again for this machine (or --force-profile if the "
             "machines are the same)";
    return false;
  }
  std::optional<motion::Axes3> start;
  if (header.startDeg) start = motion::Axes3{(*header.startDeg)[0], (*header.startDeg)[1], 0.0};
  const motion::FileCheck c = motion::checkFile(p, text, start);
  if (!c.ok) {
    *error = options_.jobPath + ": refused, nothing was sent: " + c.reason;
    return false;
  }
  if (start) jobStart_ = *start;
  else if (c.firstTargetWork) jobStart_ = *c.firstTargetWork;
  return true;
}

bool StreamSession::sameResumePoint(const job::JobProgress& saved) const {
  if (saved.lastPenDownLine == 0) return true;  // starts over anyway
  const auto i = job::indexOfFileLine(job_, saved.lastPenDownLine);
  if (!i || !job_.lines[*i].penDownPoint) return false;
  const job::Point2& a = job_.lines[*i].endDeg;
  return std::abs(a[0] - saved.penDownAnglesDeg[0]) < 1e-3 &&
         std::abs(a[1] - saved.penDownAnglesDeg[1]) < 1e-3;
}

void StreamSession::onTick(double nowS) {
  if (phase_ == Phase::Sync) {
    const auto st = poseSync_->step(nowS);
    if (st == grbl::PoseSync::State::Failed) {
      finish(false, link_.transport().name().toStdString() + ": " + poseSync_->problem());
      return;
    }
    if (st == grbl::PoseSync::State::Waiting) return;
    if (link_.protocol().state() == grbl::MachineState::Alarm) {
      finish(false, "the machine is in alarm: check it, then unlock with "
                    "'fivebar send --port " + link_.transport().name().toStdString() +
                    " $X' (or home with 'fivebar home') and stream again");
      return;
    }
    startStreaming(nowS);
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
    std::vector<std::string> approach;
    if (options_.checked && !planApproach(approach)) return;
    if (options_.checked && !withinBoardLimits(approach, 0)) return;
    runner_->start(0, approach, nowS);
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
  const auto current = link_.protocol().motorAngles();  // known: PoseSync is Ready
  if (!current) {
    finish(false, "cannot resume: the machine's pose is not known");
    return;
  }
  if (const MoveCheck here = checkPose(*options_.profile, *current); !here.ok()) {
    finish(false, "cannot resume: the machine reports " +
                      motion::anglesText(degFromRad(current->theta1), degFromRad(current->theta2)) +
                      ", which is not a safe pose (" + describe(here) + "); if the board lost its "
                      "position (power cut), put the arms in the home pose and run 'fivebar "
                      "reference', then resume");
    return;
  }
  const job::ResumePlan plan = job::planResume(job_, point, *options_.profile, *current);
  if (!plan.ok()) {
    finish(false, "cannot resume: " + plan.message);
    return;
  }
  if (options_.checked && !withinBoardLimits(plan.preamble, plan.continueFrom)) return;
  runner_->start(plan.continueFrom, plan.preamble, nowS);
}

// The motion check's board part before the first byte: the approach (or resume preamble) line by
// line from the reported pose, then every target of the job from `fromIndex` on, against the
// board's soft-limit travel in machine coordinates (GRBL would stop with ALARM:2 part-way).
bool StreamSession::withinBoardLimits(const std::vector<std::string>& preamble, std::size_t fromIndex) {
  const auto pose = motion::boardPoseOf(link_.protocol());
  if (!pose || !pose->softTravelDeg) return true;
  if (const motion::LinesCheck c = motion::checkBoardLines(preamble, *pose); !c.ok(preamble.size())) {
    finish(false, "refused, nothing was sent: the move to the job's start: " + c.reason.text());
    return false;
  }
  job::GcodeJob rest = job_;
  rest.lines.erase(rest.lines.begin(),
                   rest.lines.begin() + std::ptrdiff_t(std::min(fromIndex, rest.lines.size())));
  const auto hit = setup::firstSoftLimitHit(rest, link_.protocol().boardSettings(),
                                            {pose->wco[0], pose->wco[1]});
  if (!hit) return true;
  finish(false, "refused, nothing was sent: " + setup::describe(*hit) +
                    ": the board would stop the job there with ALARM:2. Its travel is checked in "
                    "machine coordinates, which the reference shifted against the job's: home the "
                    "machine ('fivebar home'), or make the board's settings match the profile "
                    "('fivebar setup'), then stream again");
  return false;
}

bool StreamSession::planApproach(std::vector<std::string>& preamble) {
  const auto pose = link_.protocol().workPositionDeg();
  if (!pose || !jobStart_) return true;  // a job without joint motion
  const MachineProfile& p = *options_.profile;
  const double tolDeg = 0.5 / std::max(1.0, std::min(p.motors.stepsPerDeg1, p.motors.stepsPerDeg2));
  const std::string here = motion::anglesText(pose->x(), pose->y());
  const std::string start = motion::anglesText((*jobStart_)[0], (*jobStart_)[1]);
  if (std::abs(pose->x() - (*jobStart_)[0]) <= std::max(tolDeg, 1e-3) &&
      std::abs(pose->y() - (*jobStart_)[1]) <= std::max(tolDeg, 1e-3))
    return true;
  const JointAngles from{radFromDeg(pose->x()), radFromDeg(pose->y())};
  const JointAngles to{radFromDeg((*jobStart_)[0]), radFromDeg((*jobStart_)[1])};
  if (const MoveCheck c = checkPose(p, from); !c.ok()) {
    finish(false, "refused before the first move: the machine reports " + here +
                      ", which is not a safe pose of " + p.name + " (" + describe(c) +
                      "); its reference is probably not set: put the arms in the home pose and "
                      "run 'fivebar reference' (or 'fivebar home'), then stream again");
    return false;
  }
  const auto travel = planSafeTravel(p, from, to);
  if (!travel) {
    finish(false, "refused before the first move: the machine is at " + here +
                      " and the job starts at " + start +
                      ", and no safe pen-up travel joins them. A board just powered up reads "
                      "0,0 until its reference is set: put the arms in the home pose and run "
                      "'fivebar reference'; otherwise bring it closer ('fivebar home') and "
                      "stream again");
    return false;
  }
  preamble.push_back("G90");
  for (const std::string& s : job::penUpCommands(p.tool)) preamble.push_back(s);
  for (const JointAngles& q : *travel)
    preamble.push_back(job::moveTo({degFromRad(q.theta1), degFromRad(q.theta2)}, true));
  emit progress(QString::fromStdString("approach: the machine is at " + here +
                                       ", the job starts at " + start + ": pen-up travel in " +
                                       std::to_string(travel->size()) + " checked move(s)"));
  return true;
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
