// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/kinematics/singularity.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace fivebar {
namespace {

double foldToQuarter(double angle) { return std::min(angle, kPi - angle); }

}  // namespace

Jacobians jacobians(const Geometry& g, const Pose& pose) {
  const Vec2 d1 = pose.P - pose.R1, d2 = pose.P - pose.R2;
  Jacobians j;
  j.A << d1.x(), d1.y(), d2.x(), d2.y();
  const Vec2 t1(-std::sin(pose.q.theta1), std::cos(pose.q.theta1));
  const Vec2 t2(-std::sin(pose.q.theta2), std::cos(pose.q.theta2));
  j.B << g.a1 * d1.dot(t1), 0.0, 0.0, g.a2 * d2.dot(t2);
  return j;
}

std::optional<Eigen::Matrix2d> cartesianJacobian(const Geometry& g, const Pose& pose) {
  const Jacobians j = jacobians(g, pose);
  const double det = j.A.determinant();
  if (std::abs(det) <= 1e-12 * g.b1 * g.b2) return std::nullopt;
  return Eigen::Matrix2d(j.A.inverse() * j.B);
}

SingularityMargins singularityMargins(const Geometry& g, const Pose& pose) {
  const TransmissionAngles t = transmissionAngles(g, pose);
  return {foldToQuarter(t.mu1), foldToQuarter(t.mu2), foldToQuarter(t.mu)};
}

SingularityType classify(const SingularityMargins& m, double thresholdRad) {
  const bool one = m.typeI() <= thresholdRad;
  const bool two = m.typeII <= thresholdRad;
  if (one && two) return SingularityType::TypeIII;
  if (two) return SingularityType::TypeII;
  if (one) return SingularityType::TypeI;
  return SingularityType::None;
}

double inverseCondition(const Geometry& g, const Pose& pose) {
  const auto J = cartesianJacobian(g, pose);
  if (!J) return 0.0;
  const Eigen::Vector2d s = Eigen::JacobiSVD<Eigen::Matrix2d>(*J).singularValues();
  return s(0) > 0.0 ? s(1) / s(0) : 0.0;
}

}  // namespace fivebar
