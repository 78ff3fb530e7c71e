// SPDX-License-Identifier: GPL-3.0-or-later
// The best placement of a target rectangle for a given geometry and working mode: the position
// (and optionally a quarter turn) that minimises the objective while keeping every rule
// (docs/design.md "Placement").
#pragma once

#include <optional>

#include "core/design/objective.hpp"

namespace fivebar::design {

struct PlacementOptions {
  Objective objective = Objective::Condition;
  MixWeights weights;           // Objective::Mix only
  bool allowRotation = false;   // also try the rectangle turned by 90 degrees
  Sampling finalSampling{1.0};  // the sampling of the reported evaluation
};

struct Placement {
  Rect rect;             // machine frame, mm
  bool rotated = false;  // width runs along y
  Evaluation evaluation; // at options.finalSampling
  double score = 0.0;    // penalisedScore of evaluation
};

// The rectangle of widthMm x heightMm (width along x unless rotated) placed where it scores
// best. Always returns a placement; check placement.evaluation.feasible().
Placement bestPlacement(const Geometry& g, WorkingMode mode, double widthMm, double heightMm,
                        const DesignRules& rules, const PlacementOptions& options = {});

// A rectangle of the given size centred at (cx, cy).
inline Rect centredRect(double cx, double cy, double widthMm, double heightMm) {
  return {cx - 0.5 * widthMm, cy - 0.5 * heightMm, cx + 0.5 * widthMm, cy + 0.5 * heightMm};
}

}  // namespace fivebar::design
