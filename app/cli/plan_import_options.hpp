// The import side of `fivebar plan`: import warnings on stderr, the point budget (--max-points)
// and fills (--fill outline|hatch|none, --hatch-spacing, --hatch-angle, --crosshatch,
// --no-hatch-outline). Kept apart from cmd_plan.cpp, which calls these few functions.
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>

#include "core/planning/drawing.hpp"
#include "core/planning/hatch.hpp"
#include "options.hpp"

namespace fivebar::cli {

inline constexpr std::size_t kDefaultMaxPoints = 2'000'000;

struct PlanImportSettings {
  std::size_t maxPoints = kDefaultMaxPoints;  // after flattening and hatching
  FillMode fill = FillMode::Outline;
  HatchSettings hatch;       // spacing 0.5 mm, angle 45 deg unless given
  bool warningsPrinted = false;  // the drawing may be imported twice (finer tolerance)
};

extern const char* const kPlanImportHelp;

// The option names above added to plan's own.
std::set<std::string> withImportValuedOptions(std::set<std::string> valued);
std::set<std::string> withImportFlags(std::set<std::string> flags);

// Throws UsageError naming the option for a bad value.
PlanImportSettings planImportSettingsFrom(const Options& options);

// Points of the visible layers.
std::size_t pointCount(const Drawing& drawing);

// Imports the SVG (flattened within toleranceMm), prints its warnings on stderr once
// ("fivebar plan: FILE: warning: line 3: <path id="p"> ..."), applies the fill mode to every layer
// and checks the point budget. Errors are printed; nullopt then.
std::optional<Drawing> importForPlan(const std::string& file, double toleranceMm,
                                     PlanImportSettings& settings);

}  // namespace fivebar::cli
