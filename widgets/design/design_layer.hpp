// The canvas preview of a design chosen in the Design dialog: it covers the canvas with the
// design's workspace, singularity curves, placed rectangle and one measure map, plus a card
// with its lengths and measures. Paints nothing while no design is shown.
#pragma once

#include <optional>

#include "widgets/canvas/canvas_layer.hpp"
#include "widgets/design/design_painter.hpp"

namespace fivebar::widgets {

class DesignLayer : public CanvasLayer {
 public:
  void show(const design::Design& d, DesignMaps maps);
  void hide() { design_.reset(); }
  void setMapKind(MapKind kind) { kind_ = kind; }
  MapKind mapKind() const { return kind_; }
  bool showing() const { return design_.has_value(); }
  const DesignMaps& maps() const { return maps_; }
  void paint(QPainter& painter, const ViewTransform& view) override;

 private:
  std::optional<design::Design> design_;
  DesignMaps maps_;
  MapKind kind_ = MapKind::Conditioning;
};

}  // namespace fivebar::widgets
