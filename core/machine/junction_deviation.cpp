// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/machine/junction_deviation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/kinematics/singularity.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar {
namespace {

// Grid points per side over the square that holds every reachable point.
constexpr int kLeverGridPoints = 200;
// GRBL 1.1 reports its settings with 3 decimals ($$): a $11 with more would never read back
// equal to the profile's (fivebar setup would keep writing it).
constexpr double kJunctionDecimalsScale = 1e3;

// Largest singular value of a 2x2 matrix.
double largestSingularValue(const Eigen::Matrix2d& m) {
  const Eigen::Matrix2d mtm = m.transpose() * m;
  const double tr = mtm.trace(), det = mtm.determinant();
  return std::sqrt(0.5 * tr + std::sqrt(std::max(0.0, 0.25 * tr * tr - det)));
}

}  // namespace

double largestLeverMmPerRad(const MachineProfile& p) {
  const Geometry& g = p.geometry;
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + g.w;
  const double step = 2.0 * reach / (kLeverGridPoints - 1);
  double largest = 0.0;
  for (int i = 0; i < kLeverGridPoints; ++i) {
    for (int j = 0; j < kLeverGridPoints; ++j) {
      const Vec2 at(-reach + step * i, -reach + step * j);
      const IkResult ik = inverse(g, at, p.defaultMode);
      if (!ik.ok()) continue;
      const Pose pose = makePose(g, ik.angles, at);
      const SingularityMargins m = singularityMargins(g, pose);
      if (m.typeII < p.typeIIMarginRad || m.typeI() < p.typeIMarginRad) continue;
      const auto jac = cartesianJacobian(g, pose);
      if (jac) largest = std::max(largest, largestSingularValue(*jac));
    }
  }
  return largest;
}

double junctionDeviationDegFor(const MachineProfile& profile, double toleranceMm) {
  const double lever = largestLeverMmPerRad(profile);
  if (!(lever > 0.0) || !(toleranceMm > 0.0)) return profile.motors.junctionDeviationDeg;
  const double deg = degFromRad(toleranceMm / lever);
  return std::max(1.0, std::floor(deg * kJunctionDecimalsScale)) / kJunctionDecimalsScale;
}

}  // namespace fivebar
