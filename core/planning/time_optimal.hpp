// SPDX-License-Identifier: GPL-3.0-or-later
// The time-optimal reference of a job: how fast the machine could possibly run it, whatever the
// firmware. Every job time is reported as a ratio to it (docs/performance.md, the studio's job
// preview). Derivation: docs/planning.md, "Time-optimal reference".
//
// - Pen-down strokes: the phase-plane time-optimal parameterisation (the idea of TOPP / TOPP-RA)
//   of the drawn path p(s) (machine mm, arc length s) under each motor's speed and acceleration
//   limit and the asked pen speed: x = sdot^2 is maximised on a grid of s by a backward pass
//   (the largest x from which the rest of the path can still stop in time) and a forward pass
//   (the largest acceleration the limits allow), with the constraints
//     sdot <= asked,  |q_i'(s) sdot| <= vmax_i,  |q_i'(s) sddot + q_i''(s) sdot^2| <= amax_i.
//   The path starts and ends at rest, and stops at every sharp corner (a turn of more than
//   kSharpCornerRad); between them the tangent turns smoothly (the polyline approximates a
//   smooth curve: its tangent is interpolated from vertex to vertex).
// - Travels: each motor's fastest rest-to-rest move over its rotation along the travel (bang-bang
//   under its speed and acceleration limits); the slower motor gives the time.
// - The job's own dwells (pen settle times, G4), Z moves of a Z-axis pen as rest-to-rest moves.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/calibration.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/job.hpp"

namespace fivebar {

// The planner fills PlannedJob::summary.timeOptimalS for jobs of at most this many moves (about
// 0.1 s on the 2-core target); larger jobs are left at 0 (not computed): on the 1.8 M-move
// benchmark job it would cost about as much as the rest of the planning.
inline constexpr size_t kTimeOptimalMaxMoves = 200000;

// A turn of the drawn path sharper than this (rad) is a corner the pen stops at.
inline constexpr double kSharpCornerRad = 0.7854;  // 45 deg

struct MotorLimits {
  double maxSpeedRadPerS[2] = {3.0, 3.0};
  double maxAccelRadPerS2[2] = {20.0, 20.0};
};
MotorLimits motorLimitsOf(const MachineProfile& profile);

struct TimeOptimalOptions {
  double gridStepMm = 2.0;  // largest step of the phase-plane grid along the path
  double sharpCornerRad = kSharpCornerRad;
};

// Shortest time (s) to draw the polyline `pointsMm` (machine frame) from rest to rest in working
// mode `mode`, at most `askedMmPerS` along the path. Points out of reach are skipped.
double timeOptimalPathS(const Geometry& g, WorkingMode mode, std::span<const Vec2> pointsMm,
                        double askedMmPerS, const MotorLimits& limits,
                        const TimeOptimalOptions& options = {});
// The same for the pen of a calibrated pen offset (pen_kinematics.hpp): `pointsMm` is the pen's
// path; the motors' rates are those that move the pen along it (nullopt: the pen is at P).
double timeOptimalPathS(const Geometry& g, const std::optional<PenOffset>& pen, WorkingMode mode,
                        std::span<const Vec2> pointsMm, double askedMmPerS, const MotorLimits& limits,
                        const TimeOptimalOptions& options = {});

// Shortest time (s) for one motor to rotate by `distanceRad` from rest to rest.
double restToRestS(double distanceRad, double maxSpeed, double maxAccel);

struct TimeOptimalJob {
  double drawS = 0.0;    // pen-down strokes
  double travelS = 0.0;  // travels (and Z moves of a Z-axis pen)
  double dwellS = 0.0;   // the job's dwells
  double totalS() const { return drawS + travelS + dwellS; }
};

// The reference of a planned job: its strokes (the XY waypoints of its Draw moves, which lie on
// the drawing's flattened geometry) at the pen speed of their layer, its travels and dwells.
// drawSpeedByLayerMmPerS[layer] is the asked pen speed (missing or <= 0: the profile's).
TimeOptimalJob timeOptimalJob(const PlannedJob& job, const MachineProfile& profile,
                              std::span<const double> drawSpeedByLayerMmPerS = {},
                              const TimeOptimalOptions& options = {});

}  // namespace fivebar
