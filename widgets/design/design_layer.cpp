// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/design/design_layer.hpp"

#include "paint/machine_painter.hpp"
#include "paint/studio_palette.hpp"
#include "paint/workspace_painter.hpp"

namespace fivebar::widgets {

void DesignLayer::show(const design::Design& d, paint::DesignMaps maps) {
  design_ = d;
  maps_ = std::move(maps);
}

void DesignLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  if (!design_) return;
  painter.save();
  paint::paintGrid(painter, view);  // covers the current machine's layers
  paint::paintDesignOverlay(painter, view.widgetFromMachine(), *design_, maps_, kind_);
  const QSizeF size = view.viewportPx();
  double y = 12.0;
  const QStringList lines = paint::designMeasureLines(*design_);
  QFont font = painter.font();
  font.setPointSizeF(9.0);
  painter.setFont(font);
  const double cardH = 10.0 + 18.0 * lines.size();
  painter.setPen(QPen(paint::palette::gridMajor(), 1.0));
  painter.setBrush(QColor(255, 255, 255, 230));
  painter.drawRoundedRect(QRectF(12.0, y, size.width() - 24.0, cardH), 6, 6);
  painter.setPen(paint::palette::machineBase());
  for (const QString& line : lines) {
    painter.drawText(QRectF(22.0, y + 5.0, size.width() - 44.0, 18.0), Qt::AlignVCenter | Qt::AlignLeft, line);
    y += 18.0;
  }
  if (kind_ != paint::MapKind::None)
    paint::paintColourBar(painter, QRectF(12.0, size.height() - 70.0, std::min(520.0, size.width() - 24.0), 58.0),
                   paint::mapScale(maps_.map, kind_));
  else
    paint::paintScaleBar(painter, view.widgetFromMachine(), QPointF(24.0, size.height() - 24.0));
  painter.restore();
}

}  // namespace fivebar::widgets
