// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration wizard's picture of the sheet (machine frame, y up): the pattern as planned, what
// the pen really drew on the simulated machine, the marks with the one being typed highlighted,
// the measured marks placed onto the pattern, and residual arrows (scaled, with a legend).
// Paints only what it is given; computes no kinematics.
#pragma once

#include <QString>
#include <QWidget>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar::widgets::calibration {

struct PreviewArrow {
  Vec2 atMm = Vec2::Zero();      // machine frame
  Vec2 errorMm = Vec2::Zero();   // the error itself (drawn scaled)
  bool after = false;            // after calibration (red) or before (grey)
};

class CalibrationPreview : public QWidget {
  Q_OBJECT
 public:
  explicit CalibrationPreview(QWidget* parent = nullptr);

  void setPlan(std::vector<std::vector<Vec2>> strokes);
  void setTrueTrace(std::vector<std::vector<Vec2>> strokes);  // empty: none
  void setMarks(std::vector<Vec2> centresMm, std::vector<int> ids);
  void setHighlighted(int markIndex);  // -1: none
  void setMeasured(std::vector<Vec2> placedMm);  // measured marks placed onto the pattern
  void setArrows(std::vector<PreviewArrow> arrows);
  int highlighted() const { return highlighted_; }
  // The arrow scale in use (screen length per mm of error over the sheet's mm), for tests.
  double arrowScale() const { return arrowScale_; }

  QSize sizeHint() const override { return {460, 380}; }
  QSize minimumSizeHint() const override { return {260, 220}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  void updateArrowScale();

  std::vector<std::vector<Vec2>> plan_, trace_;
  std::vector<Vec2> marks_, measured_;
  std::vector<int> ids_;
  std::vector<PreviewArrow> arrows_;
  int highlighted_ = -1;
  double arrowScale_ = 1.0;
};

}  // namespace fivebar::widgets::calibration
