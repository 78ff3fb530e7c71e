// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive segmentation: a stroke (machine-frame polyline, mm) becomes a sequence of joint-linear
// moves whose real drawn curve (forward kinematics along each move) stays within a deviation
// budget of the polyline, with moves as long as the kinematics allow. Design: docs/planning.md.
#pragma once

#include <span>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

struct SegmentationOptions {
  // Largest allowed distance (mm) between the FK curve of a joint-linear move and the stroke,
  // both ways (curve to polyline and skipped polyline vertices to curve).
  double deviationBudgetMm = 0.05;
  // Shortest piece a straight polyline segment is split into while searching (mm): below this
  // the segmentation gives up (the move cannot follow the stroke, e.g. across a singularity).
  double minPieceMm = 1e-4;
  // When >= 0: every waypoint's angles are rounded to this many decimals of a degree, as the
  // G-code will carry them, before its moves are measured, so the deviations are those of the
  // moves the machine is sent (the rounding is measured, not bounded). < 0: exact angles.
  int angleDecimalsDeg = -1;
  // A long straight segment split into pieces: the waypoints inside it are set off the line, by
  // this share of the budget, against the side the joint-linear moves bow to, so that each move's
  // curve spans the band on both sides of the line (-offset at its ends, up to the budget in its
  // middle) instead of one side only: pieces about sqrt(1 + share) longer. The deviation is still
  // measured against the line itself. 0: every waypoint on the stroke. The segment's vertices
  // (its ends) are never moved.
  double waypointOffsetShare = 0.9;
};

// One waypoint of a segmented stroke: the end of a joint-linear move (the first waypoint is the
// stroke's start). q is continuous (unwrapped near the previous waypoint).
struct JointWaypoint {
  JointAngles q;
  // Machine frame, mm: where q puts the pen. On the stroke, except inside a long straight segment
  // split into pieces (SegmentationOptions::waypointOffsetShare of the budget beside it).
  Vec2 p = Vec2::Zero();
  double deviationMm = 0.0;   // max deviation of the move ending here (0 for the first)
  double pathLengthMm = 0.0;  // stroke length covered by the move ending here (mm)
  // Largest XY speed along the move ending here, mm per unit of the move parameter u in [0, 1],
  // from the FK samples the deviation was measured with; 0 when not known (then planFeeds
  // samples the move itself).
  double peakSpeedMmPerUnit = 0.0;
};

enum class SegmentStatus {
  Ok = 0,
  OutOfReach = -1,    // a stroke point has no inverse kinematics in the working mode
  CannotFollow = -2,  // no joint-linear move however short follows the stroke (singular region)
};

struct SegmentedStroke {
  SegmentStatus status = SegmentStatus::Ok;
  std::vector<JointWaypoint> waypoints;  // waypoints[0] = stroke start; moves = size() - 1
  Vec2 failedAt = Vec2::Zero();          // where the first failure is (status != Ok)
  double maxDeviationMm = 0.0;
  bool ok() const { return status == SegmentStatus::Ok; }
};

// Segments `stroke` in working mode `mode`, FK in `assembly`; the first angles are unwrapped near
// `reference` (rad). Consecutive duplicate points are skipped; a one-point stroke is a dot.
SegmentedStroke segmentStroke(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                              std::span<const Vec2> stroke, const JointAngles& reference,
                              const SegmentationOptions& options);

// Firmware-style baseline for comparisons: every polyline segment cut into equal pieces no longer
// than `stepMm`, each piece a joint-linear move; deviations measured as in segmentStroke.
SegmentedStroke segmentFixedLength(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                                   std::span<const Vec2> stroke, const JointAngles& reference,
                                   double stepMm);

// Deviation (mm) of the joint-linear move qa -> qb (FK in `assembly`) from the polyline `chain`
// (chain.front() is where qa is, chain.back() where qb is): the larger of the curve-to-chain and
// chain-vertex-to-curve distances, plus a bound on what sampling misses. +infinity when the loop
// cannot close somewhere along the move.
double jointMoveDeviation(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                          const JointAngles& qb, std::span<const Vec2> chain);

}  // namespace fivebar
