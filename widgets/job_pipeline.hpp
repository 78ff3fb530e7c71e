// The studio's planning pipeline, run off the UI thread whenever the document changes:
// place the drawing, choose the working mode (Auto) and preflight it, optimise the stroke
// order, plan the motion with the core planner, time it into a Trajectory, and build the
// paint-ready scenes. Pure function of its inputs; no Qt object is touched.
#pragma once

#include <QPointF>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/trajectory.hpp"
#include "widgets/job_preflight.hpp"
#include "widgets/path_scene.hpp"
#include "widgets/studio_document.hpp"

namespace fivebar::widgets {

struct PipelineInput {
  Drawing drawing;
  Placement placement;
  MachineProfile profile;
  ModeSelection modeSelection;
  double toleranceMm = 0.1;
};

enum class PreviewStatus { Planned, Infeasible, Empty, Failed };

struct PreviewResult {
  PreviewStatus status = PreviewStatus::Empty;
  QString message;                       // one line for the status bar
  std::optional<WorkingMode> mode;       // mode planned in (Auto: the pick)
  double minMarginRad = 0.0;             // preflight worst type II margin in that mode
  std::vector<PreviewProblem> problems;
  std::shared_ptr<const PathScene> drawingScene;  // placed strokes, offending ones flagged
  std::shared_ptr<const PlannedJob> job;          // set when planned
  std::shared_ptr<const Trajectory> trajectory;   // set when planned
  std::shared_ptr<const PathScene> jobScene;      // moves; order = move index
  PlanReport report;
};

PreviewResult runPipeline(const PipelineInput& input);

// Paint-ready scene of a planned job: one path per run of Draw or Travel moves, order = move
// index, per-segment speed = planned feed.
std::shared_ptr<PathScene> jobSceneOf(const PlannedJob& job);

}  // namespace fivebar::widgets
