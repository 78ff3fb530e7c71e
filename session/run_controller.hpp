// SPDX-License-Identifier: GPL-3.0-or-later
// RunController: runs the planned job on the connected machine. Start writes the job's G-code
// beside the others in the job directory (atomically) and streams it with the drivers'
// StreamSession (character counting, progress saved beside the job every second and whenever
// the run ends early); hold, continue and stop go to its JobRunner. After an interruption (or a
// restart of the studio) the progress file beside the job offers "resume": the drivers plan a
// safe pen-up approach to the last completed pen-down point and continue from there.
#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <optional>

#include "drivers/stream/job_progress.hpp"
#include "drivers/stream/job_runner.hpp"
#include "drivers/stream/job_timeline.hpp"
#include "drivers/stream/stream_session.hpp"
#include "session/machine_session.hpp"
#include "session/studio_inputs.hpp"

namespace fivebar::session {

class RunController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kRefreshMs = 200;  // progress refresh while streaming

  RunController(const StudioInputs& inputs, MachineSession& session, QObject* parent = nullptr);
  ~RunController() override;

  // Where job files (NAME.gcode and NAME.gcode.progress) live; created on demand.
  void setJobDirectory(const QString& dir);
  QString jobDirectory() const { return jobDir_; }
  // The job file of the current document: <dir>/<document base name>.gcode.
  QString jobPath() const;

  bool running() const;         // streaming (not yet finished)
  bool canStart() const;        // connected, idle machine, a planned job, nothing running
  // canStart, a saved progress beside the job file, and the planned job is the one that run
  // was interrupted in (planMatchesSaved).
  bool canResume() const;
  // The saved run belongs to the job planned now (same drawing, placement, profile and
  // tolerance: the same G-code, by its SHA-256). False while nothing is planned.
  bool planMatchesSaved() const;
  // Start / Resume without comparing the board's settings with the profile (the expert's
  // "Start anyway"); for the next start only.
  void ignoreSettingsOnce() { ignoreSettings_ = true; }
  // The planned job Start would stream (the preview's), nullptr when there is none.
  const PlannedJob* plannedJob() const;
  // The saved progress beside the job file, when there is one that can be read.
  std::optional<stream::JobProgress> savedProgress() const;

  stream::RunState state() const;
  const stream::RunSnapshot& snapshot() const { return snapshot_; }
  // The job being (or last) run; nullptr before the first start and after the previous run
  // was cleared (the job, placement or profile changed since it ended).
  const stream::GcodeJob* job() const { return job_.get(); }
  QString lastMessage() const { return lastMessage_; }
  // The drawing Start and Resume work on ("flower" for .../jobs/flower.gcode).
  QString drawingName() const;
  // The resume offer in words: which drawing, how far it got (job lines), and why it stopped;
  // "" when there is nothing to resume.
  QString resumeOffer() const;
  // The executed share as one counter: "line N of M" from the executed job lines.
  QString progressText() const;
  // Seconds of machine time left by the planned time line (core's GRBL model) of the last
  // executed line, under the feed and rapid override the board reports (the job planned again
  // at them: stream::JobTimeline::overridden); < 0 while unknown. Does not change while the
  // machine holds.
  double etaS() const { return snapshot_.etaS; }
  // Feed and rapid override as the board reports them (Ov:); nullopt while not known.
  std::optional<grbl::MotionOverrides> overrides() const { return session_.reportedOverrides(); }

 public slots:
  bool start(QString* error = nullptr);
  bool resume(QString* error = nullptr);
  void hold();
  void continueRun();
  void stop();
  // A feed or rapid override during the run (the session's; GRBL caps the rate at $110/$111).
  void sendOverride(grbl::OverrideCommand command);

 signals:
  void runChanged();        // state, availability of start / resume
  void progressChanged();   // snapshot updated
  void finished(bool ok, const QString& message);

 private:
  bool launch(bool resume, std::shared_ptr<const std::string> gcode, QString* error);
  void refresh();
  void onFinished(bool ok, const QString& message);
  void dropStream();
  void clearPreviousRun();
  QString guiMessage(const QString& message) const;
  static QString alarmMessage();
  QString stopMessage(bool ok, const QString& message) const;
  std::shared_ptr<const std::string> plannedGcode() const;  // nullptr while nothing is planned
  QString planHash() const;  // of plannedGcode()

  const StudioInputs& inputs_;
  MachineSession& session_;
  QString jobDir_;
  std::unique_ptr<StreamSession> stream_;
  std::shared_ptr<const stream::GcodeJob> job_;
  stream::RunSnapshot snapshot_;
  stream::RunState lastState_ = stream::RunState::Ready;
  bool finished_ = true;
  bool ignoreSettings_ = false;
  mutable const PlannedJob* hashedPlan_ = nullptr;
  mutable QString planHash_;
  mutable std::shared_ptr<const std::string> plannedGcode_;
  QString lastMessage_;
  QTimer refresh_;
};

}  // namespace fivebar::session
