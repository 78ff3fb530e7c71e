// SPDX-License-Identifier: GPL-3.0-or-later
// Design results as JSON (the `fivebar design --json` file, docs/design.md "Output") and as a
// machine profile (core/machine/profile.hpp) ready to save.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/design/search.hpp"
#include "core/machine/profile.hpp"

namespace fivebar::design {

// {"geometry": {a1, b1, a2, b2, w}, "workingMode", "rectangle": {xMinMm, ...}, "rotated",
//  "feasible", "measures": {...}} for one design. Degrees and mm.
nlohmann::json designJson(const Design& d);

// The whole answer: the brief, the best design's fields at top level, "pareto": [designJson...],
// the search's evaluations and seconds.
nlohmann::json searchJson(const DesignBrief& brief, const SearchResult& r, const SearchOptions& o);

// A complete, valid profile for a design: the geometry, the working mode, the brief's margins,
// joint limits around the rectangle's poses (20 deg beyond them, under one turn, so that the
// limits also keep the driving links to the poses the rectangle needs) and a home pose at the
// rectangle's centre. Motors, tool and speeds from `base` (default: the maker-plotter preset).
MachineProfile designProfile(const Design& d, const DesignBrief& brief, const std::string& name,
                             const MachineProfile* base = nullptr);

}  // namespace fivebar::design
