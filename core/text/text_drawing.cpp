// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/text/text_drawing.hpp"

namespace fivebar::text {

void appendText(const TextLayout& layout, const Vec2& originMm, Layer& layer) {
  for (const Polyline& stroke : layout.strokes) {
    Polyline moved = stroke;
    for (Vec2& p : moved.points) p += originMm;
    layer.paths.push_back(std::move(moved));
  }
}

Drawing drawingFromText(const TextLayout& layout, const TextDrawingOptions& options) {
  Drawing drawing;
  drawing.source = options.source;
  drawing.flatteningToleranceMm = 0.0;
  Layer layer;
  layer.id = options.layerId;
  layer.name = options.layerName;
  layer.rgb = options.rgb;
  Vec2 lo, hi;
  const double margin = options.marginMm > 0.0 ? options.marginMm : 0.0;
  if (strokeBounds(layout.strokes, lo, hi)) {
    appendText(layout, Vec2(margin, margin) - lo, layer);
    drawing.widthMm = hi.x() - lo.x() + 2.0 * margin;
    drawing.heightMm = hi.y() - lo.y() + 2.0 * margin;
  }
  drawing.layers.push_back(std::move(layer));
  return drawing;
}

}  // namespace fivebar::text
