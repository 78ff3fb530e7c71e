// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas layer showing the drawing and the planned job: the placed drawing (moved live while a
// placement edit waits for its new plan, offending paths in red), the planned job (pen-down
// coloured by speed or plain, pen-up in grey, up to the scrubber), or during the simulation the
// job faded with the trace drawn so far; and a marker at the selected problem.
#pragma once

#include <QObject>
#include <QTimer>
#include <optional>

#include "widgets/canvas/canvas_layer.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/canvas/scene_renderer.hpp"
#include "widgets/document/simulation_controller.hpp"

namespace fivebar::widgets {

class JobLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  JobLayer(const StudioDocument& doc, const PreviewController& preview,
           const SimulationController& sim, QObject* parent = nullptr);

  void paint(QPainter& painter, const paint::ViewTransform& view) override;

  bool colourBySpeed() const { return colourBySpeed_; }
  bool showTravel() const { return showTravel_; }

 public slots:
  void setColourBySpeed(bool on);
  void setShowTravel(bool on);
  // Marks a machine-frame point (a selected problem); nullopt clears it.
  void setMarker(std::optional<QPointF> machineMm);

 signals:
  void changed();

 private:
  bool simulationActive() const;
  quint64 optionsKey() const;

  const StudioDocument& doc_;
  const PreviewController& preview_;
  const SimulationController& sim_;
  // Quick zoom: zoom frames scale the cached job image; once the view rests for kSettleMs the
  // job is re-rendered sharp.
  static constexpr int kSettleMs = 150;
  QTimer settle_;
  bool settling_ = false;
  SceneRenderer mainRenderer_;
  SceneRenderer traceRenderer_;
  bool colourBySpeed_ = true;
  bool showTravel_ = true;
  std::optional<QPointF> marker_;
};

// machine = delta * old: the rigid change from one placement of a drawing to another (the
// drawing's centre cancels, so no pass over its points is needed).
QTransform placementDelta(const Placement& from, const Placement& to);

}  // namespace fivebar::widgets
