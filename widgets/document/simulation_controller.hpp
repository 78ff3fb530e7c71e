// SPDX-License-Identifier: GPL-3.0-or-later
// The simulation clock: play, pause, step, speed and scrubbing over a planned job's trajectory.
// Pure UI state; the poses come from core's Trajectory, sampled by time (core computed the
// motion once). Ticks at 60 Hz while playing.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <memory>

#include "core/planning/trajectory.hpp"

namespace fivebar::widgets {

class SimulationController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kFrameIntervalMs = 16;  // ~60 fps
  static constexpr double kMinSpeed = 0.5;
  static constexpr double kMaxSpeed = 50.0;

  explicit SimulationController(QObject* parent = nullptr);

  // A new trajectory (nullptr: none) rewinds to the start and pauses.
  void setTrajectory(std::shared_ptr<const Trajectory> trajectory);
  const Trajectory* trajectory() const { return trajectory_.get(); }

  double timeS() const { return timeS_; }
  double durationS() const { return trajectory_ ? trajectory_->durationS() : 0.0; }
  double speed() const { return speed_; }
  bool playing() const { return timer_.isActive(); }
  bool atEnd() const { return trajectory_ && timeS_ >= trajectory_->durationS(); }
  // The pose now (valid when a trajectory is set).
  TrajectorySample sample() const;
  // Moves fully done at the current time: the trace shows moves with index < this.
  int completedMoves() const;

 public slots:
  void play();
  void pause();
  void togglePlay();
  // Jumps to the start of the next move (or the end).
  void stepForward();
  // Jumps to the start of the current move, or of the previous one when already there.
  void stepBackward();
  void setTimeS(double timeS);
  void setSpeed(double speed);  // clamped to [kMinSpeed, kMaxSpeed]
  // Advances the clock by `wallS` seconds of wall time (what each frame tick does).
  void advance(double wallS);

 signals:
  void timeChanged(double timeS);
  void playingChanged(bool playing);
  void speedChanged(double speed);
  void trajectoryChanged();
  void finished();

 private:
  void tick();

  std::shared_ptr<const Trajectory> trajectory_;
  double timeS_ = 0.0;
  double speed_ = 1.0;
  QTimer timer_;
  QElapsedTimer wall_;
};

}  // namespace fivebar::widgets
