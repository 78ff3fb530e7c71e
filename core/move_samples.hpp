// Forward kinematics at equally spaced points of a joint-linear move, the inner loop of
// segmentation and feeds. Same closure formula as forward() in kinematics.cpp, but the motor
// angles' cosines and sines advance by rotation (one complex multiplication per sample instead of
// two sincos calls), re-anchored with exact sincos every kReanchorSamples samples so that the
// rounding drift stays below 1e-12 mm on any plotter-sized linkage. The step rotation of a short
// step comes from its Taylor series, and a caller that knows the start's cosines and sines
// (MotorTrig) passes them in: a short move then costs no trigonometric call at all.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "kinematics.hpp"

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

// Writes FK of qa + (k / n)(qb - qa) for k = 0..n into out[0..n] (out has room for n + 1
// points); `start` holds the cosines and sines of qa. Returns false, leaving out partly written,
// when the loop cannot close (or the elbows coincide) at some sample, as forward() would report.
inline bool sampleJointMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                            const MotorTrig& start, const JointAngles& qb, int n, Vec2* out) {
  constexpr int kReanchorSamples = 32;
  const double d1 = (qb.theta1 - qa.theta1) / n, d2 = (qb.theta2 - qa.theta2) / n;
  double cd1, sd1, cd2, sd2;
  stepRotation(d1, cd1, sd1);
  stepRotation(d2, cd2, sd2);
  const Vec2 m1 = g.motor1(), m2 = g.motor2();
  const double sum = g.b1 + g.b2, diff = g.b1 - g.b2;
  const double side = assembly == AssemblyMode::Plus ? 1.0 : -1.0;
  const double alongConst = g.b1 * g.b1 - g.b2 * g.b2;
  double c1 = start.c1, s1 = start.s1, c2 = start.c2, s2 = start.s2;
  for (int k = 0; k <= n; ++k) {
    if (k > 0 && k % kReanchorSamples == 0) {
      const double u = static_cast<double>(k) / n;
      const double t1 = qa.theta1 + u * (qb.theta1 - qa.theta1);
      const double t2 = qa.theta2 + u * (qb.theta2 - qa.theta2);
      c1 = std::cos(t1), s1 = std::sin(t1), c2 = std::cos(t2), s2 = std::sin(t2);
    } else if (k > 0) {
      const double c1n = c1 * cd1 - s1 * sd1, c2n = c2 * cd2 - s2 * sd2;
      s1 = s1 * cd1 + c1 * sd1, s2 = s2 * cd2 + c2 * sd2;
      c1 = c1n, c2 = c2n;
    }
    const Vec2 R1 = m1 + g.a1 * Vec2(c1, s1), R2 = m2 + g.a2 * Vec2(c2, s2);
    const Vec2 r = R2 - R1;
    const double dd = r.squaredNorm();
    const double d = std::sqrt(dd);
    if (d < 1e-12 || d > sum + kReachToleranceMm || d < std::abs(diff) - kReachToleranceMm)
      return false;
    const double inv = 1.0 / d;
    const Vec2 u = r * inv;
    const double along = (alongConst + dd) * 0.5 * inv;
    const double h2 = (sum - d) * (sum + d) * (d - diff) * (d + diff) * 0.25 * inv * inv;
    const double h = side * std::sqrt(std::max(0.0, h2));
    out[k] = R1 + along * u + h * Vec2(-u.y(), u.x());
  }
  return true;
}

inline bool sampleJointMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                            const JointAngles& qb, int n, Vec2* out) {
  return sampleJointMove(g, assembly, qa, MotorTrig::of(qa), qb, n, out);
}

}  // namespace fivebar
