// SPDX-License-Identifier: GPL-3.0-or-later
// Exact scalar inverse and forward kinematics of a general (asymmetric) five-bar.
// Derivation and symbols: docs/kinematics.md. Radians and millimetres, machine frame.
#pragma once

#include <optional>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

struct JointAngles {
  double theta1 = 0.0;  // motor 1, rad, counter-clockwise from +x
  double theta2 = 0.0;  // motor 2, rad
  bool operator==(const JointAngles&) const = default;
};

// How close to the reach boundary (mm) a target may lie outside it and still be treated as
// on it: absorbs rounding so that acos never sees 1 + 1e-16.
inline constexpr double kReachToleranceMm = 1e-9;

enum class IkStatus { Ok, OutOfReach };
struct IkResult {
  IkStatus status = IkStatus::OutOfReach;
  JointAngles angles;  // valid when status == Ok; angles in (-pi, pi]
  bool ok() const { return status == IkStatus::Ok; }
};

enum class FkStatus { Ok, CannotClose, Degenerate };
struct FkResult {
  FkStatus status = FkStatus::CannotClose;
  Vec2 p = Vec2::Zero();  // end-effector, valid when status == Ok
  bool ok() const { return status == FkStatus::Ok; }
};

// Motor angle of one arm reaching `p` with the given elbow sign. nullopt when out of reach.
std::optional<double> inverseArm1(const Geometry& g, const Vec2& p, ArmSign sign);
std::optional<double> inverseArm2(const Geometry& g, const Vec2& p, ArmSign sign);

IkResult inverse(const Geometry& g, const Vec2& p, WorkingMode mode);
FkResult forward(const Geometry& g, const JointAngles& q, AssemblyMode mode);

// Elbow points.
Vec2 elbow1(const Geometry& g, double theta1);
Vec2 elbow2(const Geometry& g, double theta2);

// A complete pose: motor angles, elbows and end-effector, all consistent.
struct Pose {
  JointAngles q;
  Vec2 R1 = Vec2::Zero();
  Vec2 R2 = Vec2::Zero();
  Vec2 P = Vec2::Zero();
};
Pose makePose(const Geometry& g, const JointAngles& q, const Vec2& p);

// Branch identification of a pose (conventions.md). Exactly on a singularity the sign is '+'.
WorkingMode workingModeOf(const Geometry& g, const Pose& pose);
AssemblyMode assemblyModeOf(const Pose& pose);

// Passive angles: direction of each floating link Ri->P, rad, counter-clockwise from +x.
struct PassiveAngles {
  double phi1 = 0.0;
  double phi2 = 0.0;
};
PassiveAngles passiveAngles(const Pose& pose);

// Transmission angles, rad in [0, pi]:
//  mu  (at P)  angle between the floating links, P->R1 and P->R2: 0 or pi at a type II singularity;
//  mu1 (at R1) angle between M1->R1 continued and R1->P: 0 or pi at a type I singularity of leg 1;
//  mu2 likewise for leg 2.
struct TransmissionAngles {
  double mu = 0.0;
  double mu1 = 0.0;
  double mu2 = 0.0;
};
TransmissionAngles transmissionAngles(const Geometry& g, const Pose& pose);

}  // namespace fivebar
