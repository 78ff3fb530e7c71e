// SPDX-License-Identifier: GPL-3.0-or-later
// Strokes: the drawing's polylines placed in the machine frame (mm), in plotting order. The
// boundary between placement/optimisation (placement.hpp, optimise.hpp) and motion planning
// (segmentation, feeds, G-code).
#pragma once

#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar {

struct Stroke {
  std::vector<Vec2> points;  // machine frame, mm; drawn pen-down from first to last
  int layerIndex = 0;        // index into Drawing::layers
  int pathIndex = 0;         // index of the source polyline within its layer (for messages)
  bool reversed = false;     // drawn from the source polyline's end to its start
  // The points approximate curves (Polyline::flattened): the flattening error at the placement
  // scale (PlanOptions::flatteningToleranceMm) is part of this stroke's deviation.
  bool flattened = false;
  // Largest gap (mm) between the end of one piece and the start of the next that joining bridged
  // inside this stroke (optimise.hpp): the bridge is drawn, so half of it (its middle is that far
  // from both ends) is part of this stroke's deviation. 0 for exact joins.
  double bridgedGapMm = 0.0;
};

}  // namespace fivebar
