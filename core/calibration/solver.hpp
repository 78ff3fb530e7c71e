// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to core/calibration: one least-squares problem (points or distances, one mirror
// hypothesis, a subset of the measurements) solved with Eigen's LevenbergMarquardt module.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/calibration/fit.hpp"

namespace fivebar::calibration::detail {

// Parameter vector: a1 b1 a2 b2 w zeroOffset1 zeroOffset2 [penAlong penNormal] [rotation tx ty].
struct Problem {
  AssemblyMode assembly = AssemblyMode::Plus;
  bool distances = false;  // distance form: no paper pose
  bool mirrored = false;
  bool fitPen = false;
  // Points: a[i] measured at measured[i]. Distances: |pen(a[i]) - pen(b[i])| = dist[i].
  std::vector<JointAngles> a, b;
  std::vector<Vec2> measured;
  std::vector<double> dist;

  int machineCount() const { return fitPen ? 9 : 7; }
  int parameterCount() const { return machineCount() + (distances ? 0 : 3); }
  int residualsPer() const { return distances ? 1 : 2; }
  int residualCount() const { return residualsPer() * int(distances ? dist.size() : measured.size()); }
  MachineParameters machine(const Eigen::VectorXd& x) const;
  PaperPose paper(const Eigen::VectorXd& x) const;
  Eigen::VectorXd pack(const MachineParameters& m, const PaperPose& pose) const;
  // Residuals in mm (predicted - measured); false when the loop cannot close at some mark.
  bool residuals(const Eigen::VectorXd& x, Eigen::VectorXd& r) const;
};

struct Solution {
  Eigen::VectorXd x;
  bool converged = false;
  int evaluations = 0;
  Eigen::MatrixXd jacobian;  // at x, free parameters only
};

// Minimises over the parameters whose `free` flag is set, starting from x0.
Solution solve(const Problem& problem, const Eigen::VectorXd& x0, const std::vector<bool>& free, int maxEvaluations);

// Per-measurement residual size (mm) at x.
std::vector<double> measurementResiduals(const Problem& problem, const Eigen::VectorXd& x);

}  // namespace fivebar::calibration::detail
