// SPDX-License-Identifier: GPL-3.0-or-later
// The job preview: planning status, estimated time, lengths and segments, the colour and travel
// switches with the speed legend, a scrubber over the drawing order, and the pre-flight problems
// (a click centres the canvas on the problem and marks it).
#pragma once

#include <QPointF>
#include <QWidget>

class QCheckBox;
class QLabel;
class QListWidget;
class QSlider;

namespace fivebar::widgets {

class JobLayer;
class PreviewController;

class SpeedLegend : public QWidget {
  Q_OBJECT
 public:
  explicit SpeedLegend(QWidget* parent = nullptr);
  void setMaxSpeed(double mmPerS);
  QSize sizeHint() const override { return {220, 34}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  double maxSpeed_ = 0.0;
};

class PreviewPanel : public QWidget {
  Q_OBJECT
 public:
  PreviewPanel(PreviewController& preview, JobLayer& layer, QWidget* parent = nullptr);

  QListWidget* problems() const { return problems_; }
  QSlider* scrubber() const { return scrubber_; }
  QLabel* statistics() const { return stats_; }

 public slots:
  // A problem found outside the plan (the connected board's soft limits, session/board_preflight):
  // listed first among the pre-flight problems; "" removes it.
  void setMachineProblem(const QString& problem);

 signals:
  // A problem was chosen: centre the canvas here (machine frame, mm).
  void showLocation(QPointF machineMm);

 private:
  void showResult();
  void showPlanning();

  PreviewController& preview_;
  JobLayer& layer_;
  QLabel* status_ = nullptr;
  QLabel* stats_ = nullptr;
  QCheckBox* bySpeed_ = nullptr;
  QCheckBox* travel_ = nullptr;
  SpeedLegend* legend_ = nullptr;
  QSlider* scrubber_ = nullptr;
  QLabel* scrubLabel_ = nullptr;
  QListWidget* problems_ = nullptr;
  QString machineProblem_;
};

// "1 h 02 min", "3 min 05 s", "12.4 s".
QString formatJobTime(double seconds);

}  // namespace fivebar::widgets
