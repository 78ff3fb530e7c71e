// SPDX-License-Identifier: GPL-3.0-or-later
// Stroke optimisation before motion planning: join strokes whose ends meet, simplify within a
// tolerance (Ramer-Douglas-Peucker), then reorder and reverse strokes to cut pen-up time.
// Travel cost is motor time in joint space, max_i |dtheta_i| / maxSpeed_i, from the inverse
// kinematics of the stroke ends in the chosen working mode (not XY distance). Layers keep their
// order: strokes are optimised within each run of equal layerIndex.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/strokes.hpp"

namespace fivebar {

struct OptimiseOptions {
  bool join = true;                 // join strokes of one layer whose ends meet
  // End-to-start distance that counts as meeting: the gap is bridged by a drawn line (recorded in
  // Stroke::bridgedGapMm). The planner sets joinGapMm(tolerance) (planner.hpp).
  double joinToleranceMm = 0.05;
  double simplifyToleranceMm = 0.0; // RDP tolerance; 0 keeps every point
  bool reorder = true;              // greedy nearest neighbour + 2-opt
  bool allowReverse = true;         // strokes may be drawn backwards
  int maxTwoOptPasses = 50;
  // The 2-opt's budget: long edges it may examine in all (0 = no limit). There is no wall-clock
  // budget: the same input always gives the same order, whatever the machine's load.
  std::size_t maxTwoOptSteps = 150000;
  // Fill OptimiseReport::travelBeforeS / travelAfterS (inverse kinematics of every stroke end).
  bool measureTravel = true;
  // Pen position (joint angles) before the first stroke, e.g. the home pose; nullopt = none.
  std::optional<JointAngles> start;
};

struct OptimiseReport {
  double travelBeforeS = 0.0;  // summed joint-space travel time of the input order
  double travelAfterS = 0.0;   // same for the output order
  std::size_t strokesBefore = 0;
  std::size_t strokesAfter = 0;
  std::size_t joins = 0;        // number of joins performed
  std::size_t pointsBefore = 0;
  std::size_t pointsAfter = 0;
  double seconds = 0.0;         // wall-clock time spent
};

struct OptimiseResult {
  std::vector<Stroke> strokes;
  OptimiseReport report;
};

// Runs join -> simplify -> reorder on `strokes` (machine frame) in working mode `mode`.
// Without simplification no point is moved or dropped except the duplicate at an exact join
// (an end equal to the next start); reversal reverses the point order and flips `reversed`.
// A joined stroke keeps the layerIndex/pathIndex of its first piece.
OptimiseResult optimise(std::vector<Stroke> strokes, const MachineProfile& profile,
                        WorkingMode mode, const OptimiseOptions& options = {});

// Joint-space travel time (s) of a stroke order: pen-up moves from `start` (if any) to the first
// stroke and between consecutive strokes. Unreachable ends fall back to pseudo angles (the chord
// directions from each motor) so the cost stays defined.
double travelTimeS(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                   WorkingMode mode, const std::optional<JointAngles>& start = std::nullopt);

// Motor time (s) of a joint move from a to b: max over motors of |dtheta_i| / maxSpeed_i with
// the wrapped (shortest) angle difference.
double jointTravelTimeS(const MotorSettings& motors, const JointAngles& a, const JointAngles& b);

// Ramer-Douglas-Peucker: keeps the first and last points and every point needed so that no
// dropped point is farther than toleranceMm from the simplified polyline. Iterative (no deep
// recursion on long polylines).
std::vector<Vec2> simplifyPolyline(const std::vector<Vec2>& points, double toleranceMm);

}  // namespace fivebar
