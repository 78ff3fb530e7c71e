// SPDX-License-Identifier: GPL-3.0-or-later
// Shared checks of the pattern builders: a machine-frame point as a commanded pose that passes
// the safety rule (core/planning/safety.hpp), and a disc of such points.
#pragma once

#include <cmath>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/safety.hpp"

namespace fivebar::pattern_detail {

// The pose that draws `p` in `mode`, unwrapped near the home pose as the planner unwraps a
// stroke; nullopt when out of reach or when checkPose finds a problem (joint limit, margins).
inline std::optional<JointAngles> safePose(const MachineProfile& profile, WorkingMode mode,
                                           const Vec2& p) {
  const IkResult ik = inverse(profile.geometry, p, mode);
  if (!ik.ok()) return std::nullopt;
  const JointAngles q{unwrapNear(ik.angles.theta1, profile.homeAngles.theta1),
                      unwrapNear(ik.angles.theta2, profile.homeAngles.theta2)};
  if (!checkPose(profile, q).ok()) return std::nullopt;
  return q;
}

// Whether the centre and `ringPoints` points on each circle of radius radiusMm, radiusMm/2 around
// `center` are safe poses.
inline bool discIsSafe(const MachineProfile& profile, WorkingMode mode, const Vec2& center,
                       double radiusMm, int ringPoints = 12) {
  if (!safePose(profile, mode, center)) return false;
  for (double r : {0.5 * radiusMm, radiusMm})
    for (int k = 0; k < ringPoints; ++k) {
      const double a = 2.0 * kPi * k / ringPoints;
      if (!safePose(profile, mode, center + r * Vec2(std::cos(a), std::sin(a)))) return false;
    }
  return true;
}

}  // namespace fivebar::pattern_detail
