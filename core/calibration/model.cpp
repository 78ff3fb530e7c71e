// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration model: docs/calibration.md. Symbols as in docs/kinematics.md.
#include "core/calibration/model.hpp"

#include <cmath>

#include "core/machine/pen_kinematics.hpp"

namespace fivebar::calibration {

std::optional<Vec2> penPosition(const MachineParameters& m, AssemblyMode assembly, const JointAngles& commanded) {
  const JointAngles q{commanded.theta1 + m.zeroOffsetRad1, commanded.theta2 + m.zeroOffsetRad2};
  const FkResult fk = penForward(m.geometry, m.penOffset, q, assembly);  // the one pen formula
  if (!fk.ok()) return std::nullopt;
  return fk.p;
}

Vec2 PaperPose::paperFromMachine(const Vec2& machine) const {
  const Vec2 s(machine.x(), mirrored ? -machine.y() : machine.y());
  const double c = std::cos(rotationRad), sn = std::sin(rotationRad);
  return Vec2(c * s.x() - sn * s.y(), sn * s.x() + c * s.y()) + translationMm;
}

PaperPose bestRigidPlacement(std::span<const Vec2> from, std::span<const Vec2> to, bool mirrored) {
  PaperPose pose;
  pose.mirrored = mirrored;
  const std::size_t n = std::min(from.size(), to.size());
  if (n == 0) return pose;
  Vec2 cf = Vec2::Zero(), ct = Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    cf += Vec2(from[i].x(), mirrored ? -from[i].y() : from[i].y());
    ct += to[i];
  }
  cf /= double(n);
  ct /= double(n);
  double dot = 0.0, crs = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 s = Vec2(from[i].x(), mirrored ? -from[i].y() : from[i].y()) - cf;
    const Vec2 m = to[i] - ct;
    dot += m.x() * s.x() + m.y() * s.y();
    crs += m.y() * s.x() - m.x() * s.y();
  }
  pose.rotationRad = std::atan2(crs, dot);
  const double c = std::cos(pose.rotationRad), sn = std::sin(pose.rotationRad);
  pose.translationMm = ct - Vec2(c * cf.x() - sn * cf.y(), sn * cf.x() + c * cf.y());
  return pose;
}

ShapeError shapeError(std::span<const Vec2> drawn, std::span<const Vec2> intended) {
  const PaperPose pose = bestRigidPlacement(drawn, intended, false);
  ShapeError e;
  const std::size_t n = std::min(drawn.size(), intended.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = (pose.paperFromMachine(drawn[i]) - intended[i]).norm();
    e.maxMm = std::max(e.maxMm, d);
    sum += d * d;
  }
  e.rmsMm = n ? std::sqrt(sum / double(n)) : 0.0;
  return e;
}

}  // namespace fivebar::calibration
