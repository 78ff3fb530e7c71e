// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL's junction deviation ($11) for a five-bar. GRBL plans joint-space blocks (X = theta1 deg,
// Y = theta2 deg) and takes each junction at the speed at which a virtual arc, tangent to both
// blocks and passing within $11 of the corner, could be followed at the acceleration limit: the
// corner is cut by at most $11 in joint space. Through the arm that is at most |J| * $11 in the
// drawing (|J| the largest singular value of the Cartesian Jacobian, mm/rad), so $11 = tolerance /
// max |J| over the working mode's safe workspace keeps corners and curves within the tolerance.
// A larger $11 takes corners faster; a smaller one slows every curve (docs/planning.md, "Feeds").
#pragma once

#include "core/machine/profile.hpp"

namespace fivebar {

// The drawing tolerance the presets' $11 is chosen for (mm): the planner's default tolerance.
inline constexpr double kCorneringToleranceMm = 0.1;

// Largest |J| (mm/rad) over the points of the profile's working mode that keep its type I and
// type II margins (a grid over the reach, 200 x 200 points).
double largestLeverMmPerRad(const MachineProfile& profile);

// $11 (deg, rounded down to the 3 decimals GRBL reports) that keeps the corner cut within
// `toleranceMm` everywhere in the safe workspace.
double junctionDeviationDegFor(const MachineProfile& profile, double toleranceMm);

}  // namespace fivebar
