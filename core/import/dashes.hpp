// SPDX-License-Identifier: GPL-3.0-or-later
// Dashed strokes (stroke-dasharray, stroke-dashoffset) cut into the dashes a plotter draws, pen up
// in between, as SVG 2 "Dash patterns" specifies: lengths in the element's user units along the
// path, the pattern restarting at each subpath (an odd count of values is repeated to make an even
// one; all zero, negative or no values: solid), the offset shifting where the pattern starts.
#pragma once

#include <QPen>
#include <QTransform>

#include <optional>
#include <vector>

#include "core/planning/drawing.hpp"

namespace fivebar::svg {

struct DashPattern {
  std::vector<double> lengths;  // user units: dash, gap, dash, gap, ... (an even count, sum > 0)
  double offset = 0.0;          // user units into the pattern where each subpath starts
};

// The pattern Qt SVG put on the pen (in units of the pen width, as QPen keeps it); nullopt when
// the pen is solid or the pattern is degenerate.
std::optional<DashPattern> dashPatternOf(const QPen& pen);

// Cuts page-frame polylines (pageFromUser = the painter's transform when they were drawn) into
// their dashes, measured in user units. A closed polyline is dashed over its closing edge; a dash
// across its starting point is one piece. The dashes are open polylines without fill marks.
// More than a million dashes in one call: the lines are returned solid (a runaway pattern).
std::vector<Polyline> applyDashes(const std::vector<Polyline>& lines, const DashPattern& pattern,
                                  const QTransform& pageFromUser);

}  // namespace fivebar::svg
