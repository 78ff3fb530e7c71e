// SPDX-License-Identifier: GPL-3.0-or-later
// Grouping of captured polylines into Drawing layers (docs/svg-import.md, "Layers").
#pragma once

#include <vector>

#include "capture_engine.hpp"
#include "core/planning/drawing.hpp"
#include "svg_import.hpp"
#include "svg_sanitize.hpp"

namespace fivebar::svg {

// Layers in order of first appearance. A group layer takes the group's id, its inkscape:label
// (or id) as name and its first stroke colour; a colour layer is "color:#rrggbb".
std::vector<Layer> buildLayers(std::vector<CapturedRun>&& runs,
                               const std::vector<TopLevelElement>& topLevel, LayerMode mode);

}  // namespace fivebar::svg
