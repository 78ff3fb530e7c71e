// SPDX-License-Identifier: GPL-3.0-or-later
// Text into the planner's drawing model (core/planning/drawing.hpp): what `fivebar text` and the
// studio's text tool both use, so the two draw the same strokes. docs/text.md.
#pragma once

#include <cstdint>
#include <string>

#include "core/kinematics/geometry.hpp"
#include "core/planning/drawing.hpp"
#include "core/text/text_layout.hpp"

namespace fivebar::text {

// Appends the layout's strokes to `layer`, moved so that the layout's origin (the first
// baseline's anchor, text_layout.hpp) lands at `originMm` (work frame).
void appendText(const TextLayout& layout, const Vec2& originMm, Layer& layer);

struct TextDrawingOptions {
  std::string source = "text";   // Drawing::source, for messages
  std::string layerId = "text";
  std::string layerName = "text";
  std::uint32_t rgb = 0x000000;  // stroke colour
  double marginMm = 0.0;         // free paper around the text's strokes on each side
};

// A drawing of one layer holding the text: the page is the strokes' bounding box grown by the
// margin, the strokes are moved so that box starts at (margin, margin) in the work frame (the
// page's bottom-left corner at the origin, y up). No tolerance is spent: the strokes are the
// glyphs' own straight segments. An empty layout gives a drawing with an empty layer.
Drawing drawingFromText(const TextLayout& layout, const TextDrawingOptions& options = {});

}  // namespace fivebar::text
