// SPDX-License-Identifier: GPL-3.0-or-later
// Simulation controls: play/pause, step back/forward, speed x0.5..x50, a timeline to scrub, and
// live readouts of the motor angles, transmission angles and singularity margin at the pose.
#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace fivebar::widgets {

class SimulationController;
class StudioDocument;

class SimulationPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kTimelineSteps = 10000;

  SimulationPanel(SimulationController& sim, const StudioDocument& doc, QWidget* parent = nullptr);

  QLabel* readout() const { return readout_; }

 private:
  void showTime();
  void showPlaying(bool playing);

  SimulationController& sim_;
  const StudioDocument& doc_;
  QToolButton* play_ = nullptr;
  QToolButton* back_ = nullptr;
  QToolButton* forward_ = nullptr;
  QComboBox* speed_ = nullptr;
  QSlider* timeline_ = nullptr;
  QLabel* time_ = nullptr;
  QLabel* readout_ = nullptr;
};

}  // namespace fivebar::widgets
