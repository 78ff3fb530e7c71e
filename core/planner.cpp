// planJob: placement, working-mode choice and preflight, optimisation, then planStrokes
// (plan_motion.cpp); reportToJson.
#include "planner.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "feasibility.hpp"
#include "optimise.hpp"
#include "parallel.hpp"
#include "placement.hpp"
#include "workspace.hpp"

namespace fivebar {
namespace {

// Cells per side of the workspace map the fit rectangle is searched on.
constexpr int kFitGridCells = 160;

struct Candidate {
  WorkingMode mode = WorkingMode::PlusPlus;
  Placement placement;
  std::vector<Stroke> strokes;
  FeasibilityReport report;
};

std::string layerName(const Drawing& d, int layerIndex) {
  if (layerIndex < 0 || static_cast<size_t>(layerIndex) >= d.layers.size())
    return "layer " + std::to_string(layerIndex);
  const Layer& l = d.layers[static_cast<size_t>(layerIndex)];
  return "layer '" + (l.name.empty() ? l.id : l.name) + "'";
}

std::string fixedText(double v, int decimals) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << v;
  return s.str();
}

// The drawing fitted into the mode's largest singularity-free rectangle.
std::optional<Placement> fittedPlacement(const Drawing& d, const MachineProfile& p,
                                         WorkingMode mode, const PlanOptions& o) {
  const WorkspaceSettings s = workspaceSettings(p);
  const WorkspaceMap map =
      computeMap(p.geometry, s, mode, gridCovering(p.geometry, kFitGridCells), 2);
  const auto rotated = strokeBounds(placeDrawing(d, Placement{Vec2::Zero(), o.rotationRad, 1.0}));
  const double aspect =
      rotated && rotated->height() > 1e-9 && rotated->width() > 1e-9
          ? rotated->width() / rotated->height() : 0.0;
  const auto rect = largestSafeRectangle(map, p.geometry, s, aspect);
  if (!rect) return std::nullopt;
  return fitPlacement(d, RectMm{rect->xMin, rect->yMin, rect->xMax, rect->yMax}, true,
                      o.fitMarginMm, o.rotationRad);
}

std::vector<std::string> fixesOf(const Candidate& c, const std::vector<Candidate>& all,
                                 bool fitted) {
  std::vector<std::string> fixes;
  if (c.report.shrinkFactor)
    fixes.push_back("shrink: --scale " + fixedText(c.placement.scale * *c.report.shrinkFactor, 3));
  if (c.report.suggestedAnchorMm && !fitted)
    fixes.push_back("move: --at " + fixedText(c.report.suggestedAnchorMm->x(), 1) + "," +
                    fixedText(c.report.suggestedAnchorMm->y(), 1));
  for (const Candidate& other : all)
    if (other.report.feasible && other.mode != c.mode)
      fixes.push_back("use working mode " + std::string(toString(other.mode)));
  if (!fitted) fixes.push_back("fit into the workspace: --fit");
  return fixes;
}

void reportInfeasible(const Drawing& d, const std::vector<Candidate>& cands, bool fitted,
                      PlanResult& out) {
  // The candidate with the fewest problems explains best what to change.
  const auto best = std::min_element(cands.begin(), cands.end(), [](const auto& a, const auto& b) {
    return a.report.problemCount < b.report.problemCount;
  });
  out.report.mode = best->mode;
  out.report.minSingularityMarginDeg = degFromRad(best->report.minTypeIIMarginRad);
  const std::vector<std::string> fixes = fixesOf(*best, cands, fitted);
  for (const PreflightProblem& pr : best->report.problems) {
    std::string path = pr.strokeIndex < 0 ? "travel back to the start pose"
                                          : layerName(d, pr.layerIndex) + " path " +
                                                std::to_string(pr.pathIndex);
    if (pr.kind == MoveKind::Travel && pr.strokeIndex >= 0) path = "travel to " + path;
    out.report.problems.push_back({path, pr.whereMm, pr.reason, fixes});
  }
  if (out.report.problems.empty())
    out.report.problems.push_back({"job", Vec2::Zero(), best->report.summary(), fixes});
  out.status = PlanStatus::Infeasible;
  out.message = "working mode " + std::string(toString(best->mode)) + ": " +
                out.report.problems.front().path + ": " + out.report.problems.front().why;
}

}  // namespace

