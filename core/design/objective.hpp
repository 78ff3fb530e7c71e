// What a design search minimises, and the penalty that ranks designs that break a rule below
// every design that keeps them all (docs/design.md "Search").
#pragma once

#include <optional>
#include <string_view>

#include "core/design/evaluation.hpp"

namespace fivebar::design {

enum class Objective {
  Condition,   // worst-case condition number over the rectangle (1 = isotropic)
  Resolution,  // worst pen travel per motor step, mm
  Footprint,   // area of the machine's bounding box over the rectangle's poses, mm^2
};

std::string_view toString(Objective o);  // "condition", "resolution", "footprint"
std::optional<Objective> parseObjective(std::string_view text);

// The measure an objective minimises.
double objectiveValue(Objective o, const DesignMeasures& m);

// Every design that breaks a rule scores above this; the excess is its scaled violation.
inline constexpr double kInfeasibleScore = 1e6;
// Angles in the violation are scaled by this length (mm per rad) to add up with mm.
inline constexpr double kViolationScaleMm = 100.0;

// objectiveValue for a feasible evaluation, kInfeasibleScore + violation otherwise.
double penalisedScore(Objective o, const Evaluation& e);

}  // namespace fivebar::design
