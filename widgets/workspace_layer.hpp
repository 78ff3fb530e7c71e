// Canvas layer of the chosen working mode's workspace: the reachable and singularity-free
// regions with the margin band, type II curves, the largest rectangle (paintWorkspace), an
// optional scalar map (transmission angle, conditioning, resolution) with its colour bar, the
// legend and a scale bar. It only draws the cached analysis; the switches are view state.
#pragma once

#include <QImage>
#include <QObject>

#include "widgets/canvas_layer.hpp"
#include "widgets/map_painter.hpp"
#include "widgets/workspace_cache.hpp"
#include "widgets/workspace_painter.hpp"

namespace fivebar::widgets {

struct WorkspaceOverlays {
  bool regions = true;     // reachable / singularity-free regions and the margin band
  bool typeII = true;      // type II singularity curves
  bool rectangle = true;   // largest singularity-free rectangle
  bool legend = true;
  MapKind map = MapKind::None;
};

class WorkspaceLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  WorkspaceLayer(const StudioDocument& doc, const WorkspaceCache& cache,
                 QObject* parent = nullptr);

  void paint(QPainter& painter, const ViewTransform& view) override;
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
  MapKind imageKind_ = MapKind::None;
  QImage image_;
  MapScale imageScale_;
};

}  // namespace fivebar::widgets
