// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/rigid_fit.hpp"

#include <cmath>

namespace fivebar {
namespace {

std::optional<RigidFit> fitHanded(const std::vector<Vec2>& paper, const std::vector<Vec2>& machine,
                                  bool mirrored) {
  const double n = static_cast<double>(paper.size());
  Vec2 cp = Vec2::Zero(), cm = Vec2::Zero();
  for (size_t i = 0; i < paper.size(); ++i) {
    cp += paper[i];
    cm += machine[i];
  }
  cp /= n;
  cm /= n;
  // Mirrored: reflect the paper points (y -> -y) first, then find the best rotation.
  const Eigen::Matrix2d flip = mirrored ? Eigen::Vector2d(1.0, -1.0).asDiagonal().toDenseMatrix()
                                        : Eigen::Matrix2d::Identity();
  double sxx = 0.0, sxy = 0.0;  // sum of dot and cross products of the centred pairs
  bool spread = false;
  for (size_t i = 0; i < paper.size(); ++i) {
    const Vec2 a = flip * (paper[i] - cp), b = machine[i] - cm;
    sxx += a.dot(b);
    sxy += cross(a, b);
    spread = spread || a.norm() > 0.0;
  }
  if (!spread) return std::nullopt;
  const double angle = std::atan2(sxy, sxx);
  RigidFit f;
  f.mirrored = mirrored;
  f.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix() * flip;
  f.translation = cm - f.rotation * cp;
  double sum2 = 0.0;
  for (size_t i = 0; i < paper.size(); ++i) sum2 += (machine[i] - f.map(paper[i])).squaredNorm();
  f.rmsMm = std::sqrt(sum2 / n);
  return f;
}

}  // namespace

std::optional<RigidFit> fitRigid(const std::vector<Vec2>& paper, const std::vector<Vec2>& machine,
                                 std::optional<bool> mirrored) {
  if (paper.size() < 2 || paper.size() != machine.size()) return std::nullopt;
  if (mirrored) return fitHanded(paper, machine, *mirrored);
  const auto a = fitHanded(paper, machine, false), b = fitHanded(paper, machine, true);
  if (!a || !b) return a ? a : b;
  return b->rmsMm < a->rmsMm ? b : a;
}

}  // namespace fivebar
