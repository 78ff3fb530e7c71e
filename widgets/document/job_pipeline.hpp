// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's planning, run off the UI thread whenever the document changes: core's planJob at
// the document's fixed placement (job/job_source.hpp, the same call `fivebar plan` makes),
// then the paint-ready scenes and the timed trajectory of its result. Pure function of its
// inputs; no Qt object is touched.
#pragma once

#include <QPointF>
#include <QString>
#include <QStringList>
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include "core/machine/profile.hpp"
#include "core/planning/drawing.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/stage_times.hpp"
#include "core/planning/trajectory.hpp"
#include "job/job_source.hpp"
#include "widgets/canvas/job_scenes.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

struct PipelineInput {
  std::shared_ptr<const Drawing> drawing;  // shared with the document, never copied per plan
  job::DrawingSource source;  // to import the drawing again more finely when the planner asks
  Placement placement;
  MachineProfile profile;
  ModeSelection modeSelection;
  double toleranceMm = 0.1;
  std::shared_ptr<std::atomic<bool>> cancel;  // may be null
};

// The planner options the studio plans a document with (Run, Export G-code, --export-gcode).
PlanOptions studioPlanOptions(const Placement& placement, ModeSelection mode, double toleranceMm);

enum class PreviewStatus { Planned, Infeasible, Empty, Failed, Cancelled };

// One planning problem, ready for the problems list.
struct PreviewProblem {
  QString text;        // where (layer by name, path) and why
  QStringList fixes;   // what to do, in plain words
  QPointF whereMm;     // machine frame
  int layerIndex = -1; // the offending path; -1 for a travel
  int pathIndex = -1;
};

struct PreviewResult {
  PreviewStatus status = PreviewStatus::Empty;
  QString message;                       // one line for the status bar
  std::optional<WorkingMode> mode;       // mode planned in (Auto: the pick)
  double minMarginRad = 0.0;             // worst type II margin of the plan (or of the preflight)
  std::vector<PreviewProblem> problems;
  // Placed strokes, offending ones flagged: set when there is no job (a planned job's own scene
  // shows its drawing).
  std::shared_ptr<const PathScene> drawingScene;
  std::shared_ptr<const PlannedJob> job;          // set when planned
  std::shared_ptr<const Trajectory> trajectory;   // set when planned
  std::shared_ptr<const PathScene> jobScene;      // moves; order = move index
  PlanReport report;
  // Set when the planner needed the drawing flattened more finely: the drawing planned.
  std::shared_ptr<const Drawing> refinedDrawing;
  // Wall and CPU time of each stage: the planner's (PlanResult::timings), then the studio's own
  // ("job scene"; "drawing scene" when not planned).
  StageTimes timings;
};

PreviewResult runPipeline(const PipelineInput& input);

// A job is long when estimated over kLongJobS or over kLongJobSegments pen-down moves: Run asks
// before it starts one.
inline constexpr double kLongJobS = 8.0 * 3600.0;
inline constexpr int kLongJobSegments = 2000000;
// The question to ask before running `job`, empty when it is not long.
QString longJobQuestion(const PlannedJob& job);

}  // namespace fivebar::widgets
