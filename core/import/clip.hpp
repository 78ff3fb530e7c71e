// SPDX-License-Identifier: GPL-3.0-or-later
// Clip paths applied to plotted lines (SVG "Clipping paths"): the clip region is the union of its
// shapes, each filled with its own clip-rule; what is drawn is the part of each line inside it.
// Pure geometry in the page frame (mm). Strokes are cut at the region's edges by segment
// intersection and an inside test per piece (winding number or crossing parity); the outlines of
// fill-only shapes are intersected as areas with QPainterPath (Qt's own polygon clipper), so a
// clipped fill keeps a closed outline (the clip's edge included) that can still be hatched.
#pragma once

#include <vector>

#include "core/planning/drawing.hpp"

namespace fivebar::svg {

struct ClipShape {
  std::vector<std::vector<Vec2>> rings;  // closed rings, page mm
  FillRule rule = FillRule::NonZero;
};

// True when p lies inside one of the shapes (on an edge counts as inside).
bool insideClip(const Vec2& p, const std::vector<ClipShape>& clip);

// The parts of `lines` inside the clip region. Strokes become the pieces inside (a ring wholly
// inside stays closed); a stroked ring that is cut loses its fill marks (it is not hatched).
// Fill-only shapes (fillStart ... rings with fillOnly) become the rings of their intersection
// with the region, marked with the shape's rule.
std::vector<Polyline> clipLines(std::vector<Polyline>&& lines, const std::vector<ClipShape>& clip);

}  // namespace fivebar::svg
