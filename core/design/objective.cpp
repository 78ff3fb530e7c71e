#include "core/design/objective.hpp"

#include <algorithm>
#include <cmath>

namespace fivebar::design {

std::string_view toString(Objective o) {
  switch (o) {
    case Objective::Condition: return "condition";
    case Objective::Resolution: return "resolution";
    case Objective::Footprint: return "footprint";
  }
  return "condition";
}

std::optional<Objective> parseObjective(std::string_view text) {
  for (Objective o : {Objective::Condition, Objective::Resolution, Objective::Footprint})
    if (text == toString(o)) return o;
  return std::nullopt;
}

double objectiveValue(Objective o, const DesignMeasures& m) {
  switch (o) {
    case Objective::Condition: return m.worstCondition;
    case Objective::Resolution: return m.worstMmPerStep;
    case Objective::Footprint: return m.footprintMm2;
  }
  return m.worstCondition;
}

double penalisedScore(Objective o, const Evaluation& e) {
  if (e.feasible()) {
    const double v = objectiveValue(o, e.measures);
    return std::isfinite(v) ? std::min(v, 0.5 * kInfeasibleScore) : 0.5 * kInfeasibleScore;
  }
  return kInfeasibleScore + e.violations.total(kViolationScaleMm);
}

}  // namespace fivebar::design
