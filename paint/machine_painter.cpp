// SPDX-License-Identifier: GPL-3.0-or-later
#include "paint/machine_painter.hpp"

#include <QCoreApplication>
#include <QFontMetricsF>

#include <QLocale>
#include <QPen>
#include <array>
#include <cmath>

#include "paint/studio_palette.hpp"

namespace fivebar::paint {
namespace {

constexpr double kMinMinorSpacingPx = 8.0;

// Smallest of 1, 2, 5 x 10^k mm whose spacing on screen is at least kMinMinorSpacingPx.
double minorSpacingMm(double pxPerMm) {
  const double minMm = kMinMinorSpacingPx / pxPerMm;
  double decade = std::pow(10.0, std::floor(std::log10(minMm)));
  for (int i = 0; i < 4; ++i) {
    for (const double m : {1.0, 2.0, 5.0}) {
      if (m * decade >= minMm) return m * decade;
    }
    decade *= 10.0;
  }
  return decade;
}

QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }

}  // namespace

void paintGrid(QPainter& painter, const ViewTransform& view) {
  painter.save();
  const QSizeF size = view.viewportPx();
  painter.fillRect(QRectF(QPointF(0, 0), size), palette::background());
  const QRectF r = view.visibleMachineRect();
  const double minor = minorSpacingMm(view.pxPerMm());
  const double major = minor * 5.0;
  const QTransform t = view.widgetFromMachine();
  painter.setRenderHint(QPainter::Antialiasing, false);
  QVector<QLineF> minorLines;
  QVector<QLineF> majorLines;
  const long ix0 = static_cast<long>(std::floor(r.left() / minor));
  const long ix1 = static_cast<long>(std::ceil(r.right() / minor));
  for (long i = ix0; i <= ix1; ++i) {
    const double x = t.map(QPointF(i * minor, 0.0)).x();
    (i % 5 == 0 ? majorLines : minorLines).append(QLineF(x, 0.0, x, size.height()));
  }
  const long iy0 = static_cast<long>(std::floor(r.top() / minor));
  const long iy1 = static_cast<long>(std::ceil(r.bottom() / minor));
  for (long i = iy0; i <= iy1; ++i) {
    const double y = t.map(QPointF(0.0, i * minor)).y();
    (i % 5 == 0 ? majorLines : minorLines).append(QLineF(0.0, y, size.width(), y));
  }
  painter.setPen(QPen(palette::gridMinor(), 0));
  painter.drawLines(minorLines);
  painter.setPen(QPen(palette::gridMajor(), 0));
  painter.drawLines(majorLines);
  // Axes through the machine origin (midway between the motors).
  const QPointF o = t.map(QPointF(0.0, 0.0));
  painter.setPen(QPen(palette::axis(), 1.0, Qt::DashLine));
  painter.drawLine(QLineF(o.x(), 0.0, o.x(), size.height()));
  painter.drawLine(QLineF(0.0, o.y(), size.width(), o.y()));
  // Major line labels along the top and left edges.
  QFont font = painter.font();
  font.setPointSizeF(8.0);
  painter.setFont(font);
  painter.setPen(palette::gridLabel());
  const long jx0 = static_cast<long>(std::ceil(r.left() / major));
  const long jx1 = static_cast<long>(std::floor(r.right() / major));
  for (long j = jx0; j <= jx1; ++j) {
    const double x = t.map(QPointF(j * major, 0.0)).x();
    painter.drawText(QPointF(x + 3.0, 12.0), QLocale().toString(j * major, 'g', 6));
  }
  const long jy0 = static_cast<long>(std::ceil(r.top() / major));
  const long jy1 = static_cast<long>(std::floor(r.bottom() / major));
  for (long j = jy0; j <= jy1; ++j) {
    const double y = t.map(QPointF(0.0, j * major)).y();
    painter.drawText(QPointF(3.0, y - 3.0), QLocale().toString(j * major, 'g', 6));
  }
  painter.restore();
}

