// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_runner.hpp"

#include <algorithm>

#include "drivers/protocol/gcode_words.hpp"
#include "drivers/protocol/grbl_codes.hpp"

namespace fivebar::stream {

using grbl::MachineState;

const char* toString(RunState s) {
  switch (s) {
    case RunState::Ready: return "ready";
    case RunState::Running: return "running";
    case RunState::Holding: return "holding";
    case RunState::Held: return "held";
    case RunState::Paused: return "paused";
    case RunState::Stopping: return "stopping";
    case RunState::Stopped: return "stopped";
    case RunState::Finished: return "finished";
  }
  return "?";
}

JobRunner::JobRunner(grbl::GrblProtocol& protocol, const GcodeJob& job)
    : protocol_(protocol), job_(job) {
  protocol_.addListener(this);
}

JobRunner::~JobRunner() { protocol_.removeListener(this); }

const std::string& JobRunner::textAt(std::size_t seq) const {
  return seq < preamble_.size() ? preamble_[seq] : job_.lines[fromIndex_ + seq - preamble_.size()].text;
}

std::optional<std::size_t> JobRunner::jobIndexAt(std::size_t seq) const {
  if (seq < preamble_.size()) return std::nullopt;
  return fromIndex_ + seq - preamble_.size();
}

bool JobRunner::isMotion(std::size_t seq) const {
  if (const auto i = jobIndexAt(seq)) return job_.lines[*i].motion;
  const std::string& t = preamble_[seq];
  return t.find('X') != std::string::npos || t.find('Y') != std::string::npos ||
         (t.find('Z') != std::string::npos && t.find("G4") == std::string::npos);
}

void JobRunner::start(std::size_t fromIndex, std::vector<std::string> preamble, double nowS) {
  preamble_ = std::move(preamble);
  fromIndex_ = std::min(fromIndex, job_.lines.size());
  if (fromIndex_ > 0) lastCompleted_ = lastAcked_ = fromIndex_ - 1;
  maxDwellS_ = 0.0;
  const auto dwellOf = [](const std::string& t) {
    if (t.find("G4") == std::string::npos) return 0.0;
    const gcode::Words w = gcode::parseWords(t);
    return w.hasCode('G', 4) ? w.get('P').value_or(0.0) : 0.0;
  };
  for (const std::string& t : preamble_) maxDwellS_ = std::max(maxDwellS_, dwellOf(t));
  for (const JobLine& l : job_.lines) maxDwellS_ = std::max(maxDwellS_, dwellOf(l.text));
  nextSeq_ = 0;
  startS_ = nowS_ = nowS;
  problem_.clear();
  setState(RunState::Running);
  feed();
}

void JobRunner::setState(RunState s) {
  state_ = s;
  if (changed) changed();
}

void JobRunner::feed() {
  const bool streaming = state_ == RunState::Running || state_ == RunState::Holding ||
                         state_ == RunState::Held;
  while (streaming && nextSeq_ < sequenceLength() && protocol_.linesQueued() < kQueueAhead) {
    const auto r = protocol_.enqueue(textAt(nextSeq_));
    if (!r.ok()) {
      const auto idx = jobIndexAt(nextSeq_);
      pause("line " + std::to_string(idx ? job_.lines[*idx].fileLine : 0) + " cannot be sent: " +
            grbl::describe(r.status) + ".");
      return;
    }
    inFlight_.push_back({r.id, nextSeq_++});
  }
}

void JobRunner::pause(const std::string& problem) {
  problem_ = problem;
  for (std::uint64_t id : protocol_.dropQueued())
    std::erase_if(inFlight_, [id](const Sent& s) { return s.id == id; });
  if (!disconnected_ && !sawAlarm_) protocol_.sendRealtime(grbl::realtime::kFeedHold);
  setState(RunState::Paused);
}

void JobRunner::forgetInFlight() {
  // A reset or an alarm flushed the planner: acknowledged motions not known executed by now
  // never will be.
  pendingMotions_.clear();
  ackedBlocks_ = etaBlocks_ = completedBlocks_;
  inFlight_.clear();
  nextSeq_ = sequenceLength();  // nothing more of this run is sent
}

void JobRunner::markCompleted(std::uint64_t completedBlocks) {
  completedBlocks_ = std::max(completedBlocks_, std::min(completedBlocks, ackedBlocks_));
  while (!pendingMotions_.empty() && pendingMotions_.front().second <= completedBlocks_) {
    if (const auto i = jobIndexAt(pendingMotions_.front().first)) {
      const std::size_t capped = errorIndex_ ? std::min(*i, *errorIndex_ - 1) : *i;
      if (!errorIndex_ || *errorIndex_ > 0) lastCompleted_ = std::max(lastCompleted_.value_or(0), capped);
    }
    pendingMotions_.pop_front();
  }
}

// A board that stops answering while lines are outstanding: no status report for
// kSilentTimeoutS although polled, or Idle for kIdleStallS with lines unanswered (bytes lost on
// the wire, or a board that dropped them).
void JobRunner::checkStall(double nowS) {
  if (lastAckS_ < startS_) lastAckS_ = startS_;
  if (lastStatusS_ < startS_) lastStatusS_ = startS_;
  if (protocol_.linesInFlight() == 0) {
    lastAckS_ = nowS;
    return;
  }
  const double unansweredS = nowS - lastAckS_;
  if (nowS - lastStatusS_ > kSilentTimeoutS && unansweredS > kSilentTimeoutS) {
    disconnected_ = true;  // nothing can be sent that it would hear: stop without the sequence
    pause("The board stopped answering: no answer and no status report for " +
          std::to_string(int(unansweredS)) + " s with " + std::to_string(protocol_.linesInFlight()) +
          " line(s) outstanding. Check the cable and the board's power, reconnect, then resume "
          "from the last drawn point.");
  } else if (idleSinceS_ && nowS - *idleSinceS_ > kIdleStallS + maxDwellS_ &&
             unansweredS > kIdleStallS + maxDwellS_) {  // a dwell (G4) answers only when done
    pause("The board stays Idle with " + std::to_string(protocol_.linesInFlight()) +
          " line(s) unanswered for " + std::to_string(int(unansweredS)) +
          " s: it lost them (noise on the cable?). The job was stopped; resume from the last "
          "drawn point.");
  }
}

void JobRunner::onAck(const grbl::Ack& ack) {
  lastAckS_ = nowS_;
  if (unlockId_ && ack.id == *unlockId_) {
    unlockId_.reset();
    phase_ = StopPhase::None;
    if (!ack.ok()) problem_ += " Unlock ('$X') failed: " + grbl::describeError(ack.errorCode);
    setState(RunState::Stopped);
    return;
  }
  if (inFlight_.empty() || inFlight_.front().id != ack.id) return;  // not one of ours
  const std::size_t seq = inFlight_.front().seq;
  inFlight_.pop_front();
  const auto idx = jobIndexAt(seq);
  if (idx) lastAcked_ = std::max(lastAcked_.value_or(0), *idx);
  if (!ack.ok()) {
    if (idx && (!errorIndex_ || *idx < *errorIndex_)) errorIndex_ = *idx;
    if (state_ != RunState::Stopping && state_ != RunState::Paused && state_ != RunState::Stopped) {
      const int fileLine = idx ? job_.lines[*idx].fileLine : 0;
      pause((idx ? "line " + std::to_string(fileLine) : std::string("resume preamble line")) +
            " '" + ack.line + "' was rejected: " + grbl::describeError(ack.errorCode) +
            " The job was paused and stopped; what was drawn stays. To continue: fix the line "
            "in the file and stream it again with --resume: it continues after the last drawn "
            "point as long as that point is unchanged in the file (otherwise stream it from the "
            "start).");
    }
  } else if (isMotion(seq)) {
    pendingMotions_.emplace_back(seq, ++ackedBlocks_);
  }
  feed();
}

void JobRunner::onStatus(const grbl::StatusReport& r) {
  lastStatusS_ = nowS_;
  if (r.state != MachineState::Idle) idleSinceS_.reset();
  else if (!idleSinceS_) idleSinceS_ = nowS_;
  // Executed progress: an acknowledged motion sits in the planner until it is executed. With
  // Bf: the planner's depth is reported; without it (a stock board, $10=1) at most all 15
  // planner blocks can still be queued. While the machine moves, up to 5 more blocks may still
  // run from the stepper's segment buffer after the planner dropped them. A lower bound that
  // keeps the resume point safe (never beyond what was drawn).
  int queued = r.plannerBlocksFree ? std::max(0, grbl::kPlannerBlocks - *r.plannerBlocksFree)
                                   : grbl::kPlannerBlocks;
  // For the ETA, the best estimate: the blocks out of the planner have run but for the last
  // ~10 ms segments of up to 5 of them.
  const std::uint64_t outOfPlanner = ackedBlocks_ > std::uint64_t(queued) ? ackedBlocks_ - std::uint64_t(queued) : 0;
  if (r.plannerBlocksFree) etaBlocks_ = std::max(etaBlocks_, outOfPlanner);
  if (r.state != MachineState::Idle) queued += grbl::kSegmentBufferBlocks;
  if (r.plannerBlocksFree || r.state != MachineState::Idle)
    markCompleted(ackedBlocks_ > std::uint64_t(queued) ? ackedBlocks_ - std::uint64_t(queued) : 0);
  const bool allAcked = inFlight_.empty() && nextSeq_ >= sequenceLength();
  if (r.state == MachineState::Idle && inFlight_.empty() && protocol_.idleLink())
    markCompleted(ackedBlocks_);
  switch (state_) {
    case RunState::Running:
      // A program pause (M0, e.g. a pen change between layers) or the board's hold button: the
      // machine waits for a cycle start, which resume() sends.
      if (r.state == MachineState::Hold && r.subState == 0) {
        setState(RunState::Held);
        return;
      }
      if (allAcked && r.state == MachineState::Idle) {
        markCompleted(ackedBlocks_);
        if (!job_.lines.empty() && !errorIndex_) lastCompleted_ = job_.lines.size() - 1;
        setState(RunState::Finished);
      }
      return;
    case RunState::Holding:
      if (r.state == MachineState::Hold && r.subState == 0) setState(RunState::Held);
      return;
    case RunState::Held:  // resumed at the board (its cycle start button)
      if (r.state == MachineState::Run || r.state == MachineState::Idle) setState(RunState::Running);
      return;
    case RunState::Stopping:
      if (phase_ == StopPhase::WaitHold &&
          ((r.state == MachineState::Hold && r.subState == 0) || r.state == MachineState::Idle ||
           r.state == MachineState::Alarm))
        sendReset(nowS_);
      else if (phase_ == StopPhase::WaitSync) {
        if (r.state == MachineState::Alarm) {
          phase_ = StopPhase::WaitUnlock;
          unlockId_ = protocol_.enqueue("$X").id;
        } else {
          phase_ = StopPhase::None;
          setState(RunState::Stopped);
        }
      }
      return;
    default: return;
  }
}

void JobRunner::sendReset(double nowS) {
  forgetInFlight();
  phase_ = StopPhase::WaitBanner;
  deadlineS_ = nowS + kResetTimeoutS;
  protocol_.sendRealtime(grbl::realtime::kSoftReset);
}

void JobRunner::onAlarm(int code, const std::vector<std::uint64_t>& /*lostIds*/) {
  sawAlarm_ = true;
  if (state_ == RunState::Stopping) {
    if (phase_ == StopPhase::WaitHold) sendReset(nowS_);
    return;
  }
  forgetInFlight();
  if (state_ == RunState::Running || state_ == RunState::Holding || state_ == RunState::Held ||
      state_ == RunState::Paused)
    pause(grbl::describeAlarm(code) + " The job was paused; stopping it (soft reset, unlock) "
          "leaves the machine ready to resume from the last drawn point.");
}

void JobRunner::onReset(const std::string& version, const std::vector<std::uint64_t>& /*lost*/,
                        const std::vector<std::uint64_t>& /*dropped*/) {
  forgetInFlight();
  if (state_ == RunState::Stopping) {
    if (phase_ == StopPhase::WaitBanner || phase_ == StopPhase::WaitHold) {
      phase_ = StopPhase::WaitSync;
      deadlineS_ = nowS_ + kResetTimeoutS;
    }
    return;
  }
  if (state_ == RunState::Running || state_ == RunState::Holding || state_ == RunState::Held) {
    sawAlarm_ = true;  // no feed hold: the board has just restarted
    pause("the board reset unexpectedly (Grbl " + version + "); lines it had not executed were "
          "lost. Check the machine, then resume from the last drawn point.");
  }
}

void JobRunner::onDisconnected(const std::string& reason) {
  disconnected_ = true;
  forgetInFlight();
  if (state_ == RunState::Finished || state_ == RunState::Stopped) return;
  problem_ = (problem_.empty() ? "" : problem_ + " ") + "Connection lost (" + reason +
             "). Reconnect, then resume from the last drawn point.";
  phase_ = StopPhase::None;
  setState(state_ == RunState::Stopping ? RunState::Stopped : RunState::Paused);
}

void JobRunner::hold() {
  if (state_ != RunState::Running) return;
  protocol_.sendRealtime(grbl::realtime::kFeedHold);
  setState(RunState::Holding);
}

void JobRunner::resume() {
  if (state_ != RunState::Holding && state_ != RunState::Held) return;
  protocol_.sendRealtime(grbl::realtime::kCycleStart);
  setState(RunState::Running);
  feed();
}

void JobRunner::stop(double nowS) {
  nowS_ = nowS;
  if (state_ == RunState::Stopped || state_ == RunState::Finished || state_ == RunState::Stopping)
    return;
  if (disconnected_) { setState(RunState::Stopped); return; }
  for (std::uint64_t id : protocol_.dropQueued())
    std::erase_if(inFlight_, [id](const Sent& s) { return s.id == id; });
  nextSeq_ = sequenceLength();
  state_ = RunState::Stopping;
  if (protocol_.state() == MachineState::Alarm || sawAlarm_) {
    sendReset(nowS);
  } else {
    phase_ = StopPhase::WaitHold;
    deadlineS_ = nowS + kHoldTimeoutS;
    protocol_.sendRealtime(grbl::realtime::kFeedHold);
  }
  setState(RunState::Stopping);
}

void JobRunner::tick(double nowS) {
  nowS_ = nowS;
  if (state_ == RunState::Running) checkStall(nowS);
  if (state_ != RunState::Stopping || nowS < deadlineS_) return;
  if (phase_ == StopPhase::WaitHold) {
    problem_ += " The hold did not complete in time; the reset may have lost the position.";
    sendReset(nowS);
  } else if (phase_ == StopPhase::WaitBanner || phase_ == StopPhase::WaitSync) {
    problem_ += " The board did not answer after the soft reset.";
    phase_ = StopPhase::None;
    setState(RunState::Stopped);
  }
}

RunSnapshot JobRunner::snapshot() const {
  RunSnapshot s;
  s.totalLines = job_.lines.size();
  s.lastAcked = lastAcked_;
  s.lastCompleted = lastCompleted_;
  if (lastCompleted_) s.lastPenDownPoint = lastPenDownPoint(job_, *lastCompleted_);
  s.linesAcked = lastAcked_ ? *lastAcked_ + 1 : 0;
  s.linesCompleted = lastCompleted_ ? *lastCompleted_ + 1 : 0;
  // The plan's time line, not a line-count extrapolation (which jumped 20 -> 81 -> 18 s on an
  // 11 s job: lines take very different times).
  if (timeline_.lineEndS.size() == job_.lines.size() && !job_.lines.empty()) {
    // From the last line executed by the best estimate, not by the resume point's lower bound:
    // the up to 5 blocks it keeps back for the stepper's segment buffer have run but for their
    // last ~10 ms segments.
    std::optional<std::size_t> executed = lastCompleted_;
    for (const auto& [seq, blocks] : pendingMotions_) {
      if (blocks > etaBlocks_) break;
      if (const auto i = jobIndexAt(seq)) executed = std::max(executed.value_or(0), *i);
    }
    // Under the overrides the board reports: the job planned again at them, once per change.
    const grbl::MotionOverrides ov = protocol_.reportedOverrides().value_or(grbl::MotionOverrides{});
    if (ov == grbl::MotionOverrides{}) {
      s.etaS = timeline_.remainingS(executed);
    } else {
      if (!overriddenFor_ || !(*overriddenFor_ == ov)) {
        overridden_ = timeline_.overridden(ov);
        overriddenFor_ = ov;
      }
      s.etaS = overridden_.remainingS(executed);
    }
  }
  return s;
}

}  // namespace fivebar::stream
