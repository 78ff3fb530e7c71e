// SPDX-License-Identifier: GPL-3.0-or-later
// Least-squares rigid placement of measured points (paper frame) onto nominal points (machine
// frame): rotation and translation, mirrored or not (a sheet measured with y down, or scanned face
// down). Kabsch's method on 2-D points.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar {

struct RigidFit {
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();  // det -1 when mirrored
  Vec2 translation = Vec2::Zero();
  bool mirrored = false;
  double rmsMm = 0.0;  // of the residuals machine - map(paper)
  Vec2 map(const Vec2& paper) const { return rotation * paper + translation; }
};

// Best fit of `paper` onto `machine` (same size, >= 2 points): with mirrored = nullopt the better
// of both handednesses, else the one asked for. nullopt for fewer than two points or all equal.
std::optional<RigidFit> fitRigid(const std::vector<Vec2>& paper, const std::vector<Vec2>& machine,
                                 std::optional<bool> mirrored = std::nullopt);

}  // namespace fivebar
