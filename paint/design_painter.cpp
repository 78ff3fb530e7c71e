// SPDX-License-Identifier: GPL-3.0-or-later
#include "paint/design_painter.hpp"

#include <QCoreApplication>
#include <QLocale>
#include <QPainterPath>
#include <cmath>

#include "core/kinematics/kinematics.hpp"
#include "paint/machine_painter.hpp"
#include "paint/studio_palette.hpp"
#include "paint/view_transform.hpp"
#include "paint/workspace_painter.hpp"

namespace fivebar::paint {
namespace {

QString trD(const char* text) { return QCoreApplication::translate("DesignPainter", text); }

constexpr double kHeaderPx = 145.0;
constexpr double kPanelTitlePx = 30.0;
constexpr double kColourBarPx = 64.0;

std::optional<Pose> centrePose(const design::Design& d) {
  const Vec2 c(0.5 * (d.rect.xMin + d.rect.xMax), 0.5 * (d.rect.yMin + d.rect.yMax));
  const IkResult ik = inverse(d.geometry, c, d.mode);
  if (!ik.ok()) return std::nullopt;
  return makePose(d.geometry, ik.angles, c);
}

QString mm(double v) { return QLocale().toString(v, 'f', 1); }

}  // namespace

DesignMaps computeDesignMaps(const design::Design& d, const design::DesignRules& rules,
                             int cellsOnLongSide, int threads) {
  DesignMaps out;
  const GridSpec grid = gridCovering(d.geometry, cellsOnLongSide);
  out.map = computeMap(d.geometry, rules.workspace, d.mode, grid, threads);
  out.analysis = analyse(out.map, d.geometry, rules.workspace);
  out.analysis.largestRectangle.reset();  // the design's own rectangle is drawn instead
  return out;
}

QRectF designBoxMm(const design::Design& d, const DesignMaps& maps) {
  const Geometry& g = d.geometry;
  QRectF box(QPointF(-0.5 * g.w, -0.05 * (g.a1 + g.a2)), QPointF(0.5 * g.w, 0.0));
  box = box.united(QRectF(QPointF(d.rect.xMin, d.rect.yMin), QPointF(d.rect.xMax, d.rect.yMax)));
  box = box.united(QRectF(QPointF(d.evaluation.measures.footprint.xMin, d.evaluation.measures.footprint.yMin),
                          QPointF(d.evaluation.measures.footprint.xMax, d.evaluation.measures.footprint.yMax)));
  const GridSpec& grid = maps.map.grid;
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix)
      if (maps.map.reachable[grid.index(ix, iy)])
        box = box.united(QRectF(grid.x0 + ix * grid.cellMm, grid.y0 + iy * grid.cellMm, grid.cellMm, grid.cellMm));
  return box.normalized();
}

void paintDesignOverlay(QPainter& painter, const QTransform& widgetFromMachine,
                        const design::Design& d, const DesignMaps& maps, MapKind kind) {
  painter.save();
  WorkspacePaintOptions options;
  options.fillRegions = kind == MapKind::None;
  options.drawRectangle = false;
  if (kind != MapKind::None) {
    const MapScale scale = mapScale(maps.map, kind);
    paintMapImage(painter, widgetFromMachine, maps.map, mapImage(maps.map, kind, scale, 170));
  }
  paintWorkspace(painter, widgetFromMachine, maps.map, maps.analysis, options);
  // The placed rectangle, its size written above it.
  const QPolygonF r = widgetFromMachine.map(QPolygonF(QRectF(QPointF(d.rect.xMin, d.rect.yMin),
                                                             QPointF(d.rect.xMax, d.rect.yMax))));
  QPen pen(palette::selection(), 2.5);
  painter.setPen(pen);
  painter.setBrush(QColor(245, 158, 11, 40));
  painter.drawPolygon(r);
  QFont font = painter.font();
  font.setPointSizeF(9.0);
  font.setBold(true);
  painter.setFont(font);
  painter.setPen(palette::machineBase());
  const QRectF rb = r.boundingRect();
  painter.drawText(QRectF(rb.left(), rb.top() - 20.0, rb.width(), 18.0), Qt::AlignCenter,
                   QStringLiteral("%1 x %2 mm").arg(mm(d.rect.width()), mm(d.rect.height())));
  if (const auto pose = centrePose(d)) paintMachine(painter, widgetFromMachine, d.geometry, *pose, 0.8);
  painter.restore();
}

