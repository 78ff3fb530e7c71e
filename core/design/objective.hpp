// SPDX-License-Identifier: GPL-3.0-or-later
// What a design search minimises, and the penalty that ranks designs that break a rule below
// every design that keeps them all (docs/design.md "Search").
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/design/evaluation.hpp"
#include "core/support/message.hpp"

namespace fivebar::design {

enum class Objective {
  Condition,   // worst-case condition number over the rectangle (1 = isotropic)
  Resolution,  // worst pen travel per motor step, mm
  Footprint,   // area of the machine's bounding box over the rectangle's poses, mm^2
  Mix,         // weighted sum of the three, each normalised (MixWeights, docs/design.md "Mix")
};

std::string_view toString(Objective o);  // "condition", "resolution", "footprint", "mix"
std::optional<Objective> parseObjective(std::string_view text);

// Weights of the mix objective: score = condition * C + resolution * R + footprint * F, on the
// normalised terms (normalisedCondition, normalisedResolution, normalisedFootprint), each 1 at
// its ideal. Only the ratios matter; each weight >= 0, at least one > 0.
struct MixWeights {
  double condition = 1.0;
  double resolution = 1.0;
  double footprint = 1.0;
};
// Empty when valid, else a sentence naming the problem.
Message validateWeights(const MixWeights& w);

// The normalised terms of the mix (dimensionless, >= 1 for a feasible design, 1 ideal):
// condition: worst-case condition number kappa itself (1 = isotropic);
// resolution: worst mm per step / (step angle * sqrt(rectangle area)), the pen travel per step
//   against that of a lever as long as the rectangle's mean side;
// footprint: footprint area / rectangle area (1 = a machine no larger than its paper).
double normalisedCondition(const DesignMeasures& m);
double normalisedResolution(const DesignMeasures& m);
double normalisedFootprint(const DesignMeasures& m);

// The measure an objective minimises (weights are used by Objective::Mix only).
double objectiveValue(Objective o, const DesignMeasures& m, const MixWeights& weights = {});

// Every design that breaks a rule scores above this; the excess is its scaled violation.
inline constexpr double kInfeasibleScore = 1e6;
// Angles in the violation are scaled by this length (mm per rad) to add up with mm.
inline constexpr double kViolationScaleMm = 100.0;

// objectiveValue for a feasible evaluation, kInfeasibleScore + violation otherwise.
double penalisedScore(Objective o, const Evaluation& e, const MixWeights& weights = {});

}  // namespace fivebar::design
