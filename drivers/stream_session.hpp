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
#include "machine_link.hpp"
#include "pose_sync.hpp"

namespace fivebar {

struct StreamOptions {
  std::string jobPath;
  bool resume = false;                    // continue from JOB.progress
  std::optional<MachineProfile> profile;  // tool rules, steps, safe travel; needed for resume
  std::string machineName;                // recorded in the progress file
  bool checked = true;       // check every move of the file and the approach (needs profile)
  bool forceProfile = false;  // stream a job planned for another profile (its header) anyway
  double syncTimeoutS = 8.0;              // longest wait for the first status report
  double saveEveryS = 1.0;                // progress save period while running
  double reportEveryS = 0.5;              // progress() signal period
};

class StreamSession : public QObject {
  Q_OBJECT
 public:
  StreamSession(MachineLink& link, StreamOptions options, QObject* parent = nullptr);
  ~StreamSession() override;

  // Loads the job (and the progress when resuming). False with *error when that fails.
  bool begin(std::string* error);
  const job::GcodeJob& job() const { return job_; }
  job::JobRunner* runner() { return runner_.get(); }
  std::string progressPath() const { return job::progressPathFor(options_.jobPath); }

 signals:
  void progress(const QString& text);
  void finished(bool ok, const QString& message);

 private:
  enum class Phase { Idle, Sync, Streaming, Done };
  void onTick(double nowS);
  void startStreaming(double nowS);
  bool checkJob(const std::string& text, std::string* error);
  bool sameResumePoint(const job::JobProgress& saved) const;
  bool planApproach(std::vector<std::string>& preamble);
  bool withinBoardLimits(const std::vector<std::string>& preamble, std::size_t fromIndex);
  void onRunnerChanged();
  void save(const std::string& reason);
  void finish(bool ok, const std::string& message);

  MachineLink& link_;
  StreamOptions options_;
  job::GcodeJob job_;
  std::string jobHash_;
  std::optional<job::JobProgress> resumeFrom_;
  std::optional<std::array<double, 3>> jobStart_;  // work coordinates of the job's start pose
  std::unique_ptr<grbl::PoseSync> poseSync_;
  std::unique_ptr<job::JobRunner> runner_;
  Phase phase_ = Phase::Idle;
  double nextSaveS_ = 0.0;
  double nextReportS_ = 0.0;
};

}  // namespace fivebar
