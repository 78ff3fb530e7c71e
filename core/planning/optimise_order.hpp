// SPDX-License-Identifier: GPL-3.0-or-later
// Stroke ordering for optimise.cpp: greedy nearest neighbour on a bucket grid, then 2-opt with
// neighbour lists, on stroke ends given in scaled joint space (motor time, s). Internal to the
// optimiser; the public API is core/optimise.hpp.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar::order {

// Stroke ends in scaled joint space: (theta1 / v1, theta2 / v2), seconds, unwrapped near a
// common reference, so that the L-infinity distance is the motor time of the travel.
struct Ends {
  std::vector<Vec2> node;  // node 2 i = start of stroke i, 2 i + 1 = end
};

// A stroke order: order[p] is the stroke drawn p-th, flip[p] whether it is drawn end to start.
struct Tour {
  std::vector<int> order;
  std::vector<char> flip;
};

// Travel time between two nodes, s.
inline double cost(const Vec2& a, const Vec2& b) { return (a - b).cwiseAbs().maxCoeff(); }

// Greedy nearest neighbour from `start` (or from stroke 0, kept first, when there is none).
Tour greedyTour(const Ends& e, std::size_t n, const std::optional<Vec2>& start, bool allowReverse);

// 2-opt with segment reversal (strokes in a reversed segment flip) until no move improves or
// the pass / step / time budget ends; stepsLeft counts down the long edges examined.
void twoOpt(const Ends& e, Tour& t, const std::optional<Vec2>& start, int maxPasses,
            std::size_t& stepsLeft);

// Travel time of a tour, and of the input order (stroke i p-th, unflipped), s.
double tourCost(const Ends& e, const Tour& t, const std::optional<Vec2>& start);
double inputCost(const Ends& e, const std::optional<Vec2>& start);

}  // namespace fivebar::order
