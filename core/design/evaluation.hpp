// SPDX-License-Identifier: GPL-3.0-or-later
// Design evaluation: how well one five-bar geometry, in one working mode, serves a target
// rectangle placed in the machine frame (docs/design.md). Headless, millimetres and radians.
//
// The rectangle is sampled on a lattice (edges and corners included) and every sample is
// evaluated with the core's exact per-point evaluation (workspace evaluatePoint: reach, type I
// and type II margins, conditioning, resolution) plus the pose (inverse kinematics, elbows) and
// the Cartesian Jacobian J = A^-1 B (core/kinematics/singularity.hpp) for the motor speeds.
//
// Condition number: kappa = sigma_max(J) / sigma_min(J) of J, the map from motor rates
// (rad/s) to pen velocity (mm/s). Every entry of J is in mm/rad, so kappa is dimensionally
// consistent and independent of the unit chosen: 1 is isotropic (the pen moves equally well in
// every direction), infinity is a singularity.
#pragma once

#include <string>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar::design {

// The rules a design must keep besides its lengths (the "brief" without the bounds).
struct DesignRules {
  WorkspaceSettings workspace;   // joint limits, type II / type I margins, motor step angles
  double clearanceMm = 10.0;     // Hoang criterion 1: w >= a1 + a2 + clearanceMm
  double penSpeedMmPerS = 40.0;  // pen speed for the worst motor speed measure
  double minRectangleYMm = 0.0;  // the rectangle stays on the work side: yMin >= this
};

// Lattice spacing of the rectangle samples.
struct Sampling {
  double spacingMm = 1.0;  // samples at most this far apart along each side (edges included)
};

// Everything measured over the placed rectangle. Angles in rad, lengths in mm.
struct DesignMeasures {
  int samples = 0;
  int unreachableSamples = 0;          // samples outside the mode's reach or joint limits
  double minReachSlackMm = 0.0;        // > 0: every sample inside the reach (approximate mm)
  double minTypeIMarginRad = 0.0;      // closest approach to a leg stretched or folded
  double minTypeIIMarginRad = 0.0;     // closest approach to the floating links aligned; this is
                                       // also the minimum transmission angle min(mu, pi - mu)
  double worstCondition = 0.0;         // max kappa over the samples (infinity when singular)
  double meanCondition = 0.0;          // mean kappa over the samples
  double worstMmPerStep = 0.0;         // largest pen travel for one motor (micro)step
  double worstMotorSpeedRadPerS = 0.0; // fastest motor rate needed to move the pen at
                                       // penSpeedMmPerS in the worst direction
  double drivingLinkSpacingMm = 0.0;   // w - a1 - a2 (criterion 1 holds when >= clearance)
  double minDrivingLinkDistanceMm = 0.0;  // closest approach of the two driving links over
                                          // the rectangle's poses
  double footprintMm2 = 0.0;           // bounding box of motors, elbows and rectangle
  Rect footprint;                      // that bounding box
  double rectangleAreaMm2 = 0.0;       // the target rectangle's area
  double stepRad = 0.0;                // the larger of the two motor step angles
  // Criterion 1: the driving links can collide when they can come closer than the clearance:
  // w < a1 + a2 + clearance (they can when rotating fully; joint limits would then have to
  // keep them to the rectangle's poses, which minDrivingLinkDistanceMm describes).
  bool armsCanCollide = false;
};

// How far a design is from meeting the rules; all zero when it meets them.
struct Violations {
  double reachMm = 0.0;         // worst sample's distance outside the reach
  double typeIRad = 0.0;        // type I margin missing at the worst sample
  double typeIIRad = 0.0;       // type II margin missing at the worst sample
  double clearanceMm = 0.0;     // a1 + a2 + clearance - w when positive
  double workSideMm = 0.0;      // how far the rectangle reaches below minRectangleYMm
  double lengthsMm = 0.0;       // a negative or zero length
  bool any() const {
    return reachMm > 0 || typeIRad > 0 || typeIIRad > 0 || clearanceMm > 0 || workSideMm > 0 ||
           lengthsMm > 0;
  }
  // One number for optimisers: each violation scaled to about mm (angles times scaleMm).
  double total(double scaleMm) const;
  // Which rule is missed most (scaled like total): "reach", "typeI", "typeII", "clearance",
  // "workSide", "lengths"; empty when none.
  std::string binding(double scaleMm) const;
};

struct Evaluation {
  DesignMeasures measures;
  Violations violations;
  bool feasible() const { return !violations.any(); }
};

// Samples of a rectangle: (nx+1) x (ny+1) points at most spacingMm apart, edges included.
std::vector<Vec2> rectangleSamples(const Rect& r, double spacingMm);

// Evaluates geometry g in `mode` over rectangle `r` (machine frame).
Evaluation evaluateDesign(const Geometry& g, WorkingMode mode, const Rect& r,
                          const DesignRules& rules, const Sampling& sampling = {});

// The condition number kappa >= 1 of a 2x2 matrix (infinity when singular).
double conditionNumber(double m00, double m01, double m10, double m11);

}  // namespace fivebar::design
