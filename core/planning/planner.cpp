// SPDX-License-Identifier: GPL-3.0-or-later
// planJob: placement, working-mode choice and preflight, optimisation, then planStrokes
// (plan_motion.cpp); reportToJson.
#include "core/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/kinematics/kinematics.hpp"
#include "core/planning/feasibility.hpp"
#include "core/planning/optimise.hpp"
#include "core/support/parallel.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/auto_placement.hpp"

namespace fivebar {
namespace {

// Long edges the 2-opt of a plan may examine (well under a microsecond each): the only budget
// of the optimisation, so the same drawing always gives the same job whatever the load.
constexpr std::size_t kTwoOptSteps = 150000;
// Relative slack when comparing the flattening error with its share of the tolerance.
constexpr double kShareSlack = 1e-6;

struct ModeOption {
  WorkingMode mode = WorkingMode::PlusPlus;
  Placement placement;
  // The smallest type II margin over a sample of the placed points (rad): no plan in this mode
  // has a larger margin. nullopt when a sampled point cannot be reached in the mode.
  std::optional<double> marginBound;
};

struct Candidate {
  WorkingMode mode = WorkingMode::PlusPlus;
  Placement placement;
  FeasibilityReport report;
};

// True when a visible path approximates curves (its points carry the flattening error).
bool hasFlattenedPaths(const Drawing& d) {
  for (const Layer& layer : d.layers)
    if (layer.visible)
      for (const Polyline& line : layer.paths)
        if (line.flattened) return true;
  return false;
}

double largestScale(const Placement& p) { return p.scale * std::max(1.0, std::abs(p.stretchY)); }

// A layer by name (or id), as problems name it: "layer 'ink'", or "layer 3" without one.
Message layerName(const Drawing& d, int layerIndex) {
  if (layerIndex < 0 || static_cast<size_t>(layerIndex) >= d.layers.size())
    return FB_TR("Planner", "layer %1").arg(layerIndex);
  const Layer& l = d.layers[static_cast<size_t>(layerIndex)];
  return FB_TR("Planner", "layer '%1'").arg(l.name.empty() ? l.id : l.name);
}

// What to change (codes with their numbers; the front ends word them): the shrink factor, the
// suggested centre, the feasible modes, fitting.
// The working mode of the profile's home pose (where every job starts and ends); nullopt when
// the home angles do not close the linkage.
std::optional<WorkingMode> homeModeOf(const MachineProfile& profile) {
  const JointAngles q = kinematicFromCommanded(profile.calibration, profile.homeAngles);
  const FkResult fk = forward(profile.geometry, q, profile.assembly);
  if (!fk.ok()) return std::nullopt;
  return workingModeOf(profile.geometry, makePose(profile.geometry, q, fk.p));
}

std::vector<PlanFix> fixesOf(const Candidate& c, const std::vector<Candidate>& all, bool fitted,
                             const MachineProfile& profile) {
  std::vector<PlanFix> fixes;
  // A mode other than the home pose's: the travels from and to home change the working mode,
  // which passes a leg through full stretch or fold wherever the drawing is, and points the
  // mode reaches only in the other assembly mode (the "--" mode of a "+" machine) stay so
  // wherever the drawing goes. Moving, shrinking or fitting cannot help those; the home pose's
  // mode (or another mode that plans) does.
  const std::optional<WorkingMode> home = homeModeOf(profile);
  const bool placementCannotHelp =
      !c.report.problems.empty() &&
      std::all_of(c.report.problems.begin(), c.report.problems.end(), [](const PreflightProblem& p) {
        return p.kind == MoveKind::Travel || (p.kind == MoveKind::Point && p.status == MoveStatus::AssemblyChange);
      });
  if (home && *home != c.mode && placementCannotHelp) {
    fixes.push_back({FixKind::UseMode, 1.0, Vec2::Zero(), *home});
    for (const Candidate& other : all)
      if (other.report.feasible && other.mode != c.mode && other.mode != *home)
        fixes.push_back({FixKind::UseMode, 1.0, Vec2::Zero(), other.mode});
    return fixes;
  }
  if (c.report.shrinkFactor)
    fixes.push_back({FixKind::Shrink, c.placement.scale * *c.report.shrinkFactor});
  if (c.report.suggestedAnchorMm && !fitted)
    fixes.push_back({FixKind::MoveCentre, 1.0, *c.report.suggestedAnchorMm});
  for (const Candidate& other : all)
    if (other.report.feasible && other.mode != c.mode)
      fixes.push_back({FixKind::UseMode, 1.0, Vec2::Zero(), other.mode});
  if (!fitted) fixes.push_back({FixKind::FitToWorkspace});
  return fixes;
}

void reportInfeasible(const Drawing& d, const std::vector<Candidate>& cands, bool fitted,
                      const MachineProfile& profile, PlanResult& out) {
  // The candidate with the fewest problems explains best what to change.
  const auto best = std::min_element(cands.begin(), cands.end(), [](const auto& a, const auto& b) {
    return a.report.problemCount < b.report.problemCount;
  });
  out.report.mode = best->mode;
  out.report.minSingularityMarginDeg = degFromRad(best->report.minTypeIIMarginRad);
  const std::vector<PlanFix> fixes = fixesOf(*best, cands, fitted, profile);
  for (const PreflightProblem& pr : best->report.problems) {
    Message path = pr.strokeIndex < 0 ? FB_TR("Planner", "travel back to the start pose")
                                      : FB_TR("Planner", "%1 path %2")
                                            .arg(layerName(d, pr.layerIndex)).arg(pr.pathIndex);
    const bool travel = pr.kind == MoveKind::Travel;
    if (travel && pr.strokeIndex >= 0) path = FB_TR("Planner", "travel to %1").arg(std::move(path));
    out.report.problems.push_back({path, pr.whereMm, pr.reason, fixes,
                                   travel ? -1 : pr.layerIndex, travel ? -1 : pr.pathIndex});
  }
  if (out.report.problems.empty())
    out.report.problems.push_back({FB_TR("Planner", "job"), Vec2::Zero(), best->report.summaryMessage(), fixes});
  out.status = PlanStatus::Infeasible;
  out.message = FB_TR("Planner", "working mode %1: %2: %3")
                    .arg(toString(best->mode))
                    .arg(out.report.problems.front().path)
                    .arg(out.report.problems.front().why);
}

// The whole plan in one working mode: placed strokes, optimised, segmented and checked.
PlanResult planInMode(const Drawing& drawing, const std::optional<RectMm>& bounds,
                      const MachineProfile& profile,
                      const PlanOptions& options, const ModeOption& m, StageTimes& times) {
  StageClock clock(times);
  if (options.cancel && options.cancel->load()) {
    PlanResult cancelled;
    cancelled.status = PlanStatus::Cancelled;
    cancelled.message = FB_TR("Planner", "planning cancelled");
    return cancelled;
  }
  std::vector<Stroke> strokes = placeDrawing(drawing, machineFromWork(bounds, m.placement));
  clock.lap("placement");
  if (options.optimise) {
    OptimiseOptions oo;
    oo.start = kinematicFromCommanded(profile.calibration, profile.homeAngles);  // home is commanded
    oo.maxTwoOptSteps = kTwoOptSteps;  // under 0.1 s on 40,000 strokes
    oo.joinToleranceMm = joinGapMm(options.toleranceMm);
    oo.measureTravel = false;
    strokes = optimise(std::move(strokes), profile, m.mode, oo).strokes;
    clock.lap("optimise");
  }
  PlanOptions machineOptions = options;
  machineOptions.flatteningToleranceMm = drawing.flatteningToleranceMm * largestScale(m.placement);
  PlanResult result = planStrokes(strokes, drawing.layers, profile, m.mode, machineOptions);
  times.append(result.timings);
  clock.restart();
  result.placementScale = m.placement.scale;
  result.placement = m.placement;
  return result;
}

// Preflight of every mode that has a placement, for the report of a job no mode can plan.
std::vector<Candidate> preflightAll(const Drawing& drawing, const std::optional<RectMm>& bounds,
                                    const MachineProfile& profile,
                                    const std::vector<ModeOption>& modes, int maxListed) {
  std::vector<Candidate> cands(modes.size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    Candidate& c = cands[i];
    c.mode = modes[i].mode;
    c.placement = modes[i].placement;
    PreflightOptions pf;
    pf.maxListedProblems = maxListed;
    pf.anchorMm = c.placement.centerMm;
    c.report = preflight(placeDrawing(drawing, machineFromWork(bounds, c.placement)), profile,
                         c.mode, pf);
  }
  return cands;
}

}  // namespace

double joinGapMm(double toleranceMm) {
  return std::min(kJoinGapMaxMm, kJoinGapShare * std::max(toleranceMm, 0.0));
}

double importToleranceMm(double toleranceMm, double placementScale) {
  return kFlatteningShare * toleranceMm / std::max(placementScale, 1e-12);
}

void setFixedPlacement(PlanOptions& o, const Placement& p) {
  o.atMm = p.centerMm;
  o.scale = p.scale;
  o.stretchY = p.stretchY;
  o.rotationRad = p.rotationRad;
  o.fit = false;
}

PlanResult planJob(const Drawing& drawing, const MachineProfile& profile,
                   const PlanOptions& options) {
  PlanResult out;
  out.report.toleranceMm = options.toleranceMm;
  if (!(options.scale > 0.0) || !std::isfinite(options.scale) || !(options.stretchY > 0.0) ||
      !std::isfinite(options.stretchY)) {
    out.message = FB_TR("Planner", "scale must be a positive number");
    return out;
  }
  const std::optional<RectMm> bounds = drawingBounds(drawing);  // one pass over the points
  if (!bounds) {
    out.status = PlanStatus::EmptyDrawing;
    out.message = FB_TR("Planner", "nothing visible to draw in '%1'").arg(drawing.source);
    return out;
  }
  StageClock clock(out.timings);
  const bool fixed = options.atMm && !options.fit;
  Placement placement{options.atMm.value_or(Vec2::Zero()), options.rotationRad, options.scale,
                      options.stretchY};
  if (!fixed) {
    const auto placed = autoPlacement(drawing, profile, options.mode, options.rotationRad,
                                      options.fit ? PlacementSizing::Fit : PlacementSizing::TrueSize);
    clock.lap("placement");
    if (!placed) {
      out.status = PlanStatus::Infeasible;
      out.message = FB_TR("Planner", "no working mode has a singularity-free area to place the drawing in");
      out.report.problems.push_back({FB_TR("Planner", "job"), Vec2::Zero(), out.message,
                                     {PlanFix{FixKind::CheckProfile}}});
      return out;
    }
    placement = placed->placement;
    out.placementNote = scaleNote(*placed);
  }
  out.placement = placement;
  out.placementScale = placement.scale;
  // The drawing must have been flattened finely enough for the scale it is drawn at (straight
  // lines carry no flattening error, whatever the scale).
  const double scale = largestScale(placement);
  const double share = kFlatteningShare * options.toleranceMm;
  if (drawing.flatteningToleranceMm * scale > share * (1.0 + kShareSlack) &&
      hasFlattenedPaths(drawing)) {
    out.status = PlanStatus::CoarseDrawing;
    out.requiredFlatteningToleranceMm = importToleranceMm(options.toleranceMm, scale);
    out.message = FB_TR("Planner", "the drawing was flattened within %1 mm, too coarse at %2 %: "
                                   "import it again within %3 mm")
                      .arg(drawing.flatteningToleranceMm, 4).arg(scale * 100.0, 0)
                      .arg(out.requiredFlatteningToleranceMm, 5);
    return out;
  }
  std::vector<WorkingMode> modes(kAllWorkingModes.begin(), kAllWorkingModes.end());
  if (options.mode) modes = {*options.mode};
  // An upper bound of each mode's margin (from a sample of the points), in parallel; then full
  // plans, best bound first, until no other mode can beat the best plan.
  std::vector<ModeOption> candidates(modes.size());
  parallelFor(modes.size(), planningThreads(), [&](std::size_t i) {
    candidates[i].mode = modes[i];
    candidates[i].placement = placement;
    candidates[i].marginBound = screenMarginRad(drawing, bounds, placement, profile, modes[i]);
  });
  clock.lap("mode screening");
  std::vector<const ModeOption*> order;
  for (const ModeOption& m : candidates)
    if (m.marginBound) order.push_back(&m);
  std::stable_sort(order.begin(), order.end(), [](const ModeOption* a, const ModeOption* b) {
    return *a->marginBound > *b->marginBound;
  });
  std::optional<PlanResult> best;
  std::optional<PlanResult> firstFailure;
  for (const ModeOption* m : order) {
    if (best && *m->marginBound <= best->job.summary.minTypeIIMarginRad) break;
    PlanResult r = planInMode(drawing, bounds, profile, options, *m, out.timings);
    if (r.status == PlanStatus::BadOptions || r.status == PlanStatus::Cancelled) return r;
    if (r.ok() && (!best || r.job.summary.minTypeIIMarginRad > best->job.summary.minTypeIIMarginRad))
      best = std::move(r);
    else if (!r.ok() && !firstFailure)
      firstFailure = std::move(r);
  }
  if (best) {
    best->timings = std::move(out.timings);
    best->placementNote = out.placementNote;
    return std::move(*best);
  }
  // No mode plans: the preflight of every mode explains what to change.
  std::vector<Candidate> cands =
      preflightAll(drawing, bounds, profile, candidates, options.maxListedProblems);
  clock.lap("preflight for the report");
  const bool anyFeasible = std::any_of(cands.begin(), cands.end(),
                                       [](const Candidate& c) { return c.report.feasible; });
  if (anyFeasible && firstFailure) {  // the points pass but the planned moves do not
    firstFailure->timings = std::move(out.timings);
    firstFailure->placementNote = out.placementNote;
    return std::move(*firstFailure);
  }
  reportInfeasible(drawing, cands, !fixed, profile, out);
  return out;
}

const char* toString(FixKind kind) {
  switch (kind) {
    case FixKind::MoveOrShrink: return "move_or_shrink";
    case FixKind::TryAnotherMode: return "try_another_mode";
    case FixKind::AwayFromSingular: return "away_from_singular";
    case FixKind::AwayFromEdge: return "away_from_edge";
    case FixKind::Shrink: return "shrink";
    case FixKind::MoveCentre: return "move_centre";
    case FixKind::UseMode: return "use_mode";
    case FixKind::FitToWorkspace: return "fit";
    case FixKind::ReachableHomePose: return "reachable_home_pose";
    case FixKind::CheckProfile: return "check_profile";
  }
  return "check_profile";
}

std::string reportToJson(const PlanReport& r, const FixWords& fixWords) {
  nlohmann::json problems = nlohmann::json::array();
  for (const PlanProblem& p : r.problems) {
    std::vector<std::string> fixes, kinds;
    for (const PlanFix& f : p.fixes) {
      fixes.push_back(fixWords ? fixWords(f) : std::string(toString(f.kind)));
      kinds.emplace_back(toString(f.kind));
    }
    problems.push_back({{"path", p.path.text()},
                        {"where", {{"x_mm", p.whereMm.x()}, {"y_mm", p.whereMm.y()}}},
                        {"why", p.why.text()},
                        {"fixes", fixes},
                        {"fix_kinds", kinds}});
  }
  const nlohmann::json j = {
      {"feasible", r.feasible},
      {"mode", std::string(toString(r.mode))},
      {"estimated_time_s", r.estimatedTimeS},
      {"time_optimal_s", r.timeOptimalS},
      {"pen_down_mm", r.penDownMm},
      {"travel_mm", r.travelMm},
      {"segments", r.segments},
      {"max_deviation_mm", r.maxDeviationMm},
      {"joint_deviation_mm", r.jointDeviationMm},
      {"flattening_mm", r.flatteningMm},
      {"bridged_gap_mm", r.bridgedGapMm},
      {"rounding_mm", r.roundingMm},
      {"tolerance_mm", r.toleranceMm},
      {"min_singularity_margin", r.minSingularityMarginDeg},
      {"feed_limited_segments", r.feedLimitedSegments},
      {"problems", problems},
  };
  return j.dump(2) + "\n";
}

}  // namespace fivebar
