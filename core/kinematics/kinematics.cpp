// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/kinematics/kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace fivebar {
namespace {

// Interior angle at the motor between the chord M->P (length d) and the driving link a, from the
// law of cosines; nullopt outside the annulus |a-b| <= d <= a+b (with kReachToleranceMm slack).
std::optional<double> elbowAngle(double a, double b, double d) {
  const double outer = a + b, inner = std::abs(a - b);
  if (!(d <= outer + kReachToleranceMm) || d < inner - kReachToleranceMm) return std::nullopt;
  if (d < 1e-12) return std::nullopt;  // target on the motor axis: direction undefined
  const double c = (a * a + d * d - b * b) / (2.0 * a * d);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double angleBetween(const Vec2& u, const Vec2& v) {
  return std::atan2(std::abs(cross(u, v)), u.dot(v));
}

}  // namespace

std::optional<double> inverseArm1(const Geometry& g, const Vec2& p, ArmSign sign) {
  const Vec2 c = p - g.motor1();
  const auto alpha = elbowAngle(g.a1, g.b1, c.norm());
  if (!alpha) return std::nullopt;
  const double chord = std::atan2(c.y(), c.x());
  // '+' puts R1 counter-clockwise of the chord M1->P.
  return normalizeRad(sign == ArmSign::Plus ? chord + *alpha : chord - *alpha);
}

std::optional<double> inverseArm2(const Geometry& g, const Vec2& p, ArmSign sign) {
  const Vec2 c = p - g.motor2();
  const auto alpha = elbowAngle(g.a2, g.b2, c.norm());
  if (!alpha) return std::nullopt;
  const double chord = std::atan2(c.y(), c.x());
  // '+' puts R2 clockwise of the chord M2->P.
  return normalizeRad(sign == ArmSign::Plus ? chord - *alpha : chord + *alpha);
}

IkResult inverse(const Geometry& g, const Vec2& p, WorkingMode mode) {
  const auto t1 = inverseArm1(g, p, arm1Sign(mode));
  const auto t2 = inverseArm2(g, p, arm2Sign(mode));
  if (!t1 || !t2) return {};
  return {IkStatus::Ok, {*t1, *t2}};
}

Vec2 elbow1(const Geometry& g, double theta1) {
  return g.motor1() + g.a1 * Vec2(std::cos(theta1), std::sin(theta1));
}
Vec2 elbow2(const Geometry& g, double theta2) {
  return g.motor2() + g.a2 * Vec2(std::cos(theta2), std::sin(theta2));
}

FkResult forward(const Geometry& g, const JointAngles& q, AssemblyMode mode) {
  const Vec2 R1 = elbow1(g, q.theta1), R2 = elbow2(g, q.theta2);
  const Vec2 r = R2 - R1;
  const double d = r.norm();
  if (d < 1e-12) return {FkStatus::Degenerate, Vec2::Zero()};  // coincident elbows: P undefined
  if (d > g.b1 + g.b2 + kReachToleranceMm || d < std::abs(g.b1 - g.b2) - kReachToleranceMm)
    return {FkStatus::CannotClose, Vec2::Zero()};
  const Vec2 u = r / d;
  const Vec2 left(-u.y(), u.x());
  // Distance from R1 along R1->R2 to the chord of the two circles, and half the chord.
  const double along = (g.b1 * g.b1 - g.b2 * g.b2 + d * d) / (2.0 * d);
  // Half-chord from the product form ((b1+b2)^2 - d^2)(d^2 - (b1-b2)^2) / (4 d^2): no cancellation
  // of two nearly equal squares near the type II singularity, where h -> 0.
  const double sum = g.b1 + g.b2, diff = g.b1 - g.b2;
  const double h2 = (sum - d) * (sum + d) * (d - diff) * (d + diff) / (4.0 * d * d);
  const double h = std::sqrt(std::max(0.0, h2));
  const double s = mode == AssemblyMode::Plus ? 1.0 : -1.0;
  return {FkStatus::Ok, R1 + along * u + s * h * left};
}

Pose makePose(const Geometry& g, const JointAngles& q, const Vec2& p) {
  return {q, elbow1(g, q.theta1), elbow2(g, q.theta2), p};
}

WorkingMode workingModeOf(const Geometry& g, const Pose& pose) {
  const bool plus1 = cross(pose.P - g.motor1(), pose.R1 - g.motor1()) >= 0.0;
  const bool plus2 = cross(pose.R2 - g.motor2(), pose.P - g.motor2()) >= 0.0;
  return workingModeFromSigns(plus1 ? ArmSign::Plus : ArmSign::Minus,
                              plus2 ? ArmSign::Plus : ArmSign::Minus);
}

AssemblyMode assemblyModeOf(const Pose& pose) {
  return cross(pose.R2 - pose.R1, pose.P - pose.R1) >= 0.0 ? AssemblyMode::Plus
                                                           : AssemblyMode::Minus;
}

PassiveAngles passiveAngles(const Pose& pose) {
  const Vec2 d1 = pose.P - pose.R1, d2 = pose.P - pose.R2;
  return {std::atan2(d1.y(), d1.x()), std::atan2(d2.y(), d2.x())};
}

TransmissionAngles transmissionAngles(const Geometry& g, const Pose& pose) {
  return {angleBetween(pose.R1 - pose.P, pose.R2 - pose.P),
          angleBetween(pose.R1 - g.motor1(), pose.P - pose.R1),
          angleBetween(pose.R2 - g.motor2(), pose.P - pose.R2)};
}

}  // namespace fivebar
