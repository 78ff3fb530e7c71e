// SPDX-License-Identifier: GPL-3.0-or-later
// The steps of `fivebar plan` on a drawing (SVG) or a project (.fivebar), shared by `plan` and
// `frame` (a drawing framed is planned exactly as plan plans it): the placement options (--mode,
// --at, --scale, --rotate, --fit, --tolerance, --no-optimise), the import options
// (plan_import_options.hpp), then job/job_source.hpp's load, place and plan.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "core/machine/profile.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/stage_times.hpp"
#include "options.hpp"

namespace fivebar::cli {

// The placement options' help, as `fivebar plan --help` prints it.
extern const char* const kPlacementHelp;

// The placement and import option names added to a command's own.
std::set<std::string> withPlacementValuedOptions(std::set<std::string> valued);
std::set<std::string> withPlacementFlags(std::set<std::string> flags);

// Throws UsageError naming the option for a bad value.
PlanOptions planOptionsFrom(const Options& options);

bool isProjectFile(const std::string& path);  // PROJECT.fivebar

struct PlannedDrawing {
  PlanResult result;       // may be infeasible: result.ok()
  MachineProfile profile;  // the machine it was planned for (--machine, else the project's)
};

// Loads, places and plans options.positional()[0] as `fivebar plan` does; `machine` replaces a
// project's machine and is required for a drawing. nullopt after saying why on stderr ("fivebar
// COMMAND: ..."); warnings go to stderr too. times (may be null) receives the stages.
std::optional<PlannedDrawing> planDrawing(const Options& options, const std::optional<MachineProfile>& machine,
                                          const std::string& command, StageTimes* times);

// The first problems of an infeasible plan and the first fix, on stderr.
void printPlanProblems(const std::string& command, const std::string& file, const PlanResult& result);

}  // namespace fivebar::cli
