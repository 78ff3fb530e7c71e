// The job pipeline: Drawing + PlanOptions + MachineProfile -> placement -> optimisation ->
// working-mode selection and preflight -> adaptive segmentation -> feeds -> travel -> tool
// commands -> GRBL time estimate -> PlannedJob + PlanReport. Design: docs/planning.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/planning/job.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/stage_times.hpp"
#include "core/planning/strokes.hpp"

namespace fivebar {

struct PlanOptions {
  std::optional<WorkingMode> mode;  // nullopt: auto (the feasible mode with the best margin)
  // Placement: with atMm the centre of the drawing's bounding box goes to that machine point at
  // true size times `scale`; without it (or with fit) the drawing is fitted into the chosen
  // mode's largest singularity-free rectangle (then `scale` is ignored).
  std::optional<Vec2> atMm;
  double scale = 1.0;
  double rotationRad = 0.0;
  bool fit = false;
  double fitMarginMm = 1.0;
  // Total allowed distance (mm, machine frame) between the drawn curve and the true geometry,
  // shared by the import flattening, the G-code rounding and the joint-linear deviation of the
  // moves (the rest). flatteningToleranceMm is what the importer was asked for, in the frame of
  // the input: work-frame mm for planJob (scaled by the placement), machine mm for planStrokes.
  double toleranceMm = 0.1;
  double flatteningToleranceMm = 0.04;
  bool optimise = true;     // join, reverse and reorder strokes to cut travel time
  double minSegmentDurationS = 0.005;
};

// Share of the tolerance the importer should flatten curves with (docs/planning.md).
inline constexpr double kFlatteningShare = 0.4;

struct PlanProblem {
  std::string path;   // "layer 'ink' path 3", "travel before layer 'ink' path 3", ...
  Vec2 whereMm = Vec2::Zero();
  std::string why;
  std::vector<std::string> fixes;
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
  double maxDeviationMm = 0.0;       // joint-linear deviation of the drawn moves
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
};

struct PlanResult {
  PlanStatus status = PlanStatus::BadOptions;
  std::string message;   // first problem in one line, or empty when Ok
  PlannedJob job;        // complete when status == Ok
  PlanReport report;
  double placementScale = 1.0;  // work mm -> machine mm of the placement used (planJob)
  StageTimes timings;           // wall-clock seconds per pipeline stage
  bool ok() const { return status == PlanStatus::Ok; }
};

// The largest placement scale planJob can use for the drawing (the fitted scale of the best
// candidate mode; options.scale without fitting), so that a caller can flatten curves finely
// enough before planning. nullopt when nothing can be placed.
std::optional<double> largestPlacementScale(const Drawing& drawing, const MachineProfile& profile,
                                            const PlanOptions& options);

// The whole pipeline from a drawing in the work frame.
PlanResult planJob(const Drawing& drawing, const MachineProfile& profile,
                   const PlanOptions& options);

// The motion part only: strokes already placed in the machine frame, in plotting order, drawn in
// `mode`. `layers` gives per-layer tool overrides (may be empty: profile defaults).
PlanResult planStrokes(const std::vector<Stroke>& strokes, const std::vector<Layer>& layers,
                       const MachineProfile& profile, WorkingMode mode,
                       const PlanOptions& options);

// The share of options.toleranceMm left for the joint-linear deviation of the moves: the total
// minus the flattening share minus a bound on the G-code rounding error (4 decimals of a degree).
double jointDeviationBudgetMm(const MachineProfile& profile, const PlanOptions& options);

// REPORT.json text: mode, estimated_time_s, pen_down_mm, travel_mm, segments, max_deviation_mm,
// min_singularity_margin (deg), problems [{path, where, why, fixes}], and a few more fields.
std::string reportToJson(const PlanReport& report);

}  // namespace fivebar
