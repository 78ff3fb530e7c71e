// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/calibration_preview.hpp"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace fivebar::widgets::calibration {

namespace {
const QColor kPlan(70, 70, 70);
const QColor kTrace(230, 120, 0);
const QColor kMark(30, 90, 200);
const QColor kMeasured(20, 150, 60);
const QColor kBefore(140, 140, 140);
const QColor kAfter(210, 30, 30);
}  // namespace

CalibrationPreview::CalibrationPreview(QWidget* parent) : QWidget(parent) {
  setAutoFillBackground(true);
  QPalette p = palette();
  p.setColor(QPalette::Window, Qt::white);
  setPalette(p);
}

void CalibrationPreview::setPlan(std::vector<std::vector<Vec2>> strokes) {
  plan_ = std::move(strokes);
  update();
}
void CalibrationPreview::setTrueTrace(std::vector<std::vector<Vec2>> strokes) {
  trace_ = std::move(strokes);
  update();
}
void CalibrationPreview::setMarks(std::vector<Vec2> centresMm, std::vector<int> ids) {
  marks_ = std::move(centresMm);
  ids_ = std::move(ids);
  highlighted_ = -1;
  update();
}
void CalibrationPreview::setHighlighted(int markIndex) {
  highlighted_ = markIndex;
  update();
}
void CalibrationPreview::setMeasured(std::vector<Vec2> placedMm) {
  measured_ = std::move(placedMm);
  update();
}
void CalibrationPreview::setArrows(std::vector<PreviewArrow> arrows) {
  arrows_ = std::move(arrows);
  updateArrowScale();
  update();
}

void CalibrationPreview::updateArrowScale() {
  // The largest arrow is drawn about 8 % of the sheet's size long; the scale is a round number.
  double largest = 0.0;
  for (const PreviewArrow& a : arrows_) largest = std::max(largest, a.errorMm.norm());
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Vec2& p : marks_) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  for (const PreviewArrow& a : arrows_)
    x0 = std::min(x0, a.atMm.x()), x1 = std::max(x1, a.atMm.x()), y0 = std::min(y0, a.atMm.y()), y1 = std::max(y1, a.atMm.y());
  const double span = x1 > x0 ? std::max(x1 - x0, y1 - y0) : 100.0;
  arrowScale_ = 1.0;
  if (largest <= 0.0) return;
  for (double s : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0}) {
    if (largest * s > 0.08 * span) break;
    arrowScale_ = s;
  }
}

void CalibrationPreview::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  // Bounds of everything in mm.
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  auto grow = [&](const Vec2& p) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  };
  for (const auto& s : plan_) for (const Vec2& p : s) grow(p);
  for (const auto& s : trace_) for (const Vec2& p : s) grow(p);
  for (const Vec2& p : marks_) grow(p);
  if (x0 > x1) {
    painter.setPen(palette().color(QPalette::PlaceholderText));
    painter.drawText(rect(), Qt::AlignCenter, tr("No pattern yet"));
    return;
  }
  const double legendH = 22.0;
  const QRectF area = QRectF(rect()).adjusted(12, 12 + legendH, -12, -12);
  const double spanX = std::max(x1 - x0, 1.0), spanY = std::max(y1 - y0, 1.0);
  const double scale = std::min(area.width() / spanX, area.height() / spanY);
  const double ox = area.center().x() - (x0 + x1) / 2.0 * scale;
  const double oy = area.center().y() + (y0 + y1) / 2.0 * scale;
  auto map = [&](const Vec2& p) { return QPointF(ox + p.x() * scale, oy - p.y() * scale); };
  auto drawStrokes = [&](const std::vector<std::vector<Vec2>>& strokes, const QPen& pen) {
    painter.setPen(pen);
    for (const auto& s : strokes) {
      if (s.size() == 1) {
        painter.drawEllipse(map(s.front()), 1.2, 1.2);
        continue;
      }
      QPainterPath path(map(s.front()));
      for (std::size_t i = 1; i < s.size(); ++i) path.lineTo(map(s[i]));
      painter.drawPath(path);
    }
  };
  drawStrokes(plan_, QPen(kPlan, 1.0));
  if (!trace_.empty()) drawStrokes(trace_, QPen(kTrace, 1.2));

  // The mark being typed.
  if (highlighted_ >= 0 && highlighted_ < static_cast<int>(marks_.size())) {
    const QPointF c = map(marks_[highlighted_]);
    painter.setPen(QPen(kMark, 2.5));
    painter.setBrush(QColor(30, 90, 200, 40));
    painter.drawEllipse(c, 11.0, 11.0);
    painter.setBrush(Qt::NoBrush);
    if (highlighted_ < static_cast<int>(ids_.size())) {
      QFont f = font();
      f.setBold(true);
      painter.setFont(f);
      painter.drawText(c + QPointF(13, -8), QString::number(ids_[highlighted_]));
      painter.setFont(font());
    }
  }
  painter.setPen(QPen(kMeasured, 1.6));
  for (const Vec2& p : measured_) {
    const QPointF c = map(p);
    painter.drawLine(c + QPointF(-4, -4), c + QPointF(4, 4));
    painter.drawLine(c + QPointF(-4, 4), c + QPointF(4, -4));
  }
  // Residual arrows, scaled.
  for (const PreviewArrow& a : arrows_) {
    const QPointF from = map(a.atMm);
    const QPointF to = map(a.atMm + a.errorMm * arrowScale_);
    painter.setPen(QPen(a.after ? kAfter : kBefore, a.after ? 1.8 : 1.4));
    painter.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len > 3.0) {
      const QPointF u = d / len, n(-u.y(), u.x());
      painter.drawLine(to, to - u * 6.0 + n * 3.0);
      painter.drawLine(to, to - u * 6.0 - n * 3.0);
    }
  }

  // Legend: one entry per thing shown.
  struct Entry { QColor color; QString text; };
  std::vector<Entry> entries{{kPlan, tr("pattern as planned")}};
  if (!trace_.empty()) entries.push_back({kTrace, tr("drawn by the pen (simulation)")});
  if (!measured_.empty()) entries.push_back({kMeasured, tr("measured")});
  bool before = false, after = false;
  for (const PreviewArrow& a : arrows_) (a.after ? after : before) = true;
  if (before) entries.push_back({kBefore, tr("error before")});
  if (after) entries.push_back({kAfter, tr("error after")});
  if (!arrows_.empty()) entries.push_back({QColor(0, 0, 0, 0), tr("arrows \u00d7%1").arg(arrowScale_)});
  double x = 8.0;
  const QFontMetrics fm(font());
  for (const Entry& e : entries) {
    if (e.color.alpha() > 0) {
      painter.fillRect(QRectF(x, 9, 14, 4), e.color);
      x += 18.0;
    }
    painter.setPen(palette().color(QPalette::Text).alpha() ? QColor(40, 40, 40) : Qt::black);
    painter.drawText(QPointF(x, 16), e.text);
    x += fm.horizontalAdvance(e.text) + 14.0;
  }
}

}  // namespace fivebar::widgets::calibration
