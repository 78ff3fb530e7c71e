// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration a profile carries (issue 13): what a fit of measured marks found out about the
// real machine beyond its link lengths (which the fit writes into the profile's geometry).
// Stored as the profile's versioned "calibration" section (docs/profile-schema.md); radians and
// millimetres here, degrees in the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"

namespace fivebar {

// A pen that is not at the distal joint P but rigidly fixed to floating link b1, in that link's
// frame: `alongMm` along R1 -> P (beyond P when positive), `normalMm` 90 deg counter-clockwise
// from that direction (machine frame, y up). Pen = P + alongMm * e + normalMm * n.
struct PenOffset {
  double alongMm = 0.0;
  double normalMm = 0.0;
  bool operator==(const PenOffset&) const = default;
};

// Statistics of the fit that produced a calibration (docs/calibration.md).
struct CalibrationFitStats {
  int marksUsed = 0;             // marks in the final fit (outliers and held-out marks excluded)
  int heldOutMarks = 0;          // marks kept out of the fit to measure the after-error honestly
  double rmsResidualMm = 0.0;    // RMS distance between fitted and measured mark positions
  double maxResidualMm = 0.0;    // largest such distance among the fitted marks
  double heldOutErrorMm = 0.0;   // RMS error on the held-out marks (0 when there are none)
  std::vector<std::string> outlierIds;  // marks rejected as mis-measured, by id
  bool operator==(const CalibrationFitStats&) const = default;
};

struct MachineCalibration {
  static constexpr int kSchemaVersion = 1;
  int version = kSchemaVersion;
  // True (kinematic) motor angle = commanded angle (as sent in G-code) + offset.
  double zeroOffsetRad1 = 0.0;
  double zeroOffsetRad2 = 0.0;
  // Slack of each motor's drive, taken up when the motor reverses (>= 0).
  double backlashRad1 = 0.0;
  double backlashRad2 = 0.0;
  std::optional<PenOffset> penOffset;  // absent: the pen is at P
  std::string date;                    // ISO 8601, e.g. "2026-12-01T22:30:00Z"
  CalibrationFitStats fit;
  bool operator==(const MachineCalibration&) const = default;
};

// The one conversion between the angles G-code, jog, GRBL and the profile's home and limits speak
// (commanded) and the angles the kinematics works with (kinematic = commanded + zero offset).
// Without a calibration both are the same.
inline JointAngles kinematicFromCommanded(const std::optional<MachineCalibration>& c,
                                          const JointAngles& commanded) {
  if (!c) return commanded;
  return {commanded.theta1 + c->zeroOffsetRad1, commanded.theta2 + c->zeroOffsetRad2};
}
inline JointAngles commandedFromKinematic(const std::optional<MachineCalibration>& c,
                                          const JointAngles& kinematic) {
  if (!c) return kinematic;
  return {kinematic.theta1 - c->zeroOffsetRad1, kinematic.theta2 - c->zeroOffsetRad2};
}
// The profile's joint limits, which are on commanded angles (GRBL's soft limits count commanded
// steps), as bounds of the kinematic angles: each corner converted with kinematicFromCommanded.
// For searches that walk kinematic angles (a box to search in); a single pose is checked by
// converting it to commanded angles instead.
inline JointLimits kinematicLimits(const std::optional<MachineCalibration>& c, const JointLimits& commanded) {
  const JointAngles lo = kinematicFromCommanded(c, {commanded.theta1Min, commanded.theta2Min});
  const JointAngles hi = kinematicFromCommanded(c, {commanded.theta1Max, commanded.theta2Max});
  return {lo.theta1, hi.theta1, lo.theta2, hi.theta2};
}

}  // namespace fivebar
