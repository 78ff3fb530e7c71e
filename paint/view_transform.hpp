// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas view: the one place where the machine frame (mm, y up) meets the widget frame
// (px, y down). widgetFromMachine() is the transform every painter takes.
#pragma once

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>

namespace fivebar::paint {

class ViewTransform {
 public:
  // Scale limits in px per mm: from a 10 m wide view on a small widget down to 5 um per pixel.
  static constexpr double kMinPxPerMm = 0.02;
  static constexpr double kMaxPxPerMm = 200.0;

  ViewTransform() = default;
  ViewTransform(QPointF centerMm, double pxPerMm, QSizeF viewportPx);

  QTransform widgetFromMachine() const;
  QPointF widgetFromMachine(QPointF machineMm) const;
  QPointF machineFromWidget(QPointF widgetPx) const;
  // The machine-frame rectangle (mm) currently visible in the viewport.
  QRectF visibleMachineRect() const;

  double pxPerMm() const { return pxPerMm_; }
  QPointF centerMm() const { return centerMm_; }
  QSizeF viewportPx() const { return viewportPx_; }

  void setViewportPx(QSizeF viewportPx) { viewportPx_ = viewportPx; }
  void setCenterMm(QPointF centerMm) { centerMm_ = centerMm; }
  // Multiplies the scale by `factor`, keeping the machine point under `anchorPx` fixed.
  void zoomAround(QPointF anchorPx, double factor);
  // Moves the view so that the content follows a drag of `deltaPx`.
  void panByPx(QPointF deltaPx);
  // Centres and scales so that `machineRectMm` fills the viewport with `marginPx` around it.
  void fit(const QRectF& machineRectMm, double marginPx);

 private:
  QPointF centerMm_{0.0, 100.0};
  double pxPerMm_ = 2.0;
  QSizeF viewportPx_{800.0, 600.0};
};

}  // namespace fivebar::paint
