// SPDX-License-Identifier: GPL-3.0-or-later
// Where a drawing goes when no position is given: the one rule shared by `fivebar plan` and the
// studio (import, "Fit to workspace", "Actual size"). The drawing is centred in the largest
// singularity-free rectangle of its aspect ratio (kFitGridCells map, kFitMarginMm kept free on
// every side) in the working mode the Auto rule picks; at true size when it fits, scaled down
// when it does not, enlarged only when asked (PlacementSizing::Fit). Design: docs/planning.md.
#pragma once

#include <optional>
#include <string>

#include "core/kinematics/modes.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/drawing.hpp"
#include "core/planning/placement.hpp"
#include "core/support/message.hpp"

namespace fivebar {

// Margin kept free between a placed drawing and the edge of the singularity-free rectangle.
inline constexpr double kFitMarginMm = 1.0;
// Cells per side of the workspace map the rectangle is searched on.
inline constexpr int kFitGridCells = 160;

enum class PlacementSizing {
  TrueSize,  // 100 % when the drawing fits, otherwise scaled down to fit
  Fit,       // scaled (up or down) to fill the rectangle
};

struct AutoPlacement {
  WorkingMode mode = WorkingMode::PlusPlus;  // the mode whose rectangle the drawing is centred in
  Placement placement;
  RectMm rectMm;             // that rectangle, machine frame
  double fitScale = 1.0;     // the scale that fills it (less the margins)
  bool scaledDown = false;   // TrueSize only: the drawing did not fit at 100 %
};

// The largest singularity-free rectangle of `mode` with width/height = aspect (0: any), machine
// frame; nullopt when the mode has no safe cell. Computed afresh (no cache), deterministic.
std::optional<RectMm> fitRectangle(const MachineProfile& profile, WorkingMode mode, double aspect);

// The Auto rule: every candidate mode (just `mode` when given) gets its rectangle and the
// placement in it; the mode whose placed drawing has the largest type II margin over a fixed
// sample of its points wins (modes that cannot reach a sampled point rank after those that can,
// by the larger scale; ties keep the kAllWorkingModes order). nullopt when the drawing has no
// visible point or no mode has a rectangle.
std::optional<AutoPlacement> autoPlacement(const Drawing& drawing, const MachineProfile& profile,
                                           std::optional<WorkingMode> mode, double rotationRad,
                                           PlacementSizing sizing);

// "scaled to 62 % to fit the workspace" for a scaled-down placement, "" otherwise.
Message scaleNote(const AutoPlacement& placed);

// Upper bound (rad) of the type II margin any plan of the placed drawing can have in `mode`,
// from a fixed sample of about 20,000 of its points; nullopt when a sampled point cannot be
// reached in the mode (or only in the other assembly mode).
std::optional<double> screenMarginRad(const Drawing& drawing, const std::optional<RectMm>& bounds,
                                      const Placement& placement, const MachineProfile& profile,
                                      WorkingMode mode);

}  // namespace fivebar
