// SPDX-License-Identifier: GPL-3.0-or-later
// The five-bar's fixed architecture (conventions.md): motor 1 at (-w/2, 0), motor 2 at (+w/2, 0),
// driving links a1, a2, floating links b1, b2, all in millimetres. A cheap immutable value.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/kinematics/units.hpp"
#include "core/support/message.hpp"

namespace fivebar {

using Vec2 = Eigen::Vector2d;

// 2-D cross product (z component): positive when b is counter-clockwise of a.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Geometry {
  double a1 = 0.0;  // driving link on motor 1, mm
  double b1 = 0.0;  // floating link from elbow R1 to the end-effector P, mm
  double a2 = 0.0;  // driving link on motor 2, mm
  double b2 = 0.0;  // floating link from elbow R2 to P, mm
  double w = 0.0;   // distance between the motor axes, mm (0 = coaxial)

  Vec2 motor1() const { return {-0.5 * w, 0.0}; }
  Vec2 motor2() const { return {0.5 * w, 0.0}; }
  bool operator==(const Geometry&) const = default;
};

// Per-motor joint limits, radians, on the continuous (unwrapped) motor angle. min < max.
struct JointLimits {
  double theta1Min = -kDefaultSpan;
  double theta1Max = kDefaultSpan;
  double theta2Min = -kDefaultSpan;
  double theta2Max = kDefaultSpan;
  static constexpr double kDefaultSpan = 1.0e9;  // effectively unlimited
  bool operator==(const JointLimits&) const = default;
};

// One problem found by validation: the field it concerns ("a1", "limits.theta1", ...) and a
// sentence a person can act on, translatable (message.text() is the English the CLI prints; the
// studio shows it in the user's language, i18n/translated.hpp).
struct ValidationIssue {
  std::string field;
  Message message;
};

// Checks lengths (positive, finite) and that the two legs can ever close a loop.
std::vector<ValidationIssue> validate(const Geometry& g);
// Checks limits (finite, ordered) and that they admit at least one closable pose of g.
std::vector<ValidationIssue> validate(const Geometry& g, const JointLimits& limits);

}  // namespace fivebar
