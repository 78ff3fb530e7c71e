// SPDX-License-Identifier: GPL-3.0-or-later
// planStrokes: placed strokes -> PlannedJob (segmentation, feeds, travel, tool commands, timing);
// the moves themselves come from MotionPlanner (motion_planner.hpp).
#include <algorithm>
#include <cmath>

#include "core/planning/backlash_compensation.hpp"
#include "core/planning/motion_planner.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/time_estimate.hpp"
#include "core/planning/time_optimal.hpp"

namespace fivebar {
namespace {

using motion::kGcodeAngleDecimals;
using motion::MotionPlanner;

// Lever arm factor of the older estimate of the G-code rounding error, used when it is smaller
// than the bound from the type II margin (gcodeRoundingBoundMm).
constexpr double kRoundingLeverFactor = 4.0;

}  // namespace

double gcodeRoundingBoundMm(const MachineProfile& profile) {
  // Each angle is rounded to kGcodeAngleDecimals of a degree: |dtheta|_2 <= sqrt(2) * half a unit.
  // The pen moves by dP = A^-1 B dtheta (conventions.md, Hoang eq. 7): the rows of A are
  // (P - R_i), of length b_i, det A = b1 b2 sin(phi) with phi the angle between the distal links
  // (|sin phi| >= sin(type II margin) at every planned target), so |A^-1| <= sqrt(b1^2 + b2^2) /
  // (b1 b2 sin(margin)); |B_ii| <= a_i b_i. Without a usable margin the older lever estimate.
  const Geometry& g = profile.geometry;
  const double dThetaRad = std::sqrt(2.0) * radFromDeg(0.5 * std::pow(10.0, -kGcodeAngleDecimals));
  const double lever = kRoundingLeverFactor * std::max(g.a1 + g.b1, g.a2 + g.b2);
  const double sinMargin = std::sin(std::min(profile.typeIIMarginRad, kPi / 2.0));
  if (!(sinMargin > 0.0)) return lever * dThetaRad;
  const double jacobian = std::hypot(g.b1, g.b2) / (g.b1 * g.b2 * sinMargin) *
                          std::max(g.a1 * g.b1, g.a2 * g.b2);
  return std::min(lever, jacobian) * dThetaRad;
}

// Tolerance left for the joint-linear deviation of a stroke once its flattening is paid (the
// G-code rounding is part of the measured deviation: the moves are segmented between rounded
// angles).
double jointDeviationBudgetMm(const MachineProfile&, const PlanOptions& options, bool flattened) {
  return options.toleranceMm - (flattened ? options.flatteningToleranceMm : 0.0);
}

PlanResult planStrokes(const std::vector<Stroke>& strokes, const std::vector<Layer>& layers,
                       const MachineProfile& profile, WorkingMode mode,
                       const PlanOptions& options) {
  PlanResult out;
  out.report.mode = mode;
  out.report.toleranceMm = options.toleranceMm;
  const bool anyFlattened = std::any_of(strokes.begin(), strokes.end(),
                                       [](const Stroke& s) { return s.flattened; });
  // Below the worst case of the G-code rounding no tolerance can be promised (the rounding is
  // measured move by move, but a budget under its bound would fail somewhere as "cannot follow").
  double largestBridgeMm = 0.0;
  for (const Stroke& s : strokes) largestBridgeMm = std::max(largestBridgeMm, s.bridgedGapMm);
  const double budget = jointDeviationBudgetMm(profile, options, anyFlattened) - 0.5 * largestBridgeMm;
  if (!(budget > gcodeRoundingBoundMm(profile)) || !(options.toleranceMm > 0.0)) {
    out.status = PlanStatus::BadOptions;
    out.message = FB_TR("Planner", "tolerance %1 mm leaves nothing for the moves after flattening "
                                   "(%2 mm) and the G-code rounding (up to %3 mm)")
                      .arg(options.toleranceMm, 6)
                      .arg(anyFlattened ? options.flatteningToleranceMm : 0.0, 6)
                      .arg(gcodeRoundingBoundMm(profile), 6);
    return out;
  }
  StageClock clock(out.timings);
  MotionPlanner planner(strokes, layers, profile, mode, options, out);
  planner.run(jointDeviationBudgetMm(profile, options, false),
              jointDeviationBudgetMm(profile, options, true));
  clock.lap("segmentation, feeds, travel");
  // Backlash compensation (backlash_compensation.hpp): only when the profile's calibration has
  // play, so a job without it is byte-identical to before.
  if (profile.calibration && out.report.problems.empty()) {
    const MotorPlay play{profile.calibration->backlashRad1, profile.calibration->backlashRad2};
    if (!play.none()) {
      const BacklashPass pass = compensateBacklash(out.job, profile, play);
      if (!pass.ok)
        out.report.problems.push_back(
            {FB_TR("Planner", "backlash compensation"), pass.problem.where, pass.message,
             {PlanFix{FixKind::AwayFromEdge}}});
      clock.lap("backlash compensation");
    }
  }
  if (options.cancel != nullptr && options.cancel->load()) {
    out.status = PlanStatus::Cancelled;
    out.message = FB_TR("Planner", "planning cancelled");
    out.job = PlannedJob();
    return out;
  }
  fillJobTimes(out.job, profile);
  clock.lap("time estimate");
  if (out.job.moves.size() <= kTimeOptimalMaxMoves) {
    std::vector<double> layerSpeeds;
    for (const Layer& l : layers) layerSpeeds.push_back(l.tool.drawSpeedMmPerS);
    out.job.summary.timeOptimalS = timeOptimalJob(out.job, profile, layerSpeeds).totalS();
    clock.lap("time-optimal reference");
  }
  PlanReport& r = out.report;
  const JobSummary& s = out.job.summary;
  r.feasible = r.problems.empty();
  r.estimatedTimeS = s.estimatedTimeS;
  r.timeOptimalS = s.timeOptimalS;
  r.penDownMm = s.penDownMm;
  r.travelMm = s.travelMm;
  r.segments = s.segments;
  r.jointDeviationMm = s.maxDeviationMm;
  r.flatteningMm = planner.maxFlatteningMm_;
  r.bridgedGapMm = planner.maxBridgedGapMm_;
  r.roundingMm = 0.0;  // measured: part of the joint deviation (moves between rounded angles)
  r.maxDeviationMm = s.segments > 0 ? planner.maxStrokeDeviationMm_ : 0.0;
  r.minSingularityMarginDeg = degFromRad(s.minTypeIIMarginRad);
  r.feedLimitedSegments = s.feedLimitedSegments;
  out.status = r.feasible ? PlanStatus::Ok : PlanStatus::Infeasible;
  if (!r.feasible)
    out.message = FB_TR("Planner", "%1: %2").arg(r.problems.front().path).arg(r.problems.front().why);
  return out;
}

}  // namespace fivebar
