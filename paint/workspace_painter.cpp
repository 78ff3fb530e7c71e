// SPDX-License-Identifier: GPL-3.0-or-later
#include "paint/workspace_painter.hpp"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QImage>
#include <QLocale>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>
#include <cmath>

#include "paint/studio_palette.hpp"

namespace fivebar::paint {
namespace {

// Overlay colours (the palette's problem red and trace teal, plus region tints).
QColor safeFill() { return QColor(0x34, 0xd3, 0x99, 90); }
QColor marginFill() { return QColor(0xf5, 0x9e, 0x0b, 110); }
QColor reachLine() { return palette::trace(); }
QColor safeLine() { return QColor(0x05, 0x96, 0x69); }
QColor typeIILine() { return palette::problem(); }
QColor rectangleLine() { return palette::drawing(); }

// One pixel per cell: safe cells green, reachable cells within a margin amber, others clear.
QImage regionImage(const WorkspaceMap& map) {
  const GridSpec& g = map.grid;
  QImage image(g.nx, g.ny, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  const QRgb safe = qPremultiply(safeFill().rgba()), margin = qPremultiply(marginFill().rgba());
  for (int iy = 0; iy < g.ny; ++iy) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(g.ny - 1 - iy));  // image rows run down
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t i = g.index(ix, iy);
      if (map.reachable[i]) row[ix] = map.safe(i) ? safe : margin;
    }
  }
  return image;
}

// Image pixel (u, v) -> machine mm: x = x0 + u c, y = y0 + (ny - v) c.
QTransform machineFromImage(const GridSpec& g) {
  return QTransform(g.cellMm, 0.0, 0.0, -g.cellMm, g.x0, g.y0 + g.ny * g.cellMm);
}

void drawPolylines(QPainter& painter, const QTransform& widgetFromMachine,
                   const std::vector<Polyline>& lines, const QPen& pen) {
  painter.setPen(pen);
  painter.setBrush(Qt::NoBrush);
  for (const Polyline& line : lines) {
    QPolygonF poly;
    poly.reserve(static_cast<qsizetype>(line.points.size()) + 1);
    for (const Vec2& p : line.points) poly << widgetFromMachine.map(QPointF(p.x(), p.y()));
    if (line.closed && !poly.isEmpty()) poly << poly.front();
    painter.drawPolyline(poly);
  }
}

QString sizeText(const Rect& r) {
  return QStringLiteral("%1 x %2 mm").arg(QLocale().toString(r.width(), 'f', 1)).arg(QLocale().toString(r.height(), 'f', 1));
}

void drawRectangle(QPainter& painter, const QTransform& widgetFromMachine, const Rect& r) {
  const QRectF px = widgetFromMachine.mapRect(QRectF(r.xMin, r.yMin, r.width(), r.height()));
  painter.setPen(QPen(rectangleLine(), 2.0));
  painter.setBrush(QColor(0x1d, 0x4e, 0xd8, 28));
  painter.drawRect(px);
  QFont font = painter.font();
  font.setPointSizeF(9.0);
  font.setBold(true);
  painter.setFont(font);
  const QString text = sizeText(r);
  const QFontMetricsF fm(font);
  if (fm.horizontalAdvance(text) + 8.0 < px.width() && fm.height() + 6.0 < px.height()) {
    painter.setPen(rectangleLine());
    painter.drawText(px.adjusted(4.0, 3.0, -4.0, -3.0), Qt::AlignLeft | Qt::AlignTop, text);
  }
}

}  // namespace

void paintWorkspace(QPainter& painter, const QTransform& widgetFromMachine,
                    const WorkspaceMap& map, const WorkspaceAnalysis& analysis,
                    const WorkspacePaintOptions& options) {
  if (map.grid.size() == 0) return;
  painter.save();
  painter.setOpacity(painter.opacity() * options.opacity);
  if (options.fillRegions) {
    painter.save();
    painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
    painter.setTransform(machineFromImage(map.grid) * widgetFromMachine, true);
    painter.drawImage(QPointF(0.0, 0.0), regionImage(map));
    painter.restore();
  }
  painter.setRenderHint(QPainter::Antialiasing, true);
  if (options.drawBoundaries) {
    drawPolylines(painter, widgetFromMachine, analysis.reachBoundary, QPen(reachLine(), 1.6));
    QPen dashed(safeLine(), 1.2, Qt::DashLine);
    drawPolylines(painter, widgetFromMachine, analysis.safeBoundary, dashed);
  }
  if (options.drawTypeII)
    drawPolylines(painter, widgetFromMachine, analysis.typeIILoci, QPen(typeIILine(), 2.4));
  if (options.drawRectangle && analysis.largestRectangle)
    drawRectangle(painter, widgetFromMachine, *analysis.largestRectangle);
  painter.restore();
}

