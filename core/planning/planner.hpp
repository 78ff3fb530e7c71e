// SPDX-License-Identifier: GPL-3.0-or-later
// The job pipeline: Drawing + PlanOptions + MachineProfile -> placement -> optimisation ->
// working-mode selection and preflight -> adaptive segmentation -> feeds -> travel -> tool
// commands -> GRBL time estimate -> PlannedJob + PlanReport. Design: docs/planning.md.
#pragma once

#include <functional>
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/planning/plan_fix.hpp"
#include "core/planning/job.hpp"
#include "core/planning/placement.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/stage_times.hpp"
#include "core/planning/strokes.hpp"
#include "core/support/message.hpp"
#include "core/planning/time_estimate.hpp"

namespace fivebar {

struct PlanOptions {
  std::optional<WorkingMode> mode;  // nullopt: auto (the feasible mode with the best margin)
  // Placement. With atMm (and not fit) it is fixed: the centre of the drawing's bounding box
  // goes to that machine point, scaled by `scale` (y by scale * stretchY) and rotated. Without
  // atMm the drawing is placed by autoPlacement (auto_placement.hpp): at true size when it
  // fits, scaled down when not; with fit it is scaled up or down to fill the rectangle.
  std::optional<Vec2> atMm;
  double scale = 1.0;
  double stretchY = 1.0;
  double rotationRad = 0.0;
  bool fit = false;
  // Total allowed distance (mm, machine frame) between the drawn curve and the true geometry,
  // spent on the import flattening (Drawing::flatteningToleranceMm times the placement scale),
  // the G-code rounding, and the joint-linear deviation of the moves (all the rest).
  double toleranceMm = 0.1;
  // planStrokes only: the flattening error of its (machine-frame) strokes. planJob sets it from
  // the drawing and the placement.
  double flatteningToleranceMm = 0.0;
  bool optimise = true;     // join, reverse and reorder strokes to cut travel time
  double minSegmentDurationS = 0.005;
  int maxListedProblems = 20;  // problems listed in an infeasible report
  // Set from another thread to stop planning early (status Cancelled); may be null.
  const std::atomic<bool>* cancel = nullptr;
};

// Share of the tolerance the importer should flatten curves with (docs/planning.md); a drawing
// flattened more coarsely than this share (at its placement scale) is refused with
// PlanStatus::CoarseDrawing, naming the flattening tolerance to import it with.
inline constexpr double kFlatteningShare = 0.4;

// Stroke joining (optimise.hpp) bridges gaps up to joinGapMm(tolerance) = min(kJoinGapMaxMm,
// kJoinGapShare x tolerance): a share of the budget, never more than the tolerance. Half of a
// stroke's largest bridged gap is charged to its deviation (Stroke::bridgedGapMm) and taken from
// its segmentation budget, so the bound stays within the tolerance.
inline constexpr double kJoinGapShare = 0.2;
inline constexpr double kJoinGapMaxMm = 0.05;
double joinGapMm(double toleranceMm);

// The flattening tolerance (work-frame mm) to import a drawing with, for a total tolerance and
// the placement's largest scale (max(scale, scale * stretchY); 1 before the placement is known).
double importToleranceMm(double toleranceMm, double placementScale = 1.0);

// Options that plan at this fixed placement.
void setFixedPlacement(PlanOptions& options, const Placement& placement);

// The texts are translatable messages (core/support/message.hpp); .text() is the English.
struct PlanProblem {
  Message path;   // "layer 'ink' path 3", "travel to layer 'ink' path 3", ...
  Vec2 whereMm = Vec2::Zero();
  Message why;
  std::vector<PlanFix> fixes;  // what to change: codes with their numbers (plan_fix.hpp)
  int layerIndex = -1;  // the offending path (drawing indices); -1 for travels and the job
  int pathIndex = -1;
};

struct PlanReport {
  bool feasible = false;
  WorkingMode mode = WorkingMode::PlusPlus;
  double estimatedTimeS = 0.0;
  // Time-optimal reference of the same strokes, travels and dwells under the motors' limits
  // (core/planning/time_optimal.hpp): estimatedTimeS / timeOptimalS is how far the job is from
  // what the machine can do. 0 when not computed (jobs over kTimeOptimalMaxMoves moves).
  double timeOptimalS = 0.0;
  double penDownMm = 0.0;
  double travelMm = 0.0;
  int segments = 0;
  // Bound of the distance between the drawn line and the drawing: the largest, over the drawn
  // strokes, of the joint-linear deviation of its moves (measured between the angles as the
  // G-code rounds them) + its flattening error at the placement scale (0 for straight lines)
  // + half the largest gap joining bridged in it (0 without joins over a gap).
  double maxDeviationMm = 0.0;
  double jointDeviationMm = 0.0;     // the joint-linear part alone (measured, largest)
  double flatteningMm = 0.0;         // the largest flattening error of a drawn stroke (machine mm)
  double bridgedGapMm = 0.0;         // the largest gap joining bridged in a drawn stroke (mm)
  // The G-code rounding reserve: 0, the rounding being measured in jointDeviationMm (kept for
  // REPORT.json readers; gcodeRoundingBoundMm is the bound it would be).
  double roundingMm = 0.0;
  double toleranceMm = 0.0;
  double minSingularityMarginDeg = 0.0;  // smallest type II margin at any planned target
  int feedLimitedSegments = 0;
  std::vector<PlanProblem> problems;
};

enum class PlanStatus {
  Ok = 0,
  EmptyDrawing = -1,  // nothing visible to draw
  Infeasible = -2,    // some stroke or travel cannot be planned safely (see report.problems)
  BadOptions = -3,    // tolerance, scale or profile not usable (message says which)
  CoarseDrawing = -4, // flattened too coarsely for the placement: import again with
                      // PlanResult::requiredFlatteningToleranceMm
  Cancelled = -5,     // PlanOptions::cancel was set
};

struct PlanResult {
  PlanStatus status = PlanStatus::BadOptions;
  Message message;       // first problem in one line, or empty when Ok
  PlannedJob job;        // complete when status == Ok
  PlanReport report;
  double placementScale = 1.0;  // work mm -> machine mm of the placement used (planJob)
  Placement placement;          // the placement used (planJob)
  Message placementNote;        // "scaled to 62 % to fit the workspace" when planJob scaled down
  double requiredFlatteningToleranceMm = 0.0;  // CoarseDrawing: work-frame mm to import with
  StageTimes timings;           // wall-clock seconds per pipeline stage
  bool ok() const { return status == PlanStatus::Ok; }
};

// The whole pipeline from a drawing in the work frame.
PlanResult planJob(const Drawing& drawing, const MachineProfile& profile,
                   const PlanOptions& options);

// The motion part only: strokes already placed in the machine frame, in plotting order, drawn in
// `mode`. `layers` gives per-layer tool overrides (may be empty: profile defaults).
PlanResult planStrokes(const std::vector<Stroke>& strokes, const std::vector<Layer>& layers,
                       const MachineProfile& profile, WorkingMode mode,
                       const PlanOptions& options);

// The share of options.toleranceMm left for the joint-linear deviation of a stroke's moves: the
// total minus its flattening error (options.flatteningToleranceMm, machine frame, for a stroke of
// flattened curves; 0 for a stroke whose points are its geometry). The G-code rounding needs no
// share: the moves are measured between the angles rounded as the G-code writes them.
double jointDeviationBudgetMm(const MachineProfile& profile, const PlanOptions& options,
                              bool flattened = true);
// Bound (mm) of how far the 4-decimal rounding of the G-code angles can move the pen (for
// comparison: the planner measures the rounding instead of reserving this).
double gcodeRoundingBoundMm(const MachineProfile& profile);

// REPORT.json text: mode, estimated_time_s, pen_down_mm, travel_mm, segments, max_deviation_mm,
// min_singularity_margin (deg), problems [{path, where, why, fixes, fix_kinds}], and a few more
// fields. `fixWords` words each fix (the CLI's words: app/cli/plan_words.hpp).
using FixWords = std::function<std::string(const PlanFix&)>;
std::string reportToJson(const PlanReport& report, const FixWords& fixWords);

}  // namespace fivebar