PlanResult planJob(const Drawing& drawing, const MachineProfile& profile,
                   const PlanOptions& options) {
  PlanResult out;
  out.report.toleranceMm = options.toleranceMm;
  if (!(options.scale > 0.0) || !std::isfinite(options.scale)) {
    out.message = "scale must be a positive number";
    return out;
  }
  if (!drawingBounds(drawing)) {
    out.status = PlanStatus::EmptyDrawing;
    out.message = "nothing visible to draw in '" + drawing.source + "'";
    return out;
  }
  const bool fit = options.fit || !options.atMm;
  std::vector<WorkingMode> modes(kAllWorkingModes.begin(), kAllWorkingModes.end());
  if (options.mode) modes = {*options.mode};
  // The working modes are independent: placed and preflighted in parallel, kept in mode order.
  std::vector<std::optional<Candidate>> slots(modes.size());
  parallelFor(modes.size(), planningThreads(), [&](std::size_t i) {
    Candidate c;
    c.mode = modes[i];
    if (fit) {
      const auto placed = fittedPlacement(drawing, profile, c.mode, options);
      if (!placed) return;
      c.placement = *placed;
    } else {
      c.placement = Placement{*options.atMm, options.rotationRad, options.scale};
    }
    PreflightOptions pf;
    pf.maxListedProblems = 20;
    pf.anchorMm = c.placement.centerMm;
    c.strokes = placeDrawing(drawing, c.placement);
    c.report = preflight(c.strokes, profile, c.mode, pf);
    slots[i] = std::move(c);
  });
  std::vector<Candidate> cands;
  for (std::optional<Candidate>& c : slots)
    if (c) cands.push_back(std::move(*c));
  if (cands.empty()) {
    out.status = PlanStatus::Infeasible;
    out.message = "no working mode has a singularity-free area to fit the drawing into";
    out.report.problems.push_back({"job", Vec2::Zero(), out.message, {"check the profile"}});
    return out;
  }
  const Candidate* chosen = nullptr;
  for (const Candidate& c : cands)
    if (c.report.feasible &&
        (!chosen || c.report.minTypeIIMarginRad > chosen->report.minTypeIIMarginRad))
      chosen = &c;
  if (!chosen) {
    reportInfeasible(drawing, cands, fit, out);
    return out;
  }
  std::vector<Stroke> strokes = chosen->strokes;
  if (options.optimise) {
    OptimiseOptions oo;
    oo.start = profile.homeAngles;
    oo.timeBudgetS = 0.2;
    strokes = optimise(std::move(strokes), profile, chosen->mode, oo).strokes;
  }
  PlanOptions machineOptions = options;
  machineOptions.flatteningToleranceMm *= chosen->placement.scale;
  PlanResult result = planStrokes(strokes, drawing.layers, profile, chosen->mode, machineOptions);
  result.placementScale = chosen->placement.scale;
  return result;
}

std::string reportToJson(const PlanReport& r) {
  nlohmann::json problems = nlohmann::json::array();
  for (const PlanProblem& p : r.problems)
    problems.push_back({{"path", p.path},
                        {"where", {{"x_mm", p.whereMm.x()}, {"y_mm", p.whereMm.y()}}},
                        {"why", p.why},
                        {"fixes", p.fixes}});
  const nlohmann::json j = {
      {"feasible", r.feasible},
      {"mode", std::string(toString(r.mode))},
      {"estimated_time_s", r.estimatedTimeS},
      {"pen_down_mm", r.penDownMm},
      {"travel_mm", r.travelMm},
      {"segments", r.segments},
      {"max_deviation_mm", r.maxDeviationMm},
      {"tolerance_mm", r.toleranceMm},
      {"min_singularity_margin", r.minSingularityMarginDeg},
      {"feed_limited_segments", r.feedLimitedSegments},
      {"problems", problems},
  };
  return j.dump(2) + "\n";
}

}  // namespace fivebar
