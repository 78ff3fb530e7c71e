// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/simulation_controller.hpp"

#include <algorithm>

namespace fivebar::widgets {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
  timer_.setInterval(kFrameIntervalMs);
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, &SimulationController::tick);
}

void SimulationController::setTrajectory(std::shared_ptr<const Trajectory> trajectory) {
  pause();
  trajectory_ = std::move(trajectory);
  timeS_ = 0.0;
  emit trajectoryChanged();
  emit timeChanged(timeS_);
}

TrajectorySample SimulationController::sample() const {
  return trajectory_ ? trajectory_->at(timeS_) : TrajectorySample{};
}

int SimulationController::completedMoves() const {
  if (!trajectory_) return 0;
  if (atEnd()) return static_cast<int>(trajectory_->job().moves.size());
  return std::max(0, sample().moveIndex);
}

void SimulationController::play() {
  if (!trajectory_ || playing()) return;
  if (atEnd()) setTimeS(0.0);
  wall_.start();
  timer_.start();
  emit playingChanged(true);
}

void SimulationController::pause() {
  if (!playing()) return;
  timer_.stop();
  emit playingChanged(false);
}

void SimulationController::togglePlay() { playing() ? pause() : play(); }

void SimulationController::stepForward() {
  if (!trajectory_) return;
  const auto& moves = trajectory_->job().moves;
  const int i = sample().moveIndex;
  for (std::size_t k = static_cast<std::size_t>(std::max(i + 1, 0)); k < moves.size(); ++k) {
    if (moves[k].startTimeS > timeS_) {
      setTimeS(moves[k].startTimeS);
      return;
    }
  }
  setTimeS(durationS());
}

void SimulationController::stepBackward() {
  if (!trajectory_) return;
  const auto& moves = trajectory_->job().moves;
  for (std::size_t k = moves.size(); k-- > 0;) {
    if (moves[k].startTimeS < timeS_) {
      setTimeS(moves[k].startTimeS);
      return;
    }
  }
  setTimeS(0.0);
}

void SimulationController::setTimeS(double timeS) {
  timeS_ = std::clamp(timeS, 0.0, durationS());
  emit timeChanged(timeS_);
}

void SimulationController::setSpeed(double speed) {
  speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
  emit speedChanged(speed_);
}

void SimulationController::advance(double wallS) {
  if (!trajectory_) return;
  setTimeS(timeS_ + wallS * speed_);
  if (atEnd()) {
    pause();
    emit finished();
  }
}

void SimulationController::tick() {
  const double wallS = wall_.restart() * 1e-3;
  advance(wallS);
}

}  // namespace fivebar::widgets
