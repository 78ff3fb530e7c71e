// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/sheet_layer.hpp"

#include <QPainterPath>

namespace fivebar::widgets::calibration {

namespace {
const QColor kPlan(40, 90, 190);
const QColor kTrace(230, 120, 0);
}  // namespace

void SheetLayer::setSheet(std::vector<std::vector<Vec2>> plan, std::vector<std::vector<Vec2>> trace) {
  plan_ = std::move(plan);
  trace_ = std::move(trace);
  emit changed();
}

void SheetLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  if (empty()) return;
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing);
  auto draw = [&](const std::vector<std::vector<Vec2>>& strokes, const QPen& pen) {
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    for (const auto& s : strokes) {
      if (s.empty()) continue;
      const QPointF first = view.widgetFromMachine(QPointF(s.front().x(), s.front().y()));
      if (s.size() == 1) {
        painter.drawEllipse(first, 1.5, 1.5);
        continue;
      }
      QPainterPath path(first);
      for (std::size_t i = 1; i < s.size(); ++i) path.lineTo(view.widgetFromMachine(QPointF(s[i].x(), s[i].y())));
      painter.drawPath(path);
    }
  };
  QPen planPen(kPlan, 1.0, Qt::DashLine);
  draw(plan_, planPen);
  draw(trace_, QPen(kTrace, 1.4));
  // Legend, bottom left.
  const QStringList texts{tr("Calibration pattern (plan)"), tr("Drawn by the pen (simulated imperfect machine)")};
  const int rows = trace_.empty() ? 1 : 2;
  const QFontMetrics fm(painter.font());
  int width = 0;
  for (int i = 0; i < rows; ++i) width = std::max(width, fm.horizontalAdvance(texts[i]));
  const QRectF box(10, painter.viewport().height() - 14 - rows * (fm.height() + 4), width + 42, rows * (fm.height() + 4) + 6);
  painter.setPen(QColor(160, 160, 160));
  painter.setBrush(QColor(255, 255, 255, 225));
  painter.drawRect(box);
  for (int i = 0; i < rows; ++i) {
    const double y = box.top() + 4 + i * (fm.height() + 4) + fm.height() / 2.0;
    painter.setPen(i == 0 ? planPen : QPen(kTrace, 2.0));
    painter.drawLine(QPointF(box.left() + 8, y), QPointF(box.left() + 30, y));
    painter.setPen(Qt::black);
    painter.drawText(QPointF(box.left() + 36, y + fm.ascent() / 2.0 - 1), texts[i]);
  }
  painter.restore();
}

}  // namespace fivebar::widgets::calibration
