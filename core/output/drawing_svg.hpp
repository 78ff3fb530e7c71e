// SPDX-License-Identifier: GPL-3.0-or-later
// A drawing (core/planning/drawing.hpp) as a plain SVG in millimetres: width and height in mm and
// a viewBox of the same numbers, so one user unit is one millimetre; one <g> per visible layer
// with its stroke colour, no fill; one <path> per polyline (the work frame's y up flipped to the
// SVG's y down: y_svg = heightMm - y). Fill, hatch and tool settings are not written.
// Used by `fivebar text`; meant as well for the studio's Export SVG.
#pragma once

#include <string>

#include "core/planning/drawing.hpp"

namespace fivebar {

struct SvgWriteOptions {
  double strokeWidthMm = 0.3;  // the drawn line's width in the picture (a pen's, about)
  int decimals = 4;            // of every coordinate (0.1 um at 4)
};

std::string svgFromDrawing(const Drawing& drawing, const SvgWriteOptions& options = {});

}  // namespace fivebar
