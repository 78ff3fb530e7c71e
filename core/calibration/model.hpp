// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration model (issue 13, docs/calibration.md): what the fit estimates about a real
// five-bar, and where such a machine puts its pen for commanded motor angles. Machine frame,
// millimetres and radians; "commanded" angles are the ones sent in G-code.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/machine/calibration.hpp"

namespace fivebar::calibration {

// The machine parameters of the model: link lengths, a zero offset per motor (kinematic angle =
// commanded angle + offset) and, when fitted, the pen's offset from the distal joint P.
struct MachineParameters {
  Geometry geometry;
  double zeroOffsetRad1 = 0.0;
  double zeroOffsetRad2 = 0.0;
  std::optional<PenOffset> penOffset;
};

// The pen position (machine frame) of a machine with parameters `m` in assembly mode `assembly`
// at commanded angles; nullopt when the loop cannot close there.
std::optional<Vec2> penPosition(const MachineParameters& m, AssemblyMode assembly, const JointAngles& commanded);

// A rigid placement of the paper: paper = R(rotationRad) * S * machine + translationMm, with
// S = diag(1, -1) when the paper frame is mirrored (e.g. measured with y pointing down).
struct PaperPose {
  bool mirrored = false;
  double rotationRad = 0.0;
  Vec2 translationMm = Vec2::Zero();
  Vec2 paperFromMachine(const Vec2& machine) const;
};

// The rigid placement (no scale) minimising the squared distances |pose(from_i) - to_i|^2
// (Kabsch in 2-D). Needs at least two points that are not all the same.
PaperPose bestRigidPlacement(std::span<const Vec2> from, std::span<const Vec2> to, bool mirrored);

// Distances between a drawing and what was meant, after the best rigid placement (not mirrored).
struct ShapeError {
  double maxMm = 0.0;
  double rmsMm = 0.0;
};
ShapeError shapeError(std::span<const Vec2> drawn, std::span<const Vec2> intended);

}  // namespace fivebar::calibration