void paintDesignPanel(QPainter& painter, const QRectF& panelPx, const design::Design& d,
                      const DesignMaps& maps, MapKind kind) {
  painter.save();
  painter.setClipRect(panelPx);
  painter.translate(panelPx.topLeft());
  const QSizeF size = panelPx.size();
  const double plotTop = kPanelTitlePx, plotBottom = size.height() - kColourBarPx;
  ViewTransform view(QPointF(0, 0), 1.0, size);
  // Fit the box into the plot band between the title and the colour bar.
  const QRectF box = designBoxMm(d, maps);
  const double s = std::min((size.width() - 40.0) / box.width(), (plotBottom - plotTop - 30.0) / box.height());
  const QPointF shiftPx(0.0, 0.5 * size.height() - 0.5 * (plotTop + plotBottom));
  view = ViewTransform(box.center() + QPointF(shiftPx.x() / s, -shiftPx.y() / s), s, size);
  paintGrid(painter, view);
  paintDesignOverlay(painter, view.widgetFromMachine(), d, maps, kind);
  QString title = trD(QT_TRANSLATE_NOOP("DesignPainter", "Workspace, singularity-free region and type II curves"));
  if (kind != MapKind::None) {
    const MapScale scale = mapScale(maps.map, kind);
    title = scale.title;
    paintColourBar(painter, QRectF(20.0, plotBottom + 4.0, size.width() - 40.0, kColourBarPx - 10.0), scale);
  } else {
    paintScaleBar(painter, view.widgetFromMachine(), QPointF(24.0, size.height() - 24.0));
  }
  painter.fillRect(QRectF(0, 0, size.width(), kPanelTitlePx), QColor(255, 255, 255, 235));
  QFont font = painter.font();
  font.setPointSizeF(11.0);
  font.setBold(true);
  painter.setFont(font);
  painter.setPen(palette::machineBase());
  painter.drawText(QRectF(12, 0, size.width() - 24, kPanelTitlePx), Qt::AlignVCenter | Qt::AlignLeft, title);
  painter.setClipping(false);
  painter.setPen(QPen(palette::gridMajor(), 1.0));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(QRectF(QPointF(0.5, 0.5), size - QSizeF(1, 1)));
  painter.restore();
}

QStringList designMeasureLines(const design::Design& d) {
  const design::DesignMeasures& m = d.evaluation.measures;
  const Geometry& g = d.geometry;
  QStringList lines;
  lines << trD(QT_TRANSLATE_NOOP("DesignPainter", "a1 = %1, b1 = %2, a2 = %3, b2 = %4, w = %5 mm, working mode %6"))
               .arg(mm(g.a1), mm(g.b1), mm(g.a2), mm(g.b2), mm(g.w), QString::fromUtf8(toString(d.mode).data(), 2));
  lines << trD(QT_TRANSLATE_NOOP("DesignPainter", "Rectangle x %1 .. %2, y %3 .. %4 mm; worst condition number %5 (mean %6)"))
               .arg(mm(d.rect.xMin), mm(d.rect.xMax), mm(d.rect.yMin), mm(d.rect.yMax))
               .arg(QLocale().toString(m.worstCondition, 'f', 2))
               .arg(QLocale().toString(m.meanCondition, 'f', 2));
  lines << trD(QT_TRANSLATE_NOOP("DesignPainter", "Type II margin %1 deg, type I margin %2 deg, footprint %3 cm\u00b2"))
               .arg(QLocale().toString(degFromRad(m.minTypeIIMarginRad), 'f', 1))
               .arg(QLocale().toString(degFromRad(m.minTypeIMarginRad), 'f', 1))
               .arg(QLocale().toString(m.footprintMm2 / 100.0, 'f', 0));
  lines << trD(QT_TRANSLATE_NOOP("DesignPainter", "Worst %1 um per step, worst motor speed %2 deg/s"))
               .arg(QLocale().toString(m.worstMmPerStep * 1000.0, 'f', 1))
               .arg(QLocale().toString(degFromRad(m.worstMotorSpeedRadPerS), 'f', 0));
  return lines;
}

QImage designAtlas(const design::Design& d, const DesignMaps& maps, const QString& title, QSize sizePx) {
  QImage image(sizePx, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setRenderHint(QPainter::TextAntialiasing, true);
  QFont font = painter.font();
  font.setPointSizeF(15.0);
  font.setBold(true);
  painter.setFont(font);
  painter.setPen(palette::machineBase());
  painter.drawText(QRectF(20, 8, sizePx.width() - 40, 36), Qt::AlignVCenter | Qt::AlignLeft, title);
  font.setPointSizeF(10.5);
  font.setBold(false);
  painter.setFont(font);
  const QStringList lines = designMeasureLines(d);
  for (int i = 0; i < lines.size(); ++i)
    painter.drawText(QRectF(20, 46 + 22 * i, sizePx.width() - 40, 22), Qt::AlignVCenter | Qt::AlignLeft, lines[i]);
  const double w = 0.5 * (sizePx.width() - 30.0), h = 0.5 * (sizePx.height() - kHeaderPx - 30.0);
  const MapKind kinds[4] = {MapKind::None, MapKind::Conditioning, MapKind::Transmission, MapKind::Resolution};
  for (int k = 0; k < 4; ++k) {
    const QRectF panel(10.0 + (k % 2) * (w + 10.0), kHeaderPx + 10.0 + (k / 2) * (h + 10.0), w, h);
    paintDesignPanel(painter, panel, d, maps, kinds[k]);
  }
  return image;
}

}  // namespace fivebar::paint
