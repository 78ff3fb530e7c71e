// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_session.hpp"

#include "drivers/stream/job_timeline.hpp"

#include <QFile>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "drivers/check/soft_limits.hpp"
#include "core/planning/safety.hpp"
#include "drivers/check/motion_check.hpp"
#include "resume.hpp"

namespace fivebar {
namespace {

const char* settingName(int id) {
  switch (id) {
    case 20: return "soft limits";
    case 22: return "homing cycle";
    case 100: return "motor 1 steps/deg";
    case 101: return "motor 2 steps/deg";
    case 110: return "motor 1 max rate, deg/min";
    case 111: return "motor 2 max rate, deg/min";
    case 120: return "motor 1 acceleration, deg/s^2";
    case 121: return "motor 2 acceleration, deg/s^2";
    case 130: return "motor 1 travel, deg";
    case 131: return "motor 2 travel, deg";
    default: return "setting";
  }
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::vector<setup::SettingDiff> movingSettingDiffs(const setup::Settings& board, const MachineProfile& profile) {
  static constexpr int kMoving[] = {20, 22, 100, 101, 110, 111, 120, 121, 130, 131};
  std::vector<setup::SettingDiff> out;
  for (const setup::SettingDiff& d : setup::compare(board, setup::expectedSettings(profile)))
    if (std::find(std::begin(kMoving), std::end(kMoving), d.id) != std::end(kMoving)) out.push_back(d);
  return out;
}

std::string describeSettingDiffs(const std::vector<setup::SettingDiff>& diffs) {
  std::string text;
  for (const setup::SettingDiff& d : diffs) {
    if (!text.empty()) text += "; ";
    // Appended piece by piece (GCC 12 warns falsely on "literal" + std::string&&).
    text += '$';
    text += std::to_string(d.id);
    text += " (";
    text += settingName(d.id);
    text += ") is ";
    text += d.board ? number(*d.board) : std::string("not reported");
    text += " on the board, the profile wants ";
    text += number(d.wanted);
  }
  return text;
}

StreamSession::StreamSession(MachineLink& link, StreamOptions options, QObject* parent)
    : QObject(parent), link_(link), options_(std::move(options)) {
  connect(&link_, &MachineLink::ticked, this, &StreamSession::onTick);
}

StreamSession::~StreamSession() = default;

bool StreamSession::begin(std::string* error) {
  std::optional<std::string> read;
  if (!options_.jobText) {
    read = stream::readFile(options_.jobPath, error);
    if (!read) return false;
  }
  const std::string* text = options_.jobText ? options_.jobText.get() : &*read;
  jobHash_ = stream::sha256Hex(*text);
  const stream::JobRules rules = options_.profile ? stream::rulesFor(*options_.profile) : stream::JobRules{};
  job_ = stream::parseJob(*text, rules);
  if (!job_.issues.empty()) {
    *error = options_.jobPath + ": refused, nothing was sent: " + job_.issues.front() +
             (job_.issues.size() > 1 ? " (and " + std::to_string(job_.issues.size() - 1) + " more)" : "");
    return false;
  }
  if (options_.checked && !checkJob(*text, error)) return false;
  if (options_.resume) {
    resumeFrom_ = stream::loadProgress(progressPath(), error);
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
  runner_ = std::make_unique<stream::JobRunner>(link_.protocol(), job_);
  // The ETA (CLI progress lines, the studio's Run panel): the profile's GRBL time model of the
  // job, under the overrides the board reports. Unknown without a profile.
  if (options_.profile) runner_->setTimeline(stream::timelineOf(job_, *options_.profile));
  runner_->changed = [this] { onRunnerChanged(); };
  phase_ = Phase::Sync;
  poseSync_ = std::make_unique<grbl::PoseSync>(link_.protocol(), options_.syncTimeoutS);
  poseSync_->wantSettings(options_.checked);  // the board's soft limits
  // Read anew before every job and resume: settings changed since (a console, another program)
  // must not go unnoticed.
  poseSync_->wantFreshSettings(options_.checked && options_.checkSettings);
  stop_.totalLines = job_.lines.size();
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

bool StreamSession::sameResumePoint(const stream::JobProgress& saved) const {
  if (saved.lastPenDownLine == 0) return true;  // starts over anyway
  const auto i = stream::indexOfFileLine(job_, saved.lastPenDownLine);
  if (!i || !job_.lines[*i].penDownPoint) return false;
  const stream::Point2& a = job_.lines[*i].endDeg;
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
    const std::string port = link_.transport().name().toStdString();
    const std::string machine = options_.machineName.empty() ? "PROFILE" : options_.machineName;
    if (link_.protocol().state() == grbl::MachineState::Alarm) {
      refuse(StreamStop::Kind::Alarm,
             "the machine is in alarm: check it, then unlock with \"fivebar send --port " + port +
                 " '$X'\" (or home with 'fivebar home') and stream again");
      return;
    }
    if (options_.checked && !link_.poseTrust().known()) {
      stop_.doubt = link_.poseTrust().doubt();
      refuse(StreamStop::Kind::PoseUnknown,
             "refused before the first move: the machine's position is not known (" +
                 std::string(grbl::toString(stop_.doubt)) + "; the board reports " +
                 motion::anglesText(link_.protocol().workPositionDeg()->x(), link_.protocol().workPositionDeg()->y()) +
                 ", which says nothing about where the arms stand after a power cut). Put the arms "
                 "in the home pose and run 'fivebar reference --port " + port + " --machine " + machine +
                 "', or home the machine ('fivebar home' with switches), then stream again");
      return;
    }
    if (options_.checked && options_.checkSettings && options_.profile) {
      stop_.settings = movingSettingDiffs(link_.protocol().boardSettings(), *options_.profile);
      if (!stop_.settings.empty()) {
        refuse(StreamStop::Kind::SettingsDiffer,
               "refused before the first move: the board's settings differ from the profile " +
                   options_.profile->name + ": " + describeSettingDiffs(stop_.settings) +
                   ". Write the profile's settings with 'fivebar setup --port " + port + " --machine " +
                   machine + " --write' (or stream with --ignore-settings if you know why they differ)");
        return;
      }
    }
    if (stopRequested_) {
      refuse(StreamStop::Kind::Interrupted, "stopped before the first move: nothing was sent");
      return;
    }
    startStreaming(nowS);
    return;
  }
  if (phase_ == Phase::LiftingPen) {
    penRunner_->tick(nowS);
    return;
  }
  if (phase_ != Phase::Streaming) return;
  runner_->tick(nowS);
  if (phase_ == Phase::Streaming && runner_->state() == stream::RunState::Running && nowS >= nextSaveS_) {
    save("interrupted while running (host stopped)");
    nextSaveS_ = nowS + options_.saveEveryS;
  }
  if (phase_ == Phase::Streaming && nowS >= nextReportS_) {
    const stream::RunSnapshot s = runner_->snapshot();
    char buf[200];
    // The machine state shows an M0 pause or a hold from the board's own button (Hold: send ~).
    const std::string machine(grbl::toString(link_.protocol().state()));
    // The ETA is the plan's time line under the board's overrides (JobRunner), shown with them
    // when they are not 100 % (set from the board's own buttons or another sender).
    std::string eta = s.etaS >= 0 ? ", ETA " + std::to_string(long(std::lround(s.etaS))) + " s" : "";
    const auto ov = link_.protocol().reportedOverrides();
    if (ov && !(*ov == grbl::MotionOverrides{}))
      eta += " (feed " + std::to_string(ov->feedPct) + " %, rapid " + std::to_string(ov->rapidPct) + " %)";
    std::snprintf(buf, sizeof buf, "%s (machine %s): %zu/%zu lines acknowledged, %zu executed%s",
                  stream::toString(runner_->state()), machine.c_str(), s.linesAcked, s.totalLines, s.linesCompleted,
                  eta.c_str());
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
    link_.poseTrust().aboutToMove();
    runner_->start(0, approach, nowS);
    return;
  }
  std::optional<std::size_t> point;
  if (resumeFrom_->lastPenDownLine > 0) {
    point = stream::indexOfFileLine(job_, resumeFrom_->lastPenDownLine);
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
  const stream::ResumePlan plan = stream::planResume(job_, point, *options_.profile, *current);
  if (!plan.ok()) {
    finish(false, "cannot resume: " + plan.message);
    return;
  }
  if (options_.checked && !withinBoardLimits(plan.preamble, plan.continueFrom)) return;
  link_.poseTrust().aboutToMove();
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
  stream::GcodeJob rest = job_;
  rest.lines.erase(rest.lines.begin(),
                   rest.lines.begin() + std::ptrdiff_t(std::min(fromIndex, rest.lines.size())));
  const auto hit = setup::firstSoftLimitHit(rest, link_.protocol().boardSettings(),
                                            {pose->wco[0], pose->wco[1]});
  if (!hit) return true;
  stop_.limitHit = *hit;
  stop_.kind = StreamStop::Kind::BoardLimits;
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
  for (const std::string& s : stream::penUpCommands(p.tool)) preamble.push_back(s);
  for (const JointAngles& q : *travel)
    preamble.push_back(stream::moveTo({degFromRad(q.theta1), degFromRad(q.theta2)}, true));
  emit progress(QString::fromStdString("approach: the machine is at " + here +
                                       ", the job starts at " + start + ": pen-up travel in " +
                                       std::to_string(travel->size()) + " checked move(s)"));
  return true;
}

void StreamSession::onRunnerChanged() {
  if (phase_ != Phase::Streaming) return;
  switch (runner_->state()) {
    case stream::RunState::Paused:
      save(runner_->problem());
      runner_->stop(link_.nowS());
      return;
    case stream::RunState::Stopped: {
      const std::string reason = stopRequested_ && runner_->problem().empty()
                                     ? std::string("stopped on request")
                                     : runner_->problem();
      save(reason);
      stop_.progressSaved = true;
      stop_.kind = stopRequested_ && runner_->problem().empty() ? StreamStop::Kind::Interrupted
                                                                : StreamStop::Kind::RunProblem;
      stop_.problem = runner_->problem();
      const std::string head = stop_.kind == StreamStop::Kind::Interrupted
                                   ? "stopped on request " + whereStopped() + "."
                                   : runner_->problem() + " (" + whereStopped() + ")";
      liftPen(head + " Progress saved to " + progressPath() + "; continue with --resume.");
      return;
    }
    case stream::RunState::Finished:
      QFile::remove(QString::fromStdString(progressPath()));
      stop_.kind = StreamStop::Kind::Done;
      stop_.linesDone = job_.lines.size();
      finish(true, "done: " + std::to_string(job_.lines.size()) + " lines acknowledged, machine Idle");
      return;
    default: return;
  }
}

void StreamSession::save(const std::string& reason) {
  const stream::RunSnapshot s = runner_->snapshot();
  stream::JobProgress p;
  p.jobHash = jobHash_;
  p.machine = options_.machineName;
  p.totalLines = int(job_.lines.size());
  const auto fileLine = [&](std::optional<std::size_t> i) { return i ? job_.lines[*i].fileLine : 0; };
  p.lastAckedLine = fileLine(s.lastAcked);
  p.lastCompletedLine = fileLine(s.lastCompleted);
  p.lastPenDownLine = fileLine(s.lastPenDownPoint);
  if (s.lastPenDownPoint) p.penDownAnglesDeg = job_.lines[*s.lastPenDownPoint].endDeg;
  p.linesDone = s.lastCompleted ? int(*s.lastCompleted) + 1 : 0;
  p.reason = reason;
  const std::string err = stream::saveProgress(p, progressPath());
  if (!err.empty()) emit progress(QString::fromStdString("warning: " + err));
}

// "after line N of M": the executed job lines, the one count every front end shows.
std::string StreamSession::whereStopped() const {
  const stream::RunSnapshot s = runner_->snapshot();
  const std::size_t done = s.lastCompleted ? *s.lastCompleted + 1 : 0;
  return "after line " + std::to_string(done) + " of " + std::to_string(job_.lines.size());
}

void StreamSession::requestStop() {
  if (phase_ == Phase::Done || phase_ == Phase::LiftingPen) return;
  stopRequested_ = true;
  if (phase_ == Phase::Idle) {
    refuse(StreamStop::Kind::Interrupted, "stopped before the first move: nothing was sent");
    return;
  }
  if (phase_ == Phase::Streaming) runner_->stop(link_.nowS());
  // Sync: the next tick ends it before anything moves.
}

// After the stop sequence (the board at rest, reset with its position kept): the profile's
// pen-up command, so that a stopped job never leaves the pen on the paper (a servo pen: M5 or
// M3 S<up>; a Z pen: G0 Z<up>).
void StreamSession::liftPen(const std::string& message) {
  const stream::RunSnapshot s = runner_->snapshot();
  stop_.linesDone = s.lastCompleted ? *s.lastCompleted + 1 : 0;
  if (runner_->disconnected() || !options_.profile) {
    finish(false, message);
    return;
  }
  // Through the one motion check like every line that reaches the board (a pen command moves no
  // joint: it passes; a profile whose pen-up would is not sent).
  const std::vector<std::string> lines = stream::penUpCommands(options_.profile->tool);
  if (auto pose = motion::boardPoseOf(link_.protocol())) {
    for (const std::string& line : lines) {
      const motion::LineCheck c = motion::checkLine(*options_.profile, line, *pose);
      if (!c.ok()) {
        finish(false, message + " The pen was not lifted: '" + line + "': " + c.reason.text());
        return;
      }
      motion::applyLine(line, c, *pose);
    }
  }
  stopMessage_ = message;
  phase_ = Phase::LiftingPen;
  penRunner_ = std::make_unique<stream::JobRunner>(link_.protocol(), noLines_);
  penRunner_->changed = [this] { onPenRunnerChanged(); };
  penRunner_->start(0, lines, link_.nowS());
}

void StreamSession::onPenRunnerChanged() {
  if (phase_ != Phase::LiftingPen) return;
  const stream::RunState st = penRunner_->state();
  if (st == stream::RunState::Finished) {
    stop_.penLifted = true;
    finish(false, stopMessage_ + " The pen is up and the machine at rest.");
  } else if (st == stream::RunState::Paused || st == stream::RunState::Stopped) {
    finish(false, stopMessage_ + " The pen could not be lifted: " + penRunner_->problem());
  }
}

void StreamSession::refuse(StreamStop::Kind kind, const std::string& message) {
  stop_.kind = kind;
  finish(false, message);
}

void StreamSession::finish(bool ok, const std::string& message) {
  if (phase_ == Phase::Done) return;
  if (stop_.kind == StreamStop::Kind::None) stop_.kind = ok ? StreamStop::Kind::Done : StreamStop::Kind::Refused;
  phase_ = Phase::Done;
  emit finished(ok, QString::fromStdString(message));
}

}  // namespace fivebar
