// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/workspace_layer.hpp"

#include <cmath>

namespace fivebar::widgets {
namespace {
constexpr double kLegendInsetPx = 12.0;
constexpr double kColourBarWidthPx = 260.0;
constexpr double kColourBarHeightPx = 58.0;
constexpr QSize kLegendCanvasPx(900, 600);

// The legend painted alone and cropped to its card: paintWorkspaceLegend reports only the
// height, and the legend is placed by its right edge.
QImage legendImageOf(const WorkspaceMap& map, const WorkspaceAnalysis& analysis, const QFont& font) {
  QImage image(kLegendCanvasPx, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  double height = 0.0;
  {
    QPainter p(&image);
    p.setFont(font);
    height = paint::paintWorkspaceLegend(p, QPointF(1.0, 1.0), map, analysis);
  }
  int right = 0;
  const int rows = std::min(image.height(), static_cast<int>(std::ceil(height)) + 3);
  for (int y = 0; y < rows; ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = image.width() - 1; x > right; --x) {
      if (qAlpha(line[x]) != 0) {
        right = x;
        break;
      }
    }
  }
  return image.copy(0, 0, right + 2, rows);
}

}  // namespace

WorkspaceLayer::WorkspaceLayer(const StudioDocument& doc, const WorkspaceCache& cache,
                               QObject* parent)
    : QObject(parent), doc_(doc), cache_(cache) {
  connect(&cache_, &WorkspaceCache::ready, this, &WorkspaceLayer::changed);
  connect(&doc_, &StudioDocument::effectiveModeChanged, this, &WorkspaceLayer::changed);
}

void WorkspaceLayer::setOverlays(const WorkspaceOverlays& overlays) {
  overlays_ = overlays;
  emit changed();
}

void WorkspaceLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  const auto set = cache_.current();
  if (!set) return;
  const WorkingMode mode = doc_.effectiveMode();
  const WorkspaceMap& map = set->map(mode);
  const WorkspaceAnalysis& analysis = set->analysis(mode);
  const QTransform t = view.widgetFromMachine();
  if (overlays_.map != paint::MapKind::None) {
    if (imageSet_ != set.get() || imageMode_ != mode || imageKind_ != overlays_.map) {
      imageScale_ = paint::mapScale(map, overlays_.map);
      image_ = paint::mapImage(map, overlays_.map, imageScale_);
      imageSet_ = set.get();
      imageMode_ = mode;
      imageKind_ = overlays_.map;
    }
    paint::paintMapImage(painter, t, map, image_);
  }
  paint::WorkspacePaintOptions options;
  options.fillRegions = overlays_.regions && overlays_.map == paint::MapKind::None;
  options.drawBoundaries = overlays_.regions;
  options.drawTypeII = overlays_.typeII;
  options.drawRectangle = overlays_.rectangle;
  paint::paintWorkspace(painter, t, map, analysis, options);
}

void WorkspaceLayer::paintLegends(QPainter& painter, const paint::ViewTransform& view) {
  const auto set = cache_.current();
  if (!set) return;
  const WorkingMode mode = doc_.effectiveMode();
  const WorkspaceMap& map = set->map(mode);
  const WorkspaceAnalysis& analysis = set->analysis(mode);
  const QSizeF vp = view.viewportPx();
  if (overlays_.legend && (legendSet_ != set.get() || legendMode_ != mode || legendImage_.isNull())) {
    legendImage_ = legendImageOf(map, analysis, painter.font());
    legendSet_ = set.get();
    legendMode_ = mode;
  }
  if (overlays_.legend) {
    painter.drawImage(QPointF(vp.width() - legendImage_.width() - kLegendInsetPx,
                              kLegendInsetPx + 16.0),
                      legendImage_);
  }
  paint::paintScaleBar(painter, view.widgetFromMachine(), QPointF(vp.width() - 150.0, vp.height() - 18.0));
  if (overlays_.map != paint::MapKind::None) {
    paint::paintColourBar(painter,
                   QRectF(vp.width() - kColourBarWidthPx - kLegendInsetPx,
                          vp.height() - kColourBarHeightPx - 44.0, kColourBarWidthPx,
                          kColourBarHeightPx),
                   imageScale_);
  }
}

}  // namespace fivebar::widgets
