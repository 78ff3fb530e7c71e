// SPDX-License-Identifier: GPL-3.0-or-later
// Jacobians (Hoang 2015 eq. 7, A * v = B * thetaDot) and the Gosselin-Angeles singularity
// classification with continuous distance measures. Derivation: docs/kinematics.md.
#pragma once

#include <Eigen/Core>

#include "core/kinematics/kinematics.hpp"

namespace fivebar {

struct Jacobians {
  Eigen::Matrix2d A;  // rows (P - Ri)^T
  Eigen::Matrix2d B;  // diag(ai * (P - Ri) . (-sin theta_i, cos theta_i))
};
Jacobians jacobians(const Geometry& g, const Pose& pose);

// Cartesian Jacobian J = A^-1 B, so that v = J * thetaDot. nullopt at a type II singularity.
std::optional<Eigen::Matrix2d> cartesianJacobian(const Geometry& g, const Pose& pose);

// Continuous distances to each singularity type, as angles in [0, pi/2] (rad):
//  typeII  = min(mu, pi - mu) with mu the angle at P between the floating links: 0 when R1, P, R2
//            are collinear (det A = 0).
//  typeI1  = min(mu1, pi - mu1) with mu1 the angle at R1 between M1->R1 and R1->P: 0 when leg 1 is
//            fully stretched or folded (B11 = 0). typeI2 likewise.
// Equivalently sin(typeII) = |det A| / (b1 b2), sin(typeIi) = |Bii| / (ai bi).
struct SingularityMargins {
  double typeI1 = 0.0;
  double typeI2 = 0.0;
  double typeII = 0.0;
  double typeI() const { return typeI1 < typeI2 ? typeI1 : typeI2; }
};
SingularityMargins singularityMargins(const Geometry& g, const Pose& pose);

enum class SingularityType { None, TypeI, TypeII, TypeIII };

// Which singularity a pose is at (or within `thresholdRad` of, for each measure).
SingularityType classify(const SingularityMargins& m, double thresholdRad);

// Inverse condition number of J in [0, 1] (1 = isotropic, 0 = singular).
double inverseCondition(const Geometry& g, const Pose& pose);

}  // namespace fivebar
