// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/placement_tool.hpp"

#include <QLineF>
#include <QPen>
#include <QPolygonF>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "paint/studio_palette.hpp"

namespace fivebar::widgets {
namespace {
constexpr double kMinScale = 1e-3;
QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }
}  // namespace

PlacementTool::PlacementTool(StudioDocument& doc, QObject* parent) : QObject(parent), doc_(doc) {
  connect(&doc_, &StudioDocument::drawingChanged, this, &PlacementTool::refreshBounds);
  connect(&doc_, &StudioDocument::layersChanged, this, &PlacementTool::refreshBounds);
  refreshBounds();
}

void PlacementTool::refreshBounds() { workBounds_ = drawingBounds(doc_.drawing()); }

std::optional<std::array<QPointF, 4>> PlacementTool::cornersMm() const {
  if (!workBounds_) return std::nullopt;
  const Placement& p = doc_.placement();
  const RectMm& b = *workBounds_;
  const Vec2 c = b.center();
  const double cs = std::cos(p.rotationRad), sn = std::sin(p.rotationRad);
  const auto map = [&](double x, double y) {
    const double u = (x - c.x()) * p.scale, v = (y - c.y()) * p.scale * p.stretchY;
    return toQ(p.centerMm + Vec2(cs * u - sn * v, sn * u + cs * v));
  };
  return std::array<QPointF, 4>{map(b.x0, b.y0), map(b.x1, b.y0), map(b.x1, b.y1),
                                map(b.x0, b.y1)};
}

QPointF PlacementTool::rotateHandlePx(const paint::ViewTransform& view) const {
  const auto corners = cornersMm();
  const QPointF top = (view.widgetFromMachine((*corners)[2]) +
                       view.widgetFromMachine((*corners)[3])) / 2.0;
  const QPointF centre = view.widgetFromMachine(toQ(doc_.placement().centerMm));
  QLineF outward(centre, top);
  if (outward.length() < 1e-9) return top;
  outward.setLength(outward.length() + kRotateHandleOffsetPx);
  return outward.p2();
}

PlacementTool::Handle PlacementTool::handleAt(QPointF px, const paint::ViewTransform& view) const {
  const auto corners = cornersMm();
  if (!corners) return Handle::None;
  const double grab = kHandleRadiusPx + 3.0;
  if (QLineF(px, rotateHandlePx(view)).length() <= grab) return Handle::Rotate;
  QPolygonF box;
  for (const QPointF& c : *corners) {
    const QPointF w = view.widgetFromMachine(c);
    if (QLineF(px, w).length() <= grab) return Handle::Corner;
    box << w;
  }
  return box.containsPoint(px, Qt::OddEvenFill) ? Handle::Body : Handle::None;
}

bool PlacementTool::mousePress(QMouseEvent* event, const paint::ViewTransform& view) {
  if (event->button() != Qt::LeftButton) return false;
  active_ = handleAt(event->position(), view);
  if (active_ == Handle::None) return false;
  gesture_ = doc_.beginGesture();
  start_ = doc_.placement();
  startMm_ = view.machineFromWidget(event->position());
  return true;
}

bool PlacementTool::mouseMove(QMouseEvent* event, const paint::ViewTransform& view) {
  if (active_ == Handle::None) return false;
  const QPointF m = view.machineFromWidget(event->position());
  const QPointF c = toQ(start_.centerMm);
  Placement p = start_;
  switch (active_) {
    case Handle::Body:
      p.centerMm = start_.centerMm + Vec2(m.x() - startMm_.x(), m.y() - startMm_.y());
      break;
    case Handle::Corner: {
      const double d0 = QLineF(c, startMm_).length();
      if (d0 < 1e-9) return false;
      p.scale = std::max(kMinScale, start_.scale * QLineF(c, m).length() / d0);
      break;
    }
    case Handle::Rotate: {
      const double a0 = std::atan2(startMm_.y() - c.y(), startMm_.x() - c.x());
      const double a1 = std::atan2(m.y() - c.y(), m.x() - c.x());
      double deg = degFromRad(start_.rotationRad + (a1 - a0));
      if (event->modifiers() & Qt::ShiftModifier) deg = std::round(deg / kSnapDeg) * kSnapDeg;
      p.rotationRad = radFromDeg(normalizeDeg(deg));
      break;
    }
    case Handle::None: break;
  }
  doc_.setPlacement(p, gesture_);
  return true;
}

bool PlacementTool::mouseRelease(QMouseEvent* event, const paint::ViewTransform&) {
  if (event->button() != Qt::LeftButton || active_ == Handle::None) return false;
  active_ = Handle::None;
  gesture_ = 0;
  return true;
}

void PlacementTool::paintOverlay(QPainter& painter, const paint::ViewTransform& view) {
  const auto corners = cornersMm();
  if (!corners) return;
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  QPolygonF box;
  for (const QPointF& c : *corners) box << view.widgetFromMachine(c);
  painter.setPen(QPen(paint::palette::selection(), 1.2, Qt::DashLine));
  painter.setBrush(Qt::NoBrush);
  painter.drawPolygon(box);
  const QPointF top = (box[2] + box[3]) / 2.0;
  const QPointF handle = rotateHandlePx(view);
  painter.setPen(QPen(paint::palette::selection(), 1.2));
  painter.drawLine(top, handle);
  painter.setBrush(Qt::white);
  painter.setPen(QPen(paint::palette::selection(), 2.0));
  for (const QPointF& w : box) {
    painter.drawRect(QRectF(w - QPointF(kHandleRadiusPx, kHandleRadiusPx),
                            QSizeF(2 * kHandleRadiusPx, 2 * kHandleRadiusPx)));
  }
  painter.drawEllipse(handle, kHandleRadiusPx, kHandleRadiusPx);
  painter.restore();
}

QCursor PlacementTool::cursorAt(QPointF px, const paint::ViewTransform& view) const {
  switch (active_ != Handle::None ? active_ : handleAt(px, view)) {
    case Handle::Body: return Qt::SizeAllCursor;
    case Handle::Corner: return Qt::SizeFDiagCursor;
    case Handle::Rotate: return Qt::PointingHandCursor;
    case Handle::None: break;
  }
  return Qt::ArrowCursor;
}

}  // namespace fivebar::widgets