void paintMachine(QPainter& painter, const QTransform& widgetFromMachine, const Geometry& g,
                  const Pose& pose, double opacity, const std::optional<Vec2>& penMm) {
  painter.save();
  painter.setOpacity(opacity);
  painter.setRenderHint(QPainter::Antialiasing, true);
  const QTransform& t = widgetFromMachine;
  const QPointF m1 = t.map(toQ(g.motor1()));
  const QPointF m2 = t.map(toQ(g.motor2()));
  const QPointF r1 = t.map(toQ(pose.R1));
  const QPointF r2 = t.map(toQ(pose.R2));
  const QPointF p = t.map(toQ(pose.P));
  const double pxPerMm = std::hypot(t.m11(), t.m12());
  // Sizes follow the zoom but stay readable when zoomed far out.
  const double linkWidth = std::clamp(6.0 * pxPerMm, 3.0, 18.0);
  const double jointRadius = std::clamp(4.0 * pxPerMm, 3.0, 12.0);
  const double motorRadius = std::clamp(14.0 * pxPerMm, 7.0, 40.0);

  // Base: a plate under and between the motors.
  const double plateHalf = motorRadius * 1.4;
  QRectF plate(QPointF(std::min(m1.x(), m2.x()) - plateHalf, m1.y() - plateHalf * 0.6),
               QPointF(std::max(m1.x(), m2.x()) + plateHalf, m1.y() + plateHalf * 1.2));
  painter.setPen(Qt::NoPen);
  QColor plateColor = palette::machineBase();
  plateColor.setAlpha(40);
  painter.setBrush(plateColor);
  painter.drawRoundedRect(plate, plateHalf * 0.3, plateHalf * 0.3);

  for (const QPointF& m : {m1, m2}) {
    painter.setBrush(palette::machineBase());
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(m, motorRadius, motorRadius);
  }
  const auto link = [&](QPointF a, QPointF b, const QColor& c, double width) {
    painter.setPen(QPen(c, width, Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(a, b);
  };
  link(m1, r1, palette::drivingLink(), linkWidth);
  link(m2, r2, palette::drivingLink(), linkWidth);
  link(r1, p, palette::floatingLink(), linkWidth * 0.7);
  link(r2, p, palette::floatingLink(), linkWidth * 0.7);
  const bool offset = penMm && (*penMm - pose.P).norm() > 1e-9;
  const QPointF pen = offset ? t.map(toQ(*penMm)) : p;
  // A pen off P sits on a bracket fixed to link b1 (R1 -> P -> pen are rigid).
  if (offset) link(p, pen, palette::floatingLink(), linkWidth * 0.45);
  painter.setPen(QPen(palette::machineBase(), 1.5));
  painter.setBrush(palette::joint());
  for (const QPointF& j : {m1, m2, r1, r2}) painter.drawEllipse(j, jointRadius, jointRadius);
  if (offset) painter.drawEllipse(p, jointRadius * 0.8, jointRadius * 0.8);
  painter.setBrush(palette::pen());
  painter.setPen(QPen(Qt::white, 1.5));
  painter.drawEllipse(pen, jointRadius * 1.3, jointRadius * 1.3);
  painter.restore();
}

void paintUnknownPose(QPainter& painter, const QTransform& widgetFromMachine, const Geometry& g) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  const QPointF m1 = widgetFromMachine.map(toQ(g.motor1()));
  const QPointF m2 = widgetFromMachine.map(toQ(g.motor2()));
  const double pxPerMm = std::hypot(widgetFromMachine.m11(), widgetFromMachine.m12());
  const double motorRadius = std::clamp(14.0 * pxPerMm, 7.0, 40.0);
  QColor warn(0xb4, 0x53, 0x09);
  for (const QPointF& m : {m1, m2}) {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(warn, 2.0, Qt::DashLine));
    painter.drawEllipse(m, motorRadius, motorRadius);
  }
  const QPointF centre = (m1 + m2) / 2.0;
  QFont font = painter.font();
  font.setBold(true);
  painter.setFont(font);
  const QString text = QCoreApplication::translate("fivebar::widgets::MachineLayer", "Position unknown: set the reference pose");
  const QFontMetricsF metrics(font);
  const QRectF box(centre.x() - metrics.horizontalAdvance(text) / 2.0 - 6.0,
                   centre.y() - motorRadius * 2.2 - metrics.height(), metrics.horizontalAdvance(text) + 12.0,
                   metrics.height() + 6.0);
  painter.setPen(QPen(warn, 1.0));
  painter.setBrush(QColor(0xfe, 0xf3, 0xc7));
  painter.drawRoundedRect(box, 4.0, 4.0);
  painter.setPen(warn);
  painter.drawText(box, Qt::AlignCenter, text);
  painter.restore();
}

}  // namespace fivebar::paint
