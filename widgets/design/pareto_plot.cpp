// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/design/pareto_plot.hpp"

#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "paint/studio_palette.hpp"

namespace fivebar::widgets {

ParetoPlot::ParetoPlot(QWidget* parent) : QWidget(parent) { setMinimumSize(260, 180); }

void ParetoPlot::setPoints(std::vector<Point> points) {
  points_ = std::move(points);
  selected_ = -1;
  x0_ = y0_ = 1e300;
  x1_ = y1_ = -1e300;
  for (const Point& p : points_) {
    x0_ = std::min(x0_, p.footprintCm2), x1_ = std::max(x1_, p.footprintCm2);
    y0_ = std::min(y0_, p.condition), y1_ = std::max(y1_, p.condition);
  }
  if (points_.empty()) x0_ = y0_ = 0, x1_ = y1_ = 1;
  const double padX = std::max(0.05 * (x1_ - x0_), 1.0), padY = std::max(0.05 * (y1_ - y0_), 0.05);
  x0_ -= padX, x1_ += padX, y0_ = std::max(1.0, y0_ - padY), y1_ += padY;
  update();
}

void ParetoPlot::setSelected(int index) {
  selected_ = index;
  update();
}

QRectF ParetoPlot::plotRect() const { return QRectF(48.0, 10.0, width() - 60.0, height() - 44.0); }

QPointF ParetoPlot::positionOf(int index) const {
  const QRectF r = plotRect();
  const Point& p = points_[static_cast<std::size_t>(index)];
  return {r.left() + r.width() * (p.footprintCm2 - x0_) / (x1_ - x0_),
          r.bottom() - r.height() * (p.condition - y0_) / (y1_ - y0_)};
}

void ParetoPlot::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.fillRect(rect(), paint::palette::background());
  const QRectF r = plotRect();
  painter.setPen(QPen(paint::palette::axis(), 1.0));
  painter.drawRect(r);
  QFont font = painter.font();
  font.setPointSizeF(8.0);
  painter.setFont(font);
  painter.setPen(paint::palette::gridLabel());
  // Footprints are whole cm² unless the range is narrow (an empty plot spans 0..1).
  const int xDecimals = (x1_ - x0_) >= 8.0 ? 0 : 2;
  for (int k = 0; k <= 4; ++k) {
    const double fx = x0_ + (x1_ - x0_) * k / 4.0, fy = y0_ + (y1_ - y0_) * k / 4.0;
    const double px = r.left() + r.width() * k / 4.0, py = r.bottom() - r.height() * k / 4.0;
    painter.drawText(QRectF(px - 30, r.bottom() + 2, 60, 14), Qt::AlignCenter, QLocale().toString(fx, 'f', xDecimals));
    painter.drawText(QRectF(0, py - 7, 44, 14), Qt::AlignRight | Qt::AlignVCenter, QLocale().toString(fy, 'f', 2));
  }
  painter.drawText(QRectF(r.left(), height() - 16, r.width(), 14), Qt::AlignCenter, tr("Footprint (cm\u00b2)"));
  painter.save();
  painter.translate(10, r.center().y());
  painter.rotate(-90);
  painter.drawText(QRectF(-80, -8, 160, 14), Qt::AlignCenter, tr("Worst condition number"));
  painter.restore();
  painter.setPen(QPen(paint::palette::travel(), 1.0, Qt::DashLine));
  for (std::size_t i = 1; i < points_.size(); ++i)
    painter.drawLine(positionOf(static_cast<int>(i - 1)), positionOf(static_cast<int>(i)));
  for (int i = 0; i < static_cast<int>(points_.size()); ++i) {
    const bool sel = i == selected_;
    painter.setPen(QPen(Qt::white, 1.0));
    painter.setBrush(sel ? paint::palette::selection() : paint::palette::drawing());
    painter.drawEllipse(positionOf(i), sel ? 6.5 : 4.5, sel ? 6.5 : 4.5);
  }
}

void ParetoPlot::mousePressEvent(QMouseEvent* event) {
  int best = -1;
  double bestD = 20.0;  // px
  for (int i = 0; i < static_cast<int>(points_.size()); ++i) {
    const QPointF d = positionOf(i) - event->position();
    const double dist = std::hypot(d.x(), d.y());
    if (dist < bestD) bestD = dist, best = i;
  }
  if (best >= 0) {
    setSelected(best);
    emit pointClicked(best);
  }
}

}  // namespace fivebar::widgets
