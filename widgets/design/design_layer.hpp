// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas preview of a design chosen in the Design dialog: it covers the canvas with the
// design's workspace, singularity curves, placed rectangle and one measure map, plus a card
// with its lengths and measures. Paints nothing while no design is shown.
#pragma once

#include <optional>

#include "widgets/canvas/canvas_layer.hpp"
#include "paint/design_painter.hpp"

namespace fivebar::widgets {

class DesignLayer : public CanvasLayer {
 public:
  void show(const design::Design& d, paint::DesignMaps maps);
  void hide() { design_.reset(); }
  void setMapKind(paint::MapKind kind) { kind_ = kind; }
  paint::MapKind mapKind() const { return kind_; }
  bool showing() const { return design_.has_value(); }
  const paint::DesignMaps& maps() const { return maps_; }
  void paint(QPainter& painter, const paint::ViewTransform& view) override;

 private:
  std::optional<design::Design> design_;
  paint::DesignMaps maps_;
  paint::MapKind kind_ = paint::MapKind::Conditioning;
};

}  // namespace fivebar::widgets
