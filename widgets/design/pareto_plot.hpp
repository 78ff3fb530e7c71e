// SPDX-License-Identifier: GPL-3.0-or-later
// The trade-off plot of the Design dialog: worst-case condition number (up) against footprint
// (right), one dot per design; a click selects the nearest dot.
#pragma once

#include <QWidget>
#include <vector>

namespace fivebar::widgets {

class ParetoPlot : public QWidget {
  Q_OBJECT
 public:
  explicit ParetoPlot(QWidget* parent = nullptr);
  struct Point {
    double footprintCm2 = 0.0;
    double condition = 0.0;
  };
  void setPoints(std::vector<Point> points);
  void setSelected(int index);
  int selected() const { return selected_; }
  QSize sizeHint() const override { return {360, 220}; }
  // Widget position of point `index` (for tests).
  QPointF positionOf(int index) const;

 signals:
  void pointClicked(int index);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;

 private:
  QRectF plotRect() const;
  std::vector<Point> points_;
  int selected_ = -1;
  double x0_ = 0, x1_ = 1, y0_ = 0, y1_ = 1;
};

}  // namespace fivebar::widgets
