// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/objective.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fivebar::design {

std::string_view toString(Objective o) {
  switch (o) {
    case Objective::Condition: return "condition";
    case Objective::Resolution: return "resolution";
    case Objective::Footprint: return "footprint";
    case Objective::Mix: return "mix";
  }
  return "condition";
}

std::optional<Objective> parseObjective(std::string_view text) {
  for (Objective o : {Objective::Condition, Objective::Resolution, Objective::Footprint, Objective::Mix})
    if (text == toString(o)) return o;
  return std::nullopt;
}

Message validateWeights(const MixWeights& w) {
  for (double v : {w.condition, w.resolution, w.footprint})
    if (!std::isfinite(v) || v < 0.0) return FB_TR("Design", "mix weights must be finite and not negative");
  if (w.condition + w.resolution + w.footprint <= 0.0) return FB_TR("Design", "mix weights must not all be zero");
  return {};
}

double normalisedCondition(const DesignMeasures& m) { return m.worstCondition; }

double normalisedResolution(const DesignMeasures& m) {
  const double lever = m.stepRad * std::sqrt(m.rectangleAreaMm2);
  return lever > 0.0 ? m.worstMmPerStep / lever : std::numeric_limits<double>::infinity();
}

double normalisedFootprint(const DesignMeasures& m) {
  return m.rectangleAreaMm2 > 0.0 ? m.footprintMm2 / m.rectangleAreaMm2
                                  : std::numeric_limits<double>::infinity();
}

double objectiveValue(Objective o, const DesignMeasures& m, const MixWeights& w) {
  switch (o) {
    case Objective::Condition: return m.worstCondition;
    case Objective::Resolution: return m.worstMmPerStep;
    case Objective::Footprint: return m.footprintMm2;
    case Objective::Mix: {
      // A zero weight drops its term entirely (0 * inf would be NaN).
      double sum = 0.0;
      if (w.condition > 0.0) sum += w.condition * normalisedCondition(m);
      if (w.resolution > 0.0) sum += w.resolution * normalisedResolution(m);
      if (w.footprint > 0.0) sum += w.footprint * normalisedFootprint(m);
      return sum;
    }
  }
  return m.worstCondition;
}

double penalisedScore(Objective o, const Evaluation& e, const MixWeights& weights) {
  if (e.feasible()) {
    const double v = objectiveValue(o, e.measures, weights);
    return std::isfinite(v) ? std::min(v, 0.5 * kInfeasibleScore) : 0.5 * kInfeasibleScore;
  }
  return kInfeasibleScore + e.violations.total(kViolationScaleMm);
}

}  // namespace fivebar::design
