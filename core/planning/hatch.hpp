// SPDX-License-Identifier: GPL-3.0-or-later
// Fill modes for filled shapes: outline (the shape's geometry, as AxiDraw and vpype draw it),
// hatch (parallel lines clipped by the shape with its fill rule, optionally crossed), or none.
// Pure geometry on the work frame (mm); the import marks filled shapes (Polyline::fill,
// fillStart, fillOnly in drawing.hpp). docs/svg-import.md, "Fills".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/planning/drawing.hpp"

namespace fivebar {

const char* toString(FillMode mode);
std::optional<FillMode> fillModeFromString(std::string_view text);  // outline|hatch|none


// Empty when usable; else what is wrong (spacing must be finite and >= kMinHatchSpacingMm).
inline constexpr double kMinHatchSpacingMm = 0.01;
std::string validate(const HatchSettings& settings);

// Hatch lines of the area bounded by `rings` (each taken as closed) under `rule`, at the given
// spacing and angle. Every line lies inside the area and ends on its boundary; neighbouring lines
// are joined (boustrophedon) where the joining segment stays inside, so there are few strokes.
std::vector<Polyline> hatchArea(const std::vector<std::vector<Vec2>>& rings, FillRule rule,
                                double spacingMm, double angleRad);

// The polylines to plot for a layer's paths under a fill mode: outline keeps them as they are;
// none drops the outlines of fill-only shapes; hatch adds each filled shape's hatch lines after
// its outline (and drops fill-only outlines unless settings.outline).
std::vector<Polyline> applyFill(const std::vector<Polyline>& paths, FillMode mode,
                                const HatchSettings& settings);

// The polylines a layer is drawn with: its paths under its own fill (Layer::fill, Layer::hatch).
inline std::vector<Polyline> filledPaths(const Layer& layer) {
  return layer.fill == FillMode::Outline ? layer.paths : applyFill(layer.paths, layer.fill, layer.hatch);
}

}  // namespace fivebar
