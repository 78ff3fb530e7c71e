// SPDX-License-Identifier: GPL-3.0-or-later
// The pen's kinematics (issue 13): where a profile's pen is for given motor angles, and the motor
// angles that put it on a point, honouring the calibrated pen offset (calibration.hpp PenOffset:
// a pen rigidly fixed to floating link b1, not at the distal joint P). Planning, pre-flight, jog
// and the simulation convert between pen positions and motor angles here and nowhere else;
// without a pen offset every function is the plain inverse() / forward() of P.
// Machine frame, millimetres, KINEMATIC angles in radians (commanded angles convert through
// calibration.hpp). Derivation: docs/calibration.md "Pen offset".
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/calibration.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {

// The profile's calibrated pen offset (nullopt: the pen is at P).
inline const std::optional<PenOffset>& calibratedPenOffset(const MachineProfile& p) {
  static const std::optional<PenOffset> kNone;
  return p.calibration ? p.calibration->penOffset : kNone;
}

// The pen for a pose whose elbow of leg 1 is R1 and distal joint P (|P - R1| = b1):
// pen = P + alongMm * e + normalMm * n, e = (P - R1) / b1, n = e turned 90 deg counter-clockwise.
Vec2 penFromDistal(const std::optional<PenOffset>& pen, const Geometry& g, const Vec2& R1, const Vec2& P);

// Forward kinematics of the pen at kinematic angles q in `assembly` (status as forward()).
FkResult penForward(const Geometry& g, const std::optional<PenOffset>& pen, const JointAngles& q,
                    AssemblyMode assembly);

// Kinematic angles (in (-pi, pi]) that put the pen at `penXY` in working mode `mode`; the mode's
// arm signs are those of the pose, defined on P (conventions.md). `distal`, when given, receives
// P. Leg 1 reaches the pen as a two-link chain a1, c1 = |(b1 + along, normal)|; P follows on
// the rigid link, and leg 2 reaches P.
IkResult penInverse(const Geometry& g, const std::optional<PenOffset>& pen, const Vec2& penXY,
                    WorkingMode mode, Vec2* distal = nullptr);

// Which leg cannot reach a pen position that penInverse refuses: 1 or 2 (0 when both can).
int unreachableLeg(const Geometry& g, const std::optional<PenOffset>& pen, const Vec2& penXY, WorkingMode mode);

// Profile forms: profile.geometry, its calibrated pen offset, profile.assembly.
inline FkResult penForward(const MachineProfile& p, const JointAngles& q) {
  return penForward(p.geometry, calibratedPenOffset(p), q, p.assembly);
}
inline IkResult penInverse(const MachineProfile& p, const Vec2& penXY, WorkingMode mode, Vec2* distal = nullptr) {
  return penInverse(p.geometry, calibratedPenOffset(p), penXY, mode, distal);
}

// How far (mm) the path of P that draws a straight piece of a pen stroke may bow away from the
// chord between its two mapped ends before distalPath splits the piece.
inline constexpr double kDistalChordToleranceMm = 0.002;
// Shortest pen piece distalPath splits (mm).
inline constexpr double kDistalMinPieceMm = 0.01;

// A pen stroke mapped to the stroke of P that draws it (working mode `mode`): every pen vertex
// mapped exactly, a pen segment cut where the mapped path bows more than
// kDistalChordToleranceMm from the chord. nullopt (and `failedAt` = the pen point) when a
// point is out of reach.
std::optional<std::vector<Vec2>> distalPath(const Geometry& g, const PenOffset& pen, WorkingMode mode,
                                            std::span<const Vec2> penStroke, Vec2* failedAt = nullptr);

// Factor (>= 1) by which a deviation of P from its path can grow at the pen: a rotation of link b1
// by dphi moves the pen by |offset| dphi more than P, and |dphi| <= |dP| / (b1 sin mu1) with mu1
// the transmission angle at R1; the planner divides its deviation budget by this factor, taken
// at sin mu1 >= 1/2 (kPenLeverSinMu1), and measures the pen in its tests.
inline constexpr double kPenLeverSinMu1 = 0.5;
double penDeviationFactor(const Geometry& g, const std::optional<PenOffset>& pen);

}  // namespace fivebar
