// SPDX-License-Identifier: GPL-3.0-or-later
#include "paint/view_transform.hpp"

#include <algorithm>

namespace fivebar::paint {

ViewTransform::ViewTransform(QPointF centerMm, double pxPerMm, QSizeF viewportPx)
    : centerMm_(centerMm),
      pxPerMm_(std::clamp(pxPerMm, kMinPxPerMm, kMaxPxPerMm)),
      viewportPx_(viewportPx) {}

QTransform ViewTransform::widgetFromMachine() const {
  // x_px = cx + s (x - cx_mm), y_px = cy - s (y - cy_mm): the y flip of the view.
  const double cx = 0.5 * viewportPx_.width();
  const double cy = 0.5 * viewportPx_.height();
  return QTransform(pxPerMm_, 0.0, 0.0, -pxPerMm_, cx - pxPerMm_ * centerMm_.x(),
                    cy + pxPerMm_ * centerMm_.y());
}

QPointF ViewTransform::widgetFromMachine(QPointF machineMm) const {
  return widgetFromMachine().map(machineMm);
}

QPointF ViewTransform::machineFromWidget(QPointF widgetPx) const {
  const double cx = 0.5 * viewportPx_.width();
  const double cy = 0.5 * viewportPx_.height();
  return {centerMm_.x() + (widgetPx.x() - cx) / pxPerMm_,
          centerMm_.y() - (widgetPx.y() - cy) / pxPerMm_};
}

QRectF ViewTransform::visibleMachineRect() const {
  const QPointF a = machineFromWidget({0.0, viewportPx_.height()});
  const QPointF b = machineFromWidget({viewportPx_.width(), 0.0});
  return QRectF(a, b).normalized();
}

void ViewTransform::zoomAround(QPointF anchorPx, double factor) {
  const QPointF anchorMm = machineFromWidget(anchorPx);
  pxPerMm_ = std::clamp(pxPerMm_ * factor, kMinPxPerMm, kMaxPxPerMm);
  // Solve for the centre that maps anchorMm back onto anchorPx.
  const double cx = 0.5 * viewportPx_.width();
  const double cy = 0.5 * viewportPx_.height();
  centerMm_ = {anchorMm.x() - (anchorPx.x() - cx) / pxPerMm_,
               anchorMm.y() + (anchorPx.y() - cy) / pxPerMm_};
}

void ViewTransform::panByPx(QPointF deltaPx) {
  centerMm_ += QPointF(-deltaPx.x() / pxPerMm_, deltaPx.y() / pxPerMm_);
}

void ViewTransform::fit(const QRectF& machineRectMm, double marginPx) {
  if (!machineRectMm.isValid() || machineRectMm.isEmpty()) return;
  const double w = std::max(1.0, viewportPx_.width() - 2.0 * marginPx);
  const double h = std::max(1.0, viewportPx_.height() - 2.0 * marginPx);
  pxPerMm_ = std::clamp(std::min(w / machineRectMm.width(), h / machineRectMm.height()),
                        kMinPxPerMm, kMaxPxPerMm);
  centerMm_ = machineRectMm.center();
}

}  // namespace fivebar::paint
