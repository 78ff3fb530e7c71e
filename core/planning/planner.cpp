// planJob: placement, working-mode choice and preflight, optimisation, then planStrokes
// (plan_motion.cpp); reportToJson.
#include "core/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <mutex>
#include <sstream>

#include "core/planning/feasibility.hpp"
#include "core/planning/optimise.hpp"
#include "core/support/parallel.hpp"
#include "core/planning/placement.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

// Cells per side of the workspace map the fit rectangle is searched on.
constexpr int kFitGridCells = 160;

// Long edges the 2-opt of a plan may examine (well under a microsecond each).
constexpr std::size_t kTwoOptSteps = 150000;
// Stride of the point sample that bounds a mode's margin from above: about this many points.
constexpr std::size_t kScreenPoints = 20000;

struct ModeOption {
  WorkingMode mode = WorkingMode::PlusPlus;
  Placement placement;
  // sin of the smallest type II margin over a sample of the placed points: no plan in this mode
  // has a larger margin. nullopt when a sampled point cannot be reached in the mode.
  std::optional<double> marginBound;
};

struct Candidate {
  WorkingMode mode = WorkingMode::PlusPlus;
  Placement placement;
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

// Bounds of the visible points rotated by rotationRad about the origin.
std::optional<RectMm> rotatedBounds(const Drawing& d, double rotationRad) {
  const Eigen::Rotation2Dd rot(rotationRad);
  std::optional<RectMm> box;
  for (const Layer& l : d.layers) {
    if (!l.visible) continue;
    for (const Polyline& path : l.paths)
      for (const Vec2& p0 : path.points) {
        const Vec2 p = rot * p0;
        if (!box) box = RectMm{p.x(), p.y(), p.x(), p.y()};
        box->x0 = std::min(box->x0, p.x()), box->x1 = std::max(box->x1, p.x());
        box->y0 = std::min(box->y0, p.y()), box->y1 = std::max(box->y1, p.y());
      }
  }
  return box;
}

// The largest singularity-free rectangle of a mode for an aspect ratio, remembered: the CLI asks
// for the placement scale before it flattens the drawing finely, then plans (the rectangle takes
// tens of milliseconds per mode). The aspect is rounded to 1e-4 relative, which changes the
// rectangle by far less than its refinement step; the drawing is still fitted exactly into it.
std::optional<Rect> safeRectangle(const MachineProfile& p, WorkingMode mode, double aspect) {
  struct Entry {
    Geometry g;
    WorkspaceSettings s;
    WorkingMode mode;
    double aspect;
    std::optional<Rect> rect;
  };
  static std::mutex mutex;
  static std::vector<Entry> cache;  // most recent last
  constexpr std::size_t kEntries = 16;
  const WorkspaceSettings s = workspaceSettings(p);
  if (aspect > 0.0) {
    const double unit = std::pow(10.0, std::floor(std::log10(aspect)) - 4.0);
    aspect = std::round(aspect / unit) * unit;
  }
  auto same = [&](const Entry& e) {
    const Geometry& a = e.g;
    const Geometry& b = p.geometry;
    return e.mode == mode && e.aspect == aspect && a.a1 == b.a1 && a.b1 == b.b1 && a.a2 == b.a2 &&
           a.b2 == b.b2 && a.w == b.w && e.s.limits.theta1Min == s.limits.theta1Min &&
           e.s.limits.theta1Max == s.limits.theta1Max && e.s.limits.theta2Min == s.limits.theta2Min &&
           e.s.limits.theta2Max == s.limits.theta2Max && e.s.typeIIMarginRad == s.typeIIMarginRad &&
           e.s.typeIMarginRad == s.typeIMarginRad && e.s.stepRad1 == s.stepRad1 &&
           e.s.stepRad2 == s.stepRad2;
  };
  {
    const std::lock_guard lock(mutex);
    const auto hit = std::find_if(cache.begin(), cache.end(), same);
    if (hit != cache.end()) return hit->rect;
  }
  const WorkspaceMap map =
      computeMap(p.geometry, s, mode, gridCovering(p.geometry, kFitGridCells), 1);
  const std::optional<Rect> rect = largestSafeRectangle(map, p.geometry, s, aspect);
  const std::lock_guard lock(mutex);
  if (cache.size() == kEntries) cache.erase(cache.begin());
  cache.push_back({p.geometry, s, mode, aspect, rect});
  return rect;
}

// The drawing fitted into the mode's largest singularity-free rectangle.
std::optional<Placement> fittedPlacement(const std::optional<RectMm>& bounds, const MachineProfile& p,
                                         WorkingMode mode, const PlanOptions& o,
                                         const std::optional<RectMm>& rotated) {
  const double aspect =
      rotated && rotated->height() > 1e-9 && rotated->width() > 1e-9
          ? rotated->width() / rotated->height() : 0.0;
  const auto rect = safeRectangle(p, mode, aspect);
  if (!rect) return std::nullopt;
  return fitPlacement(bounds, RectMm{rect->xMin, rect->yMin, rect->xMax, rect->yMax}, true,
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

// sin of the type II margin of the pose reaching p with angles q; negative when the pose is in
// the other assembly mode.
double signedSinTypeII(const Geometry& g, const JointAngles& q, const Vec2& p, AssemblyMode a) {
  const Vec2 d1 = p - elbow1(g, q.theta1), d2 = p - elbow2(g, q.theta2);
  const double s = std::min(1.0, std::abs(cross(d1, d2)) / (g.b1 * g.b2));
  return assemblyModeOf(makePose(g, q, p)) == a ? s : -s;
}

// Upper bound of the margin any plan in `mode` can have (see ModeOption::marginBound).
std::optional<double> screenMargin(const Drawing& d, const std::optional<RectMm>& bounds,
                                   const Placement& placement,
                                   const MachineProfile& p, WorkingMode mode) {
  const Eigen::Affine2d machineFromWorkT = machineFromWork(bounds, placement);
  std::size_t total = 0;
  for (const Layer& l : d.layers)
    if (l.visible)
      for (const Polyline& path : l.paths) total += path.points.size();
  const std::size_t stride = std::max<std::size_t>(1, total / kScreenPoints);
  double bound = 1.0;
  std::size_t k = 0;
  for (const Layer& l : d.layers) {
    if (!l.visible) continue;
    for (const Polyline& path : l.paths)
      for (const Vec2& w : path.points) {
        if (k++ % stride != 0) continue;
        const Vec2 x = machineFromWorkT * w;
        const IkResult ik = inverse(p.geometry, x, mode);
        if (!ik.ok()) return std::nullopt;
        const double s = signedSinTypeII(p.geometry, ik.angles, x, p.assembly);
        if (s < 0.0) return std::nullopt;
        bound = std::min(bound, s);
      }
  }
  return std::asin(bound);
}

// The whole plan in one working mode: placed strokes, optimised, segmented and checked.
PlanResult planInMode(const Drawing& drawing, const std::optional<RectMm>& bounds,
                      const MachineProfile& profile,
                      const PlanOptions& options, const ModeOption& m, StageTimes& times) {
  StageClock clock(times);
  std::vector<Stroke> strokes = placeDrawing(drawing, machineFromWork(bounds, m.placement));
  clock.lap("placement");
  if (options.optimise) {
    OptimiseOptions oo;
    oo.start = profile.homeAngles;
    // A deterministic 2-opt budget (the same drawing always gives the same job), under 0.1 s
    // on 40,000 strokes; the wall-clock budget only guards against a pathological case.
    oo.maxTwoOptSteps = kTwoOptSteps;
    oo.measureTravel = false;
    oo.timeBudgetS = 2.0;
    strokes = optimise(std::move(strokes), profile, m.mode, oo).strokes;
    clock.lap("optimise");
  }
  PlanOptions machineOptions = options;
  machineOptions.flatteningToleranceMm *= m.placement.scale;
  PlanResult result = planStrokes(strokes, drawing.layers, profile, m.mode, machineOptions);
  times.append(result.timings);
  clock.restart();
  result.placementScale = m.placement.scale;
  return result;
}

// Preflight of every mode that has a placement, for the report of a job no mode can plan.
std::vector<Candidate> preflightAll(const Drawing& drawing, const std::optional<RectMm>& bounds,
                                    const MachineProfile& profile,
                                    const std::vector<ModeOption>& modes) {
  std::vector<Candidate> cands(modes.size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    Candidate& c = cands[i];
    c.mode = modes[i].mode;
    c.placement = modes[i].placement;
    PreflightOptions pf;
    pf.maxListedProblems = 20;
    pf.anchorMm = c.placement.centerMm;
    c.report = preflight(placeDrawing(drawing, machineFromWork(bounds, c.placement)), profile,
                         c.mode, pf);
  }
  return cands;
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
  const std::optional<RectMm> bounds = drawingBounds(drawing);  // one pass over the points
  if (!bounds) {
    out.status = PlanStatus::EmptyDrawing;
    out.message = "nothing visible to draw in '" + drawing.source + "'";
    return out;
  }
  StageClock clock(out.timings);
  const bool fit = options.fit || !options.atMm;
  std::vector<WorkingMode> modes(kAllWorkingModes.begin(), kAllWorkingModes.end());
  if (options.mode) modes = {*options.mode};
  // Each mode's placement and an upper bound of its margin (from a sample of the points), in
  // parallel; then full plans, best bound first, until no other mode can beat the best plan.
  const auto rotated = rotatedBounds(drawing, options.rotationRad);
  std::vector<std::optional<ModeOption>> slots(modes.size());
  parallelFor(modes.size(), planningThreads(), [&](std::size_t i) {
    ModeOption m;
    m.mode = modes[i];
    if (fit) {
      const auto placed = fittedPlacement(bounds, profile, m.mode, options, rotated);
      if (!placed) return;
      m.placement = *placed;
    } else {
      m.placement = Placement{*options.atMm, options.rotationRad, options.scale};
    }
    m.marginBound = screenMargin(drawing, bounds, m.placement, profile, m.mode);
    slots[i] = m;
  });
  std::vector<ModeOption> candidates;
  for (const auto& m : slots)
    if (m) candidates.push_back(*m);
  clock.lap("placement and mode screening");
  if (candidates.empty()) {
    out.status = PlanStatus::Infeasible;
    out.message = "no working mode has a singularity-free area to fit the drawing into";
    out.report.problems.push_back({"job", Vec2::Zero(), out.message, {"check the profile"}});
    return out;
  }
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
    if (r.status == PlanStatus::BadOptions) return r;  // the options, not the drawing: say so
    if (r.ok() && (!best || r.job.summary.minTypeIIMarginRad > best->job.summary.minTypeIIMarginRad))
      best = std::move(r);
    else if (!r.ok() && !firstFailure)
      firstFailure = std::move(r);
  }
  if (best) {
    best->timings = std::move(out.timings);
    return std::move(*best);
  }
  // No mode plans: the preflight of every mode explains what to change.
  std::vector<Candidate> cands = preflightAll(drawing, bounds, profile, candidates);
  clock.lap("preflight for the report");
  const bool anyFeasible = std::any_of(cands.begin(), cands.end(),
                                       [](const Candidate& c) { return c.report.feasible; });
  if (anyFeasible && firstFailure) {  // the points pass but the planned moves do not
    firstFailure->timings = std::move(out.timings);
    return std::move(*firstFailure);
  }
  reportInfeasible(drawing, cands, fit, out);
  return out;
}

std::optional<double> largestPlacementScale(const Drawing& drawing, const MachineProfile& profile,
                                            const PlanOptions& options) {
  const std::optional<RectMm> bounds = drawingBounds(drawing);
  if (!bounds) return std::nullopt;
  if (options.atMm && !options.fit) return options.scale;
  std::vector<WorkingMode> modes(kAllWorkingModes.begin(), kAllWorkingModes.end());
  if (options.mode) modes = {*options.mode};
  const auto rotated = rotatedBounds(drawing, options.rotationRad);
  std::vector<double> scales(modes.size(), 0.0);
  parallelFor(modes.size(), planningThreads(), [&](std::size_t i) {
    if (const auto placed = fittedPlacement(bounds, profile, modes[i], options, rotated))
      scales[i] = placed->scale;
  });
  const double largest = *std::max_element(scales.begin(), scales.end());
  if (largest > 0.0) return largest;
  return std::nullopt;
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
      {"time_optimal_s", r.timeOptimalS},
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
