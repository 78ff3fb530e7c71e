// SPDX-License-Identifier: GPL-3.0-or-later
// StreamSession: one run of `fivebar stream` (or the studio's "send job"): load the job (and
// its resume state with resume = true), check every move of the file before the first byte
// (motion_check.hpp checkFile; a job planned for another profile is refused unless
// forceProfile), read the board's real pose (PoseSync; refuse to start in alarm), reach the
// job's start (or the resume point) by a checked pen-up approach, stream it with JobRunner, save the progress beside the job every
// second and whenever the run ends early, and on a problem bring the machine to a clean state
// (the runner's stop sequence) before reporting.
#pragma once

#include <QObject>
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "core/machine/profile.hpp"
#include "gcode_job.hpp"
#include "job_progress.hpp"
#include "job_runner.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/protocol/pose_sync.hpp"
#include "drivers/protocol/pose_trust.hpp"
#include "drivers/check/soft_limits.hpp"

namespace fivebar {

struct StreamOptions {
  std::string jobPath;
  // The job's text when the caller holds it already (the studio's planned job, written to
  // jobPath as the resume record): parsed from memory, the file is not read back.
  std::shared_ptr<const std::string> jobText;
  bool resume = false;                    // continue from JOB.progress
  std::optional<MachineProfile> profile;  // tool rules, steps, safe travel; needed for resume
  std::string machineName;                // recorded in the progress file
  bool checked = true;       // check every move of the file and the approach (needs profile)
  bool forceProfile = false;  // stream a job planned for another profile (its header) anyway
  // Read the board's $$ before the first move and refuse when a setting that changes where or
  // how fast the machine moves differs from the profile (movingSettingDiffs). Off: the expert's
  // override (`--ignore-settings`, the studio's "Start anyway").
  bool checkSettings = true;
  std::string portName;       // for the advice in messages ("--port PORT")
  double syncTimeoutS = 8.0;              // longest wait for the first status report
  double saveEveryS = 1.0;                // progress save period while running
  double reportEveryS = 0.5;              // progress() signal period
};

// Why a stream ended, as values; each front end words it (the CLI prints message(), the studio
// its own sentences for the kinds it knows).
struct StreamStop {
  enum class Kind {
    None,            // still running
    Done,            // every line acknowledged, machine Idle
    Refused,         // refused before the first move: the job, the approach
    BoardLimits,     // refused: the board's soft limits would stop the job (limitHit)
    PoseUnknown,     // refused: the host does not know where the arms are (doubt)
    SettingsDiffer,  // refused: the board's settings differ from the profile (settings)
    Alarm,           // refused: the board is in alarm
    Interrupted,     // stopped on request (Ctrl+C, SIGTERM, the studio's Stop)
    RunProblem,      // an error, alarm, reset, stall or disconnect stopped the run
  };
  Kind kind = Kind::None;
  grbl::PoseDoubt doubt = grbl::PoseDoubt::None;
  std::vector<setup::SettingDiff> settings;
  std::optional<setup::SoftLimitHit> limitHit;
  std::size_t linesDone = 0;   // job lines executed (one count: "line N of M")
  std::size_t totalLines = 0;
  std::string problem;         // RunProblem: what happened, the runner's explanation (English)
  bool penLifted = false;      // the stop sequence ended with the profile's pen-up command
  bool progressSaved = false;  // JOB.progress holds the resume point
};

// The settings that change where or how fast the machine moves: steps $100/$101, rates
// $110/$111, accelerations $120/$121, travel $130/$131, soft limits $20, homing $22 - those of
// compare(board, expectedSettings(profile)) among them.
std::vector<setup::SettingDiff> movingSettingDiffs(const setup::Settings& board, const MachineProfile& profile);
// "$100 (motor 1 steps/deg) is 250 on the board, the profile wants 35.5556; ..." (English).
std::string describeSettingDiffs(const std::vector<setup::SettingDiff>& diffs);

class StreamSession : public QObject {
  Q_OBJECT
 public:
  StreamSession(MachineLink& link, StreamOptions options, QObject* parent = nullptr);
  ~StreamSession() override;

  // Loads the job (and the progress when resuming). False with *error when that fails.
  bool begin(std::string* error);
  const stream::GcodeJob& job() const { return job_; }
  stream::JobRunner* runner() { return runner_.get(); }
  std::string progressPath() const { return stream::progressPathFor(options_.jobPath); }
  const StreamStop& stop() const { return stop_; }

  // A stop on request (Ctrl+C, SIGTERM, the studio's Stop): before the first move it ends at
  // once (nothing moved); while streaming it is the runner's stop sequence (feed hold, wait for
  // the hold, soft reset with the position kept), then the pen up, the progress saved, and
  // finished() says where the job stopped and how to resume.
  void requestStop();

 signals:
  void progress(const QString& text);
  void finished(bool ok, const QString& message);

 private:
  enum class Phase { Idle, Sync, Streaming, LiftingPen, Done };
  void onTick(double nowS);
  void startStreaming(double nowS);
  bool checkJob(const std::string& text, std::string* error);
  bool sameResumePoint(const stream::JobProgress& saved) const;
  bool planApproach(std::vector<std::string>& preamble);
  bool withinBoardLimits(const std::vector<std::string>& preamble, std::size_t fromIndex);
  void onRunnerChanged();
  void save(const std::string& reason);
  void finish(bool ok, const std::string& message);
  void refuse(StreamStop::Kind kind, const std::string& message);
  void liftPen(const std::string& message);
  void onPenRunnerChanged();
  std::string whereStopped() const;

  MachineLink& link_;
  StreamOptions options_;
  stream::GcodeJob job_;
  std::string jobHash_;
  std::optional<stream::JobProgress> resumeFrom_;
  std::optional<std::array<double, 3>> jobStart_;  // work coordinates of the job's start pose
  std::unique_ptr<grbl::PoseSync> poseSync_;
  std::unique_ptr<stream::JobRunner> runner_;
  stream::GcodeJob noLines_;                      // the pen-up run after a stop has only a preamble
  std::unique_ptr<stream::JobRunner> penRunner_;
  std::string stopMessage_;                    // said once the pen is up
  bool stopRequested_ = false;
  StreamStop stop_;
  Phase phase_ = Phase::Idle;
  double nextSaveS_ = 0.0;
  double nextReportS_ = 0.0;
};

}  // namespace fivebar
