// SPDX-License-Identifier: GPL-3.0-or-later
// What a view of the machine should show (machine frame, mm): the drawing with the motors and
// the elbows wherever the pen reaches the drawing's corners and edge midpoints, or without a
// drawing the whole reach of the arms. The studio fits its canvas to it ("Zoom to fit").
#pragma once

#include <array>
#include <optional>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

struct BoxMm {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();
};

// The box around the placed drawing's corners (any order), the motors and the elbows of the
// arms reaching its corners and edge midpoints in `mode`, with `marginMm` around it.
BoxMm drawingViewBoxMm(const Geometry& g, WorkingMode mode, const std::array<Vec2, 4>& cornersMm,
                       double marginMm = 15.0);
// The box of everything the arms can reach, with the motors below it.
BoxMm machineViewBoxMm(const Geometry& g);

}  // namespace fivebar
