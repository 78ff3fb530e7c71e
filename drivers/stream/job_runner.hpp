// SPDX-License-Identifier: GPL-3.0-or-later
// JobRunner: streams a job through GrblProtocol (character counting) and follows it on the
// machine: progress by acknowledged line and by executed line (acknowledged motions minus the
// planner blocks still queued, from the Bf field of status reports, or without Bf: minus the
// planner's 15 blocks; while moving minus 5 more still in the stepper's segment buffer; all
// executed once the board is Idle), the ETA from the job's time line, a stall watchdog, hold (!) and resume
// (~), the stop sequence (hold, wait for Hold:0, soft reset, wait for the banner, re-sync with a
// status report, $X when the board is in alarm), and pausing with a plain explanation when an
// error, an alarm, an unexpected reset or a disconnect happens. Pure logic: time comes in by
// tick(nowS); the owner saves progress (snapshot()) and reacts to changed().
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gcode_job.hpp"
#include "job_timeline.hpp"
#include "drivers/protocol/grbl_protocol.hpp"

namespace fivebar::stream {

enum class RunState {
  Ready,     // not started
  Running,   // streaming
  Holding,   // feed hold sent, decelerating
  Held,      // Hold:0, resume with resume()
  Paused,    // an error / alarm / reset / disconnect stopped the stream: see problem()
  Stopping,  // the stop sequence is under way
  Stopped,   // the machine is in a clean state; the job can be resumed from snapshot()
  Finished,  // every line acknowledged and the machine Idle
};
const char* toString(RunState s);

struct RunSnapshot {
  std::size_t totalLines = 0;
  std::optional<std::size_t> lastAcked;      // job line index
  std::optional<std::size_t> lastCompleted;  // job line index known executed
  std::optional<std::size_t> lastPenDownPoint;
  std::size_t linesAcked = 0;      // count, this run and before
  std::size_t linesCompleted = 0;  // count
  // Machine time left (s): JobTimeline::remainingS of the last executed line, of the job planned
  // at the overrides the board reports (JobTimeline::overridden); < 0 unknown (no time line).
  double etaS = -1.0;
};

class JobRunner : public grbl::ProtocolListener {
 public:
  // Lines the protocol is given ahead of the character-counting window; keeps pause quick and
  // memory flat for any job size.
  static constexpr std::size_t kQueueAhead = 16;
  static constexpr double kHoldTimeoutS = 20.0;   // stop: longest wait for Hold:0
  static constexpr double kResetTimeoutS = 5.0;   // stop: longest wait for the banner
  static constexpr double kSilentTimeoutS = 10.0; // no answer and no status report: stalled
  static constexpr double kIdleStallS = 3.0;      // Idle with lines unanswered: stalled

  JobRunner(grbl::GrblProtocol& protocol, const GcodeJob& job);
  ~JobRunner() override;
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // The job's planned time line (timelineOf(job, profile)), from which snapshot() takes the ETA;
  // without one the ETA is unknown.
  void setTimeline(JobTimeline timeline) {
    timeline_ = std::move(timeline);
    overriddenFor_.reset();
  }
  // Streams preamble, then job lines from `fromIndex` on.
  void start(std::size_t fromIndex, std::vector<std::string> preamble, double nowS);
  void hold();
  void resume();
  void stop(double nowS);
  void tick(double nowS);

  RunState state() const { return state_; }
  const std::string& problem() const { return problem_; }
  bool disconnected() const { return disconnected_; }
  RunSnapshot snapshot() const;

  std::function<void()> changed;  // state or problem changed

  void onAck(const grbl::Ack& ack) override;
  void onStatus(const grbl::StatusReport& report) override;
  void onAlarm(int code, const std::vector<std::uint64_t>& lostIds) override;
  void onReset(const std::string& version, const std::vector<std::uint64_t>& lostIds,
               const std::vector<std::uint64_t>& dropped) override;
  void onDisconnected(const std::string& reason) override;

 private:
  enum class StopPhase { None, WaitHold, WaitBanner, WaitSync, WaitUnlock };
  struct Sent {
    std::uint64_t id;
    std::size_t seq;  // position in the run's sequence (preamble then job lines)
  };
  std::size_t sequenceLength() const { return preamble_.size() + job_.lines.size() - fromIndex_; }
  const std::string& textAt(std::size_t seq) const;
  std::optional<std::size_t> jobIndexAt(std::size_t seq) const;
  bool isMotion(std::size_t seq) const;
  void feed();
  void setState(RunState s);
  void pause(const std::string& problem);
  void forgetInFlight();
  void markCompleted(std::uint64_t completedBlocks);
  void sendReset(double nowS);
  void checkStall(double nowS);

  grbl::GrblProtocol& protocol_;
  const GcodeJob& job_;
  JobTimeline timeline_;
  // Scratch of snapshot(): the time line at the overrides last reported (recomputed on a change).
  mutable JobTimeline overridden_;
  mutable std::optional<grbl::MotionOverrides> overriddenFor_;
  std::vector<std::string> preamble_;
  std::size_t fromIndex_ = 0;
  std::size_t nextSeq_ = 0;
  std::deque<Sent> inFlight_;
  std::deque<std::pair<std::size_t, std::uint64_t>> pendingMotions_;  // seq, cumulative blocks
  std::uint64_t ackedBlocks_ = 0;
  std::uint64_t completedBlocks_ = 0;
  std::uint64_t etaBlocks_ = 0;  // blocks out of the planner by the last Bf: (the ETA's count)
  std::optional<std::size_t> lastAcked_;
  std::optional<std::size_t> lastCompleted_;
  std::optional<std::size_t> errorIndex_;  // first job line answered with error:N
  RunState state_ = RunState::Ready;
  StopPhase phase_ = StopPhase::None;
  std::string problem_;
  bool disconnected_ = false;
  bool sawAlarm_ = false;
  std::optional<std::uint64_t> unlockId_;
  double nowS_ = 0.0;
  double startS_ = 0.0;
  double deadlineS_ = 0.0;
  double lastAckS_ = 0.0;
  double maxDwellS_ = 0.0;  // longest G4 of the run: an Idle board answers it only when done
  double lastStatusS_ = 0.0;
  std::optional<double> idleSinceS_;
};

}  // namespace fivebar::stream
