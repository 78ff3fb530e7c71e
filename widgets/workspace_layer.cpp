#include "widgets/workspace_layer.hpp"

namespace fivebar::widgets {
namespace {
constexpr double kLegendInsetPx = 12.0;
constexpr double kColourBarWidthPx = 260.0;
constexpr double kColourBarHeightPx = 58.0;
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

void WorkspaceLayer::paint(QPainter& painter, const ViewTransform& view) {
  const auto set = cache_.current();
  if (!set) return;
  const WorkingMode mode = doc_.effectiveMode();
  const WorkspaceMap& map = set->map(mode);
  const WorkspaceAnalysis& analysis = set->analysis(mode);
  const QTransform t = view.widgetFromMachine();
  if (overlays_.map != MapKind::None) {
    if (imageSet_ != set.get() || imageMode_ != mode || imageKind_ != overlays_.map) {
      imageScale_ = mapScale(map, overlays_.map);
      image_ = mapImage(map, overlays_.map, imageScale_);
      imageSet_ = set.get();
      imageMode_ = mode;
      imageKind_ = overlays_.map;
    }
    paintMapImage(painter, t, map, image_);
  }
  WorkspacePaintOptions options;
  options.fillRegions = overlays_.regions && overlays_.map == MapKind::None;
  options.drawBoundaries = overlays_.regions;
  options.drawTypeII = overlays_.typeII;
  options.drawRectangle = overlays_.rectangle;
  paintWorkspace(painter, t, map, analysis, options);
  if (!overlays_.legend) return;
  const QSizeF vp = view.viewportPx();
  paintWorkspaceLegend(painter, QPointF(kLegendInsetPx + 28.0, kLegendInsetPx + 14.0), map,
                       analysis);
  paintScaleBar(painter, t, QPointF(vp.width() - 150.0, vp.height() - 18.0));
  if (overlays_.map != MapKind::None) {
    paintColourBar(painter,
                   QRectF(kLegendInsetPx, vp.height() - kColourBarHeightPx - kLegendInsetPx,
                          kColourBarWidthPx, kColourBarHeightPx),
                   imageScale_);
  }
}

}  // namespace fivebar::widgets