double paintWorkspaceLegend(QPainter& painter, QPointF topLeftPx, const WorkspaceMap& map,
                            const WorkspaceAnalysis& analysis) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  QFont font = painter.font();
  font.setPointSizeF(9.0);
  painter.setFont(font);
  const QFontMetricsF fm(font);
  const double line = fm.height() + 6.0, swatch = 22.0, pad = 10.0;
  // Legend text: translation context "WorkspaceLegend" (no QObject here).
  const QString marginText =
      QCoreApplication::translate("WorkspaceLegend", "type II >= %1 deg, type I >= %2 deg")
          .arg(QLocale().toString(degFromRad(map.typeIIMarginRad), 'f', 0))
          .arg(QLocale().toString(degFromRad(map.typeIMarginRad), 'f', 0));
  struct Entry {
    QString text;
    QColor fill;
    QPen pen;
  };
  const QString rect = analysis.largestRectangle
                           ? sizeText(*analysis.largestRectangle)
                           : QCoreApplication::translate("WorkspaceLegend", "none");
  const std::vector<Entry> entries{
      {QCoreApplication::translate("WorkspaceLegend", "singularity-free (%1)").arg(marginText),
       safeFill(), Qt::NoPen},
      {QCoreApplication::translate("WorkspaceLegend", "reachable, within a singularity margin"),
       marginFill(), Qt::NoPen},
      {QCoreApplication::translate("WorkspaceLegend", "reach boundary"), Qt::transparent,
       QPen(reachLine(), 1.6)},
      {QCoreApplication::translate("WorkspaceLegend", "singularity-free boundary"),
       Qt::transparent, QPen(safeLine(), 1.2, Qt::DashLine)},
      {QCoreApplication::translate("WorkspaceLegend", "type II singularity (%1 curves)")
           .arg(analysis.typeIILoci.size()),
       Qt::transparent, QPen(typeIILine(), 2.4)},
      {QCoreApplication::translate("WorkspaceLegend", "largest rectangle: %1").arg(rect),
       QColor(0x1d, 0x4e, 0xd8, 28), QPen(rectangleLine(), 2.0)},
  };
  const QStringList areas{
      QCoreApplication::translate("WorkspaceLegend", "reachable area: %1 cm\u00b2")
          .arg(QLocale().toString(analysis.reachableAreaMm2 / 100.0, 'f', 1)),
      QCoreApplication::translate("WorkspaceLegend", "singularity-free area: %1 cm\u00b2")
          .arg(QLocale().toString(analysis.safeAreaMm2 / 100.0, 'f', 1))};
  double width = 0.0;
  for (const Entry& e : entries) width = std::max(width, fm.horizontalAdvance(e.text));
  for (const QString& a : areas) width = std::max(width, fm.horizontalAdvance(a));
  width += swatch + 3.0 * pad;
  const double height = (entries.size() + areas.size()) * line + 2.0 * pad + 4.0;
  painter.setPen(QPen(palette::gridMajor(), 1.0));
  painter.setBrush(QColor(255, 255, 255, 235));
  painter.drawRoundedRect(QRectF(topLeftPx, QSizeF(width, height)), 6.0, 6.0);
  double y = topLeftPx.y() + pad;
  const double x = topLeftPx.x() + pad;
  for (const Entry& e : entries) {
    const QRectF sw(x, y + 0.5 * (line - 12.0), swatch, 12.0);
    painter.setPen(Qt::NoPen);
    painter.setBrush(e.fill);
    painter.drawRect(sw);
    if (e.pen.style() != Qt::NoPen) {
      painter.setPen(e.pen);
      painter.setBrush(Qt::NoBrush);
      if (e.fill.alpha() > 0) painter.drawRect(sw);
      else painter.drawLine(QLineF(sw.left(), sw.center().y(), sw.right(), sw.center().y()));
    }
    painter.setPen(palette::machineBase());
    painter.drawText(QRectF(x + swatch + pad, y, width, line), Qt::AlignVCenter, e.text);
    y += line;
  }
  y += 4.0;
  for (const QString& a : areas) {
    painter.drawText(QRectF(x, y, width, line), Qt::AlignVCenter, a);
    y += line;
  }
  painter.restore();
  return height;
}

void paintScaleBar(QPainter& painter, const QTransform& widgetFromMachine, QPointF leftPx,
                   double targetPx) {
  const double pxPerMm = QLineF(widgetFromMachine.map(QPointF(0, 0)),
                                widgetFromMachine.map(QPointF(1, 0))).length();
  if (!(pxPerMm > 0.0)) return;
  const double wantMm = targetPx / pxPerMm;
  const double decade = std::pow(10.0, std::floor(std::log10(wantMm)));
  double lengthMm = decade;
  for (double m : {2.0, 5.0, 10.0})
    if (m * decade <= wantMm) lengthMm = m * decade;
  const double lengthPx = lengthMm * pxPerMm;
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setPen(QPen(palette::machineBase(), 2.0));
  const QPointF right = leftPx + QPointF(lengthPx, 0.0);
  painter.drawLine(leftPx, right);
  painter.drawLine(leftPx, leftPx - QPointF(0.0, 6.0));
  painter.drawLine(right, right - QPointF(0.0, 6.0));
  QFont font = painter.font();
  font.setPointSizeF(9.0);
  painter.setFont(font);
  painter.drawText(QRectF(leftPx.x(), leftPx.y() - 24.0, lengthPx, 16.0), Qt::AlignHCenter,
                   QStringLiteral("%1 mm").arg(QLocale().toString(lengthMm, 'g', 6)));
  painter.restore();
}

}  // namespace fivebar::paint
