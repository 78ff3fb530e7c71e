// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas layer of the chosen working mode's workspace: the reachable and singularity-free
// regions with the margin band, type II curves, the largest rectangle (paintWorkspace), an
// optional scalar map (transmission angle, conditioning, resolution) with its colour bar, the
// legend and a scale bar. It only draws the cached analysis; the switches are view state.
#pragma once

#include <QImage>
#include <QObject>

#include "widgets/canvas/canvas_layer.hpp"
#include "paint/map_painter.hpp"
#include "widgets/canvas/workspace_cache.hpp"
#include "paint/workspace_painter.hpp"

namespace fivebar::widgets {

struct WorkspaceOverlays {
  bool regions = true;     // reachable / singularity-free regions and the margin band
  bool typeII = true;      // type II singularity curves
  bool rectangle = true;   // largest singularity-free rectangle
  bool legend = false;     // the workspace legend card (the map's colour bar is always shown)
  paint::MapKind map = paint::MapKind::None;
};

class WorkspaceLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  WorkspaceLayer(const StudioDocument& doc, const WorkspaceCache& cache,
                 QObject* parent = nullptr);

  // Regions, curves, rectangle and map (legends excluded: see paintLegends).
  void paint(QPainter& painter, const paint::ViewTransform& view) override;
  // The legend (top right), the map's colour bar and the scale bar (bottom right); painted by a
  // WorkspaceLegendLayer above every other layer so nothing hides them.
  void paintLegends(QPainter& painter, const paint::ViewTransform& view);
  const WorkspaceOverlays& overlays() const { return overlays_; }

 public slots:
  void setOverlays(const WorkspaceOverlays& overlays);

 signals:
  void changed();

 private:
  const StudioDocument& doc_;
  const WorkspaceCache& cache_;
  WorkspaceOverlays overlays_;
  // Cached map image: valid for this set, mode and kind.
  const WorkspaceSet* imageSet_ = nullptr;
  WorkingMode imageMode_ = WorkingMode::PlusPlus;
  paint::MapKind imageKind_ = paint::MapKind::None;
  QImage image_;
  paint::MapScale imageScale_;
  // Cached legend card: valid for this set and mode.
  const WorkspaceSet* legendSet_ = nullptr;
  WorkingMode legendMode_ = WorkingMode::PlusPlus;
  QImage legendImage_;
};

class WorkspaceLegendLayer : public CanvasLayer {
 public:
  explicit WorkspaceLegendLayer(WorkspaceLayer& layer) : layer_(layer) {}
  void paint(QPainter& painter, const paint::ViewTransform& view) override {
    layer_.paintLegends(painter, view);
  }

 private:
  WorkspaceLayer& layer_;
};

}  // namespace fivebar::widgets
