// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/job_layer.hpp"

#include <QPen>
#include <cmath>

#include "paint/studio_palette.hpp"

namespace fivebar::widgets {
namespace {

constexpr double kFadedJobOpacity = 0.25;

bool samePlacement(const Placement& a, const Placement& b) {
  return a.centerMm == b.centerMm && a.rotationRad == b.rotationRad && a.scale == b.scale &&
         a.stretchY == b.stretchY;
}

// machineFromWork = T(c) R(r) S(s, s k) T(-workCenter).
QTransform machineFromCentred(const Placement& p) {
  QTransform t;
  t.translate(p.centerMm.x(), p.centerMm.y());
  t.rotateRadians(p.rotationRad);
  t.scale(p.scale, p.scale * p.stretchY);
  return t;
}

}  // namespace

QTransform placementDelta(const Placement& from, const Placement& to) {
  // QTransform composes row-vector style: (A * B) maps by A first, then B.
  return machineFromCentred(from).inverted() * machineFromCentred(to);
}

JobLayer::JobLayer(const StudioDocument& doc, const PreviewController& preview,
                   const SimulationController& sim, QObject* parent)
    : QObject(parent), doc_(doc), preview_(preview), sim_(sim) {
  connect(&preview_, &PreviewController::resultChanged, this, &JobLayer::changed);
  connect(&preview_, &PreviewController::planningStarted, this, &JobLayer::changed);
  connect(&preview_, &PreviewController::scrubLimitChanged, this, &JobLayer::changed);
  connect(&sim_, &SimulationController::timeChanged, this, &JobLayer::changed);
  connect(&doc_, &StudioDocument::placementChanged, this, &JobLayer::changed);
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  connect(&settle_, &QTimer::timeout, this, [this] {
    settling_ = true;
    emit changed();
  });
}

void JobLayer::setColourBySpeed(bool on) {
  colourBySpeed_ = on;
  emit changed();
}

void JobLayer::setShowTravel(bool on) {
  showTravel_ = on;
  emit changed();
}

void JobLayer::setMarker(std::optional<QPointF> machineMm) {
  marker_ = machineMm;
  emit changed();
}

bool JobLayer::simulationActive() const {
  return sim_.trajectory() != nullptr && (sim_.playing() || sim_.timeS() > 0.0);
}

quint64 JobLayer::optionsKey() const {
  return (colourBySpeed_ ? 1u : 0u) | (showTravel_ ? 2u : 0u);
}

void JobLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  const PreviewResult& r = preview_.result();
  // While a plan is on its way, the last result is not the document's: show its drawing moved to
  // the current placement, unflagged and faded, with "Planning..." (no old numbers, no red).
  const bool planning = preview_.busy() && doc_.hasDrawing();
  const bool fresh = !planning && samePlacement(preview_.resultPlacement(), doc_.placement());
  ScenePaintOptions o;
  o.colourBySpeed = colourBySpeed_;
  o.showTravel = showTravel_;
  if (fresh && r.jobScene && simulationActive()) {
    o.opacity = kFadedJobOpacity;
    mainRenderer_.paint(painter, view, r.jobScene, o, optionsKey() | 16u);
    ScenePaintOptions trace = o;
    trace.opacity = 1.0;
    trace.colourBySpeed = false;
    trace.drawColour = paint::palette::trace();
    trace.penWidthPx = 1.5;
    trace.orderLimit = sim_.completedMoves();
    traceRenderer_.paint(painter, view, r.jobScene, trace, optionsKey() | 32u);
  } else if (fresh && r.jobScene) {
    o.orderLimit = preview_.scrubLimit();
    mainRenderer_.setQuickZoom(!settling_);
    mainRenderer_.paint(painter, view, r.jobScene, o, optionsKey());
    settling_ = false;
    if (mainRenderer_.stale()) settle_.start();
  } else if (r.drawingScene || r.jobScene) {
    // The drawing as last planned: its scene, or for a planned job the job's draw moves.
    const std::shared_ptr<const PathScene>& scene = r.drawingScene ? r.drawingScene : r.jobScene;
    if (!r.drawingScene) {
      o.showTravel = false;
      o.colourBySpeed = false;
    }
    o.machineFromScene = placementDelta(preview_.resultPlacement(), doc_.placement());
    if (planning) {
      o.opacity = kFadedJobOpacity;
      o.showFlags = false;
    }
    // Any change of the delta must re-render: fold it into the key.
    const quint64 deltaKey = std::hash<double>{}(o.machineFromScene.m11() * 7.0 +
                                                 o.machineFromScene.dx() * 13.0 +
                                                 o.machineFromScene.dy() * 17.0 +
                                                 o.machineFromScene.m12() * 19.0);
    mainRenderer_.paint(painter, view, scene, o,
                        (deltaKey << 9) | 64u | (planning ? 128u : 0u) | (r.drawingScene ? 0u : 256u));
  }
  if (planning) {
    painter.save();
    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 1.4);
    font.setBold(true);
    painter.setFont(font);
    painter.setPen(paint::palette::trace());
    const QRectF area(0, 0, painter.device()->width(), 48);
    painter.drawText(area, Qt::AlignCenter, tr("Planning..."));
    painter.restore();
  }
  if (marker_) {
    const QPointF c = view.widgetFromMachine(*marker_);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(paint::palette::problem(), 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(c, 12.0, 12.0);
    painter.drawLine(c - QPointF(18, 0), c - QPointF(6, 0));
    painter.drawLine(c + QPointF(6, 0), c + QPointF(18, 0));
    painter.drawLine(c - QPointF(0, 18), c - QPointF(0, 6));
    painter.drawLine(c + QPointF(0, 6), c + QPointF(0, 18));
    painter.restore();
  }
}

}  // namespace fivebar::widgets
