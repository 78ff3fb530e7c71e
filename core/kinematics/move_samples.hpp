// SPDX-License-Identifier: GPL-3.0-or-later
// Forward kinematics at equally spaced points of a joint-linear move, the inner loop of
// segmentation and feeds. Same closure formula as forward() in kinematics.cpp, but the motor
// angles' cosines and sines advance by rotation (one complex multiplication per sample instead of
// two sincos calls), re-anchored with exact sincos every 32 samples so that the rounding drift
// stays below 1e-12 mm on any plotter-sized linkage. The step rotation of a short
// step comes from its Taylor series, and a caller that knows the start's cosines and sines
// (MotorTrig) passes them in: a short move then costs no trigonometric call at all.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/kinematics/kinematics.hpp"

namespace fivebar {

// cos and sin of both motor angles of a pose.
struct MotorTrig {
  double c1 = 1.0, s1 = 0.0, c2 = 1.0, s2 = 0.0;
  static MotorTrig of(const JointAngles& q) {
    return {std::cos(q.theta1), std::sin(q.theta1), std::cos(q.theta2), std::sin(q.theta2)};
  }
};

// cos and sin of a step angle: Taylor series to the 9th order below 0.05 rad (error below
// 1e-17), libm above.
inline void stepRotation(double d, double& c, double& s) {
  if (std::abs(d) < 0.05) {
    const double d2 = d * d;
    c = 1.0 - d2 * (1.0 / 2 - d2 * (1.0 / 24 - d2 * (1.0 / 720 - d2 * (1.0 / 40320))));
    s = d * (1.0 - d2 * (1.0 / 6 - d2 * (1.0 / 120 - d2 * (1.0 / 5040 - d2 * (1.0 / 362880)))));
  } else {
    c = std::cos(d);
    s = std::sin(d);
  }
}

// Most samples one call takes (n <= kMaxMoveSamples).
inline constexpr int kMaxMoveSamples = 1024;

// Writes FK of qa + (k / n)(qb - qa) for k = 0..n into out[0..n] (out has room for n + 1
// points, 1 <= n <= kMaxMoveSamples); `start` holds the cosines and sines of qa. Returns false
// when the loop cannot close (or the elbows coincide) at some sample, as forward() would report
// (out is then partly meaningless). The closure runs as a vectorised loop (move_samples.cpp).
bool sampleJointMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                     const MotorTrig& start, const JointAngles& qb, int n, Vec2* out);

// The cosines and sines of the motor angles that inverse kinematics in `mode` gives for each of
// the n points (reachable ones; others get meaningless values), from the IK geometry without a
// trigonometric call: theta = chord + sign * alpha with cos alpha from the law of cosines
// (kinematics.cpp, inverseArm1/2). Vectorised like sampleJointMove.
void motorTrigOfPoints(const Geometry& g, WorkingMode mode, const Vec2* points, std::size_t n,
                       MotorTrig* out);

inline bool sampleJointMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                            const JointAngles& qb, int n, Vec2* out) {
  return sampleJointMove(g, assembly, qa, MotorTrig::of(qa), qb, n, out);
}

}  // namespace fivebar
