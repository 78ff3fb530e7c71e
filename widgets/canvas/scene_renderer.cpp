// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/scene_renderer.hpp"

#include <cmath>

namespace fivebar::widgets {
namespace {
// The cached image extends this share of the viewport beyond each edge.
constexpr double kMarginShare = 0.5;
}  // namespace

bool SceneRenderer::covers(const paint::ViewTransform& view) const {
  if (image_.isNull() || view.pxPerMm() != imageView_.pxPerMm()) return false;
  return imageView_.visibleMachineRect().contains(view.visibleMachineRect());
}

void SceneRenderer::renderFull(const paint::ViewTransform& view, const ScenePaintOptions& options) {
  const QSizeF vp = view.viewportPx();
  // A new zoom renders just the viewport (zoom steps come in bursts); a pan at an unchanged zoom
  // renders the margins too, so the following pan frames are blits.
  const bool sameZoom = !image_.isNull() && view.pxPerMm() == imageView_.pxPerMm();
  const double marginShare = sameZoom ? kMarginShare : 0.0;
  // Whole-pixel margins keep the image's pixel grid aligned with the viewport's, so a pan by
  // whole pixels blits without resampling.
  const int marginX = static_cast<int>(std::ceil(vp.width() * marginShare));
  const int marginY = static_cast<int>(std::ceil(vp.height() * marginShare));
  const QSize size(static_cast<int>(std::ceil(vp.width())) + 2 * marginX,
                   static_cast<int>(std::ceil(vp.height())) + 2 * marginY);
  imageView_ = paint::ViewTransform(view.centerMm(), view.pxPerMm(), QSizeF(size));
  if (image_.size() != size) image_ = QImage(size, QImage::Format_ARGB32_Premultiplied);
  image_.fill(Qt::transparent);
  QPainter p(&image_);
  ScenePaintOptions o = options;
  o.opacity = 1.0;  // applied when blitting, so incremental additions match
  scene_->paint(p, imageView_, o);
  ++fullRenders_;
}

void SceneRenderer::paint(QPainter& painter, const paint::ViewTransform& view,
                          const std::shared_ptr<const PathScene>& scene,
                          const ScenePaintOptions& options, quint64 optionsKey) {
  if (!scene || scene->empty()) return;
  const bool onlyZoomed = quickZoom_ && !image_.isNull() && scene == scene_ &&
                          optionsKey == optionsKey_ && options.orderBegin == orderBegin_ &&
                          options.orderLimit == orderLimit_ &&
                          view.pxPerMm() != imageView_.pxPerMm();
  if (onlyZoomed) {
    // Image pixel -> machine (image view) -> widget (current view): a scale and an offset.
    const double r = view.pxPerMm() / imageView_.pxPerMm();
    const QPointF origin = view.widgetFromMachine(imageView_.machineFromWidget(QPointF(0, 0)));
    painter.save();
    painter.setOpacity(painter.opacity() * options.opacity);
    painter.setTransform(QTransform(r, 0.0, 0.0, r, origin.x(), origin.y()), true);
    painter.drawImage(QPointF(0, 0), image_);
    painter.restore();
    stale_ = true;
    ++previewFrames_;
    return;
  }
  stale_ = false;
  const bool sameBase = scene == scene_ && optionsKey == optionsKey_ &&
                        options.orderBegin == orderBegin_ && covers(view);
  const bool grows = sameBase && orderLimit_ >= 0 &&
                     (options.orderLimit < 0 || options.orderLimit >= orderLimit_);
  if (sameBase && options.orderLimit == orderLimit_) {
    // Pure pan: reuse as is.
  } else if (grows) {
    QPainter p(&image_);
    ScenePaintOptions o = options;
    o.opacity = 1.0;
    o.orderBegin = orderLimit_;
    scene->paint(p, imageView_, o);
    ++incrementalRenders_;
  } else {
    scene_ = scene;
    optionsKey_ = optionsKey;
    orderBegin_ = options.orderBegin;
    renderFull(view, options);
  }
  orderLimit_ = options.orderLimit;
  opacity_ = options.opacity;
  // Blit the visible part: the image's view centre sits at this widget position.
  const QPointF centerPx = view.widgetFromMachine(imageView_.centerMm());
  const QPointF topLeft = centerPx - QPointF(image_.width() / 2.0, image_.height() / 2.0);
  const QRectF target(QPointF(0, 0), view.viewportPx());
  const QRectF source = target.translated(-topLeft);
  painter.save();
  painter.setOpacity(painter.opacity() * opacity_);
  painter.drawImage(target, image_, source);
  painter.restore();
}

}  // namespace fivebar::widgets
