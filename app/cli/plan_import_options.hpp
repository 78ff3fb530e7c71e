// SPDX-License-Identifier: GPL-3.0-or-later
// The import side of `fivebar plan`: import warnings on stderr, the point budget (--max-points)
// and fills (--fill outline|hatch|none, --hatch-spacing, --hatch-angle, --crosshatch,
// --no-hatch-outline), dashes (--dashes dashed|solid) and text (--text-font NAME). Kept apart from cmd_plan.cpp, which calls these few functions.
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>

#include "core/planning/drawing.hpp"
#include "core/planning/hatch.hpp"
#include "options.hpp"

namespace fivebar::cli {

struct PlanImportSettings {
  std::size_t maxPoints = kDefaultMaxPoints;  // after flattening and hatching
  FillMode fill = FillMode::Outline;
  HatchSettings hatch;       // spacing 0.5 mm, angle 45 deg unless given
  bool solidDashes = false;  // --dashes solid: dashed strokes drawn whole
  std::string textFont;      // --text-font NAME: <text> redrawn in that Hershey font
};

extern const char* const kPlanImportHelp;

// The option names above added to plan's own.
std::set<std::string> withImportValuedOptions(std::set<std::string> valued);
std::set<std::string> withImportFlags(std::set<std::string> flags);

// Throws UsageError naming the option for a bad value.
PlanImportSettings planImportSettingsFrom(const Options& options);

// Points of the visible layers.
std::size_t pointCount(const Drawing& drawing);

// False, with the reason on stderr, when the drawing has more points than settings.maxPoints
// (after flattening and hatching): a guard against runaway files, raised with --max-points.
bool withinPointBudget(const std::string& file, const Drawing& drawing, const PlanImportSettings& settings);

}  // namespace fivebar::cli
