// SPDX-License-Identifier: GPL-3.0-or-later
// The paint-ready scenes of the studio's planning results (canvas/path_scene.hpp): the placed
// strokes of a drawing with the offending ones flagged, and a planned job's moves. Built off the UI
// thread by the job pipeline; pure functions of their inputs.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/planning/job.hpp"
#include "core/planning/strokes.hpp"
#include "widgets/canvas/path_scene.hpp"

namespace fivebar::widgets {

// The placed strokes, the paths named in `flagged` ({layer index, path index}) marked as problems;
// order = point index.
std::shared_ptr<PathScene> drawingSceneOf(const std::vector<Stroke>& strokes,
                                          const std::vector<std::pair<int, int>>& flagged);

// Paint-ready scene of a planned job: one path per run of Draw or Travel moves, order = move
// index, per-segment speed = planned feed.
std::shared_ptr<PathScene> jobSceneOf(const PlannedJob& job);

}  // namespace fivebar::widgets
