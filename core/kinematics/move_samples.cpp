// SPDX-License-Identifier: GPL-3.0-or-later
// sampleJointMove: the elbows by rotation (a short sequential recurrence), then the loop closure
// of every sample as one branch-free loop that the compiler vectorises (compiled with -O3 and
// sqrt without errno, in AVX-512, AVX2 and baseline variants chosen at load time).
#include "core/kinematics/move_samples.hpp"

namespace fivebar {

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
bool sampleJointMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                     const MotorTrig& start, const JointAngles& qb, int n, Vec2* out) {
  constexpr int kReanchorSamples = 32;
  if (n < 1 || n > kMaxMoveSamples) return false;
  alignas(64) double r1x[kMaxMoveSamples + 1], r1y[kMaxMoveSamples + 1];
  alignas(64) double r2x[kMaxMoveSamples + 1], r2y[kMaxMoveSamples + 1];
  const double d1 = (qb.theta1 - qa.theta1) / n, d2 = (qb.theta2 - qa.theta2) / n;
  double cd1, sd1, cd2, sd2;
  stepRotation(d1, cd1, sd1);
  stepRotation(d2, cd2, sd2);
  const Vec2 m1 = g.motor1(), m2 = g.motor2();
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
    r1x[k] = m1.x() + g.a1 * c1, r1y[k] = m1.y() + g.a1 * s1;
    r2x[k] = m2.x() + g.a2 * c2, r2y[k] = m2.y() + g.a2 * s2;
  }
  const double sum = g.b1 + g.b2, diff = g.b1 - g.b2;
  const double farthest = sum + kReachToleranceMm, nearest = std::abs(diff) - kReachToleranceMm;
  const double side = assembly == AssemblyMode::Plus ? 1.0 : -1.0;
  const double alongConst = g.b1 * g.b1 - g.b2 * g.b2;
  double* xy = out[0].data();
  int bad = 0;
  for (int k = 0; k <= n; ++k) {
    const double rx = r2x[k] - r1x[k], ry = r2y[k] - r1y[k];
    const double dd = rx * rx + ry * ry;
    const double d = std::sqrt(dd);
    bad |= (d < 1e-12) | (d > farthest) | (d < nearest);
    const double inv = 1.0 / std::max(d, 1e-12);
    const double ux = rx * inv, uy = ry * inv;
    const double along = (alongConst + dd) * 0.5 * inv;
    const double h2 = (sum - d) * (sum + d) * (d - diff) * (d + diff) * 0.25 * inv * inv;
    const double h = side * std::sqrt(std::max(0.0, h2));
    xy[2 * k] = r1x[k] + along * ux - h * uy;
    xy[2 * k + 1] = r1y[k] + along * uy + h * ux;
  }
  return bad == 0;
}

__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
void motorTrigOfPoints(const Geometry& g, WorkingMode mode, const Vec2* points, std::size_t n,
                       MotorTrig* out) {
  // '+' puts R1 counter-clockwise of the chord M1->P, R2 clockwise of M2->P.
  const double sign1 = arm1Sign(mode) == ArmSign::Plus ? 1.0 : -1.0;
  const double sign2 = arm2Sign(mode) == ArmSign::Plus ? -1.0 : 1.0;
  const Vec2 m1 = g.motor1(), m2 = g.motor2();
  const double* xy = points[0].data();
  double* trig = &out[0].c1;  // MotorTrig is four doubles: c1, s1, c2, s2
  for (std::size_t k = 0; k < n; ++k) {
    const double x = xy[2 * k], y = xy[2 * k + 1];
    const double cx1 = x - m1.x(), cy1 = y - m1.y(), cx2 = x - m2.x(), cy2 = y - m2.y();
    const double d1 = std::max(std::sqrt(cx1 * cx1 + cy1 * cy1), 1e-12);
    const double d2 = std::max(std::sqrt(cx2 * cx2 + cy2 * cy2), 1e-12);
    const double ca1 = std::clamp((g.a1 * g.a1 + d1 * d1 - g.b1 * g.b1) / (2.0 * g.a1 * d1), -1.0, 1.0);
    const double ca2 = std::clamp((g.a2 * g.a2 + d2 * d2 - g.b2 * g.b2) / (2.0 * g.a2 * d2), -1.0, 1.0);
    const double sa1 = std::sqrt(std::max(0.0, 1.0 - ca1 * ca1));
    const double sa2 = std::sqrt(std::max(0.0, 1.0 - ca2 * ca2));
    const double cc1 = cx1 / d1, sc1 = cy1 / d1, cc2 = cx2 / d2, sc2 = cy2 / d2;
    trig[4 * k] = cc1 * ca1 - sign1 * sc1 * sa1;
    trig[4 * k + 1] = sc1 * ca1 + sign1 * cc1 * sa1;
    trig[4 * k + 2] = cc2 * ca2 - sign2 * sc2 * sa2;
    trig[4 * k + 3] = sc2 * ca2 + sign2 * cc2 * sa2;
  }
}

}  // namespace fivebar
