// SPDX-License-Identifier: GPL-3.0-or-later
// Design search (docs/design.md "Search"): starts over (working mode, turn, seed), each a global
// NLopt run (GN_CRS2_LM) on a coarse sampling of the rectangle then a local one (LN_SBPLX) on a
// finer sampling; every feasible design seen feeds a per-start Pareto archive. Starts are taken
// by the worker threads in any order but their results are merged in start order.
#include "core/design/search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <nlopt.hpp>
#include <thread>

#include "core/design/pareto.hpp"
#include "core/design/placement.hpp"

namespace fivebar::design {
namespace {

// Margin added to the brief's type I / type II margins while searching (rad): the final 1 mm
// sampling then keeps the brief's own margins.
constexpr double kSearchMarginRad = 0.25 * kPi / 180.0;
// Starts whose best designs are re-evaluated at the final sampling.
constexpr std::size_t kFinalists = 8;
// Progress is reported every this many evaluations.
constexpr long kProgressEvery = 512;

struct Start {
  WorkingMode mode;
  bool rotated;
  std::uint32_t seed;
};

// The search variables, each scaled to [0, 1]: symmetric (a, b, w, cx, cy) or
// (a1, b1, a2, b2, w, cx, cy).
struct Encoding {
  DesignBounds bounds;
  double rectW = 0.0, rectH = 0.0;  // oriented rectangle
  double cyMin = 0.0, cyMax = 0.0, cxSpan = 0.0;

  unsigned size() const { return bounds.symmetric ? 5u : 7u; }
  double link(double u) const { return bounds.minLinkMm + u * (bounds.maxLinkMm - bounds.minLinkMm); }
  void decode(const double* u, Geometry& g, Rect& r) const {
    const unsigned k = bounds.symmetric ? 2 : 4;
    g.a1 = link(u[0]);
    g.b1 = link(u[1]);
    g.a2 = bounds.symmetric ? g.a1 : link(u[2]);
    g.b2 = bounds.symmetric ? g.b1 : link(u[3]);
    g.w = bounds.minBaseMm + u[k] * (bounds.maxBaseMm - bounds.minBaseMm);
    const double cx = (2.0 * u[k + 1] - 1.0) * cxSpan;
    const double cy = cyMin + u[k + 2] * (cyMax - cyMin);
    r = centredRect(cx, cy, rectW, rectH);
  }
};

Encoding encodingFor(const DesignBrief& b, bool rotated) {
  Encoding e;
  e.bounds = b.bounds;
  e.rectW = rotated ? b.heightMm : b.widthMm;
  e.rectH = rotated ? b.widthMm : b.heightMm;
  e.cyMin = b.rules.minRectangleYMm + 0.5 * e.rectH;
  e.cyMax = std::max(e.cyMin + 1.0, 2.0 * b.bounds.maxLinkMm - 0.5 * e.rectH);
  e.cxSpan = b.bounds.maxLinkMm;
  return e;
}

struct Shared {
  Shared(const DesignBrief& b, const SearchOptions& o, const ProgressFn& p,
         const std::atomic<bool>* c)
      : brief(&b), rules(searchRules(b.rules)), options(&o), progress(&p), cancel(c) {}
  const DesignBrief* brief;
  DesignRules rules;  // searchRules(brief.rules)
  const SearchOptions* options;
  const ProgressFn* progress;
  const std::atomic<bool>* cancel;
  std::atomic<long> evaluations{0};
  long budget = 1;
  std::mutex progressMutex;
  double bestScore = kInfeasibleScore * 10.0;  // guarded by progressMutex
};

using Archive = ParetoArchive<std::vector<double>>;

struct Run {
  Shared* shared;
  Encoding enc;
  WorkingMode mode;
  Sampling sampling;
  Archive* archive;
  nlopt::opt* opt = nullptr;
};

double runScore(unsigned n, const double* u, double* grad, void* data) {
  (void)grad;
  auto& run = *static_cast<Run*>(data);
  Shared& sh = *run.shared;
  if (sh.cancel && sh.cancel->load(std::memory_order_relaxed) && run.opt) run.opt->force_stop();
  Geometry g;
  Rect r;
  run.enc.decode(u, g, r);
  const Evaluation e = evaluateDesign(g, run.mode, r, sh.rules, run.sampling);
  const double score = penalisedScore(sh.brief->objective, e, sh.brief->weights);
  if (e.feasible())
    run.archive->insert(e.measures.worstCondition, e.measures.footprintMm2,
                        std::vector<double>(u, u + n));
  const long done = sh.evaluations.fetch_add(1, std::memory_order_relaxed) + 1;
  if (sh.progress && *sh.progress && (done % kProgressEvery == 0 || score < sh.bestScore)) {
    std::lock_guard lock(sh.progressMutex);
    sh.bestScore = std::min(sh.bestScore, score);
    if (done % kProgressEvery == 0)
      (*sh.progress)({std::min(1.0, static_cast<double>(done) / sh.budget), done, sh.bestScore});
  }
  return score;
}

struct StartResult {
  std::vector<double> u;
  double score = 0.0;
  Archive archive;
};

void optimise(nlopt::algorithm algorithm, Run& run, std::vector<double>& u, int evaluations,
              double initialStep) {
  nlopt::opt opt(algorithm, run.enc.size());
  run.opt = &opt;
  opt.set_min_objective(runScore, &run);
  opt.set_lower_bounds(0.0);
  opt.set_upper_bounds(1.0);
  opt.set_maxeval(evaluations);
  opt.set_xtol_abs(1e-5);
  if (initialStep > 0.0) opt.set_initial_step(initialStep);
  double f = 0.0;
  try {
    opt.optimize(u, f);
  } catch (const std::exception&) {
    // forced stop (cancel) or a roundoff-limited step: u holds the best point found.
  }
  run.opt = nullptr;
}

StartResult runStart(Shared& sh, const Start& s) {
  StartResult out;
  const DesignBrief& b = *sh.brief;
  nlopt::srand(s.seed);  // NLopt's generator is thread-local: one seed per start
  Run run{&sh, encodingFor(b, s.rotated), s.mode, {}, &out.archive};
  const double longSide = std::max(b.widthMm, b.heightMm);
  out.u.assign(run.enc.size(), 0.5);
  run.sampling = Sampling{longSide / 8.0};
  optimise(nlopt::GN_CRS2_LM, run, out.u, sh.options->globalEvaluations, 0.0);
  run.sampling = Sampling{longSide / 24.0};
  optimise(nlopt::LN_SBPLX, run, out.u, sh.options->localEvaluations, 0.02);
  out.score = runScore(run.enc.size(), out.u.data(), nullptr, &run);
  return out;
}

Design designAt(const DesignBrief& b, const Start& s, const std::vector<double>& u,
                const Sampling& sampling) {
  Design d;
  d.mode = s.mode;
  d.rotated = s.rotated;
  encodingFor(b, s.rotated).decode(u.data(), d.geometry, d.rect);
  d.evaluation = evaluateDesign(d.geometry, d.mode, d.rect, b.rules, sampling);
  d.score = penalisedScore(b.objective, d.evaluation, b.weights);
  return d;
}

std::string fmt(double v, int decimals = 1) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string describe(const Geometry& g) {
  return "a1=" + fmt(g.a1) + " b1=" + fmt(g.b1) + " a2=" + fmt(g.a2) + " b2=" + fmt(g.b2) +
         " w=" + fmt(g.w) + " mm";
}

// The sentence for an impossible brief, from the closest miss.
std::string impossibleMessage(const DesignBrief& b, const Design& d, const std::string& binding) {
  const Violations& v = d.evaluation.violations;
  const DesignMeasures& m = d.evaluation.measures;
  const std::string rect = fmt(b.widthMm) + " x " + fmt(b.heightMm) + " mm rectangle";
  const std::string closest = " (closest design: " + describe(d.geometry) + ", mode " +
                              std::string(toString(d.mode)) + ")";
  if (binding == "reach")
    return "reach binds: no design with links of " + fmt(b.bounds.minLinkMm) + " to " +
           fmt(b.bounds.maxLinkMm) + " mm and motor spacing of " + fmt(b.bounds.minBaseMm) +
           " to " + fmt(b.bounds.maxBaseMm) + " mm reaches the whole " + rect + "; the closest misses by " +
           fmt(v.reachMm) + " mm" + closest + ". Raise --max-link or shrink the rectangle.";
  if (binding == "typeII")
    return "type II margin binds: the " + rect + " fits the reach, but no design keeps it " +
           fmt(degFromRad(b.rules.workspace.typeIIMarginRad)) +
           " deg from a type II singularity (the closest keeps " +
           fmt(degFromRad(m.minTypeIIMarginRad)) + " deg)" + closest +
           ". Lower --type2-margin or raise --max-link.";
  if (binding == "typeI")
    return "type I margin binds: no design keeps the " + rect + " " +
           fmt(degFromRad(b.rules.workspace.typeIMarginRad)) +
           " deg from a leg fully stretched or folded (the closest keeps " +
           fmt(degFromRad(m.minTypeIMarginRad)) + " deg)" + closest + ".";
  if (binding == "clearance" && v.clearanceMm <= 0.0)  // found before searching
    return "clearance binds: criterion 1 (w >= a1 + a2 + clearance) needs w >= " +
           fmt(2.0 * b.bounds.minLinkMm + b.rules.clearanceMm) + " mm with links of at least " +
           fmt(b.bounds.minLinkMm) + " mm and a clearance of " + fmt(b.rules.clearanceMm) +
           " mm, but --max-base is " + fmt(b.bounds.maxBaseMm) + " mm.";
  if (binding == "clearance")
    return "clearance binds: the designs that reach the " + rect +
           " bring the driving links closer than criterion 1 allows (w >= a1 + a2 + " +
           fmt(b.rules.clearanceMm) + " mm); the closest is " + fmt(v.clearanceMm) + " mm short" +
           closest + ". Raise --max-base or lower --clearance.";
  if (binding == "workSide")
    return "work side binds: the rectangle cannot stay at y >= " + fmt(b.rules.minRectangleYMm) +
           " mm" + closest + ".";
  return binding + " binds" + closest + ".";
}

}  // namespace

DesignRules searchRules(const DesignRules& rules) {
  DesignRules r = rules;
  r.workspace.typeIIMarginRad += kSearchMarginRad;
  r.workspace.typeIMarginRad += kSearchMarginRad;
  return r;
}

std::vector<ValidationIssue> validate(const DesignBrief& b) {
  std::vector<ValidationIssue> issues;
  auto positive = [&](double v, const char* field, Message what) {
    if (!(v > 0.0) || !std::isfinite(v))
      issues.push_back({field, FB_TR("Design", "%1 must be a positive length in mm").arg(std::move(what))});
  };
  positive(b.widthMm, "widthMm", FB_TR("Design", "the rectangle's width"));
  positive(b.heightMm, "heightMm", FB_TR("Design", "the rectangle's height"));
  positive(b.bounds.minLinkMm, "bounds.minLinkMm", FB_TR("Design", "the shortest link"));
  positive(b.bounds.maxLinkMm, "bounds.maxLinkMm", FB_TR("Design", "the longest link"));
  if (b.bounds.minLinkMm > b.bounds.maxLinkMm)
    issues.push_back({"bounds.minLinkMm", FB_TR("Design", "the shortest link (%1 mm) is longer than the longest (%2 mm)")
                                              .arg(b.bounds.minLinkMm, 1)
                                              .arg(b.bounds.maxLinkMm, 1)});
  if (!(b.bounds.minBaseMm >= 0.0) || !std::isfinite(b.bounds.maxBaseMm))
    issues.push_back({"bounds.minBaseMm", FB_TR("Design", "the motor spacing must be 0 mm or more")});
  if (b.bounds.minBaseMm > b.bounds.maxBaseMm)
    issues.push_back({"bounds.minBaseMm", FB_TR("Design", "the smallest motor spacing (%1 mm) exceeds the largest (%2 mm)")
                                              .arg(b.bounds.minBaseMm, 1)
                                              .arg(b.bounds.maxBaseMm, 1)});
  if (!(b.rules.clearanceMm >= 0.0) || !std::isfinite(b.rules.clearanceMm))
    issues.push_back({"rules.clearanceMm", FB_TR("Design", "the clearance must be 0 mm or more")});
  const double t2 = b.rules.workspace.typeIIMarginRad;
  if (!(t2 >= 0.0 && t2 < 0.5 * kPi))
    issues.push_back({"rules.typeIIMargin", FB_TR("Design", "the type II margin must be from 0 to below 90 deg")});
  if (b.objective == Objective::Mix)
    if (Message w = validateWeights(b.weights); !w.empty()) issues.push_back({"weights", std::move(w)});
  return issues;
}

SearchResult searchDesigns(const DesignBrief& brief, const SearchOptions& options,
                           const ProgressFn& progress, const std::atomic<bool>* cancel) {
  const auto t0 = std::chrono::steady_clock::now();
  SearchResult result;
  auto finish = [&] {
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
  };
  // Criterion 1 cannot hold at all: no search needed to say so.
  if (2.0 * brief.bounds.minLinkMm + brief.rules.clearanceMm > brief.bounds.maxBaseMm) {
    result.binding = "clearance";
    result.message = impossibleMessage(brief, Design{}, result.binding);
    return finish();
  }
  std::vector<Start> starts;
  std::vector<WorkingMode> modes;
  if (brief.mode) modes.push_back(*brief.mode);
  else modes.assign(kAllWorkingModes.begin(), kAllWorkingModes.end());
  for (WorkingMode m : modes)
    for (bool rotated : {false, true}) {
      if (rotated && !(brief.allowRotation && brief.widthMm != brief.heightMm)) continue;
      for (int k = 0; k < options.startsPerMode; ++k)
        starts.push_back({m, rotated, options.seed * 7919u + static_cast<std::uint32_t>(starts.size())});
    }
  Shared sh(brief, options, progress, cancel);
  sh.budget = static_cast<long>(starts.size()) * (options.globalEvaluations + options.localEvaluations + 1);
  std::vector<StartResult> results(starts.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < starts.size(); i = next++) results[i] = runStart(sh, starts[i]);
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < std::max(1u, options.threads); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  result.evaluations = sh.evaluations.load();
  if (cancel && cancel->load()) {
    result.status = SearchStatus::Cancelled;
    return finish();
  }
  // Finalists: the best starts, re-evaluated at the final sampling.
  std::vector<std::size_t> order(starts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return results[a].score < results[b].score; });
  for (std::size_t k = 0; k < std::min(kFinalists, order.size()); ++k) {
    const Design d = designAt(brief, starts[order[k]], results[order[k]].u, options.finalSampling);
    if (!result.best || d.score < result.best->score) result.best = d;
  }
  // Trade-off: every start's archive merged in start order, spread, re-evaluated, filtered.
  ParetoArchive<std::size_t> merged;
  std::vector<std::pair<std::size_t, std::size_t>> where;  // (start, point) per merged payload
  for (std::size_t i = 0; i < results.size(); ++i)
    for (std::size_t j = 0; j < results[i].archive.size(); ++j) {
      const auto& p = results[i].archive.points()[j];
      if (merged.insert(p.f1, p.f2, where.size())) where.emplace_back(i, j);
    }
  std::vector<double> f2;
  for (const auto& p : merged.points()) f2.push_back(p.f2);
  ParetoArchive<Design> front;
  if (result.best && result.best->evaluation.feasible())
    front.insert(result.best->evaluation.measures.worstCondition,
                 result.best->evaluation.measures.footprintMm2, *result.best);
  for (std::size_t k : spreadIndices(f2, 2 * options.paretoSize)) {
    const auto [i, j] = where[merged.points()[k].payload];
    const Design d = designAt(brief, starts[i], results[i].archive.points()[j].payload, options.finalSampling);
    if (d.evaluation.feasible())
      front.insert(d.evaluation.measures.worstCondition, d.evaluation.measures.footprintMm2, d);
  }
  std::vector<double> frontF2;
  for (const auto& p : front.points()) frontF2.push_back(p.f2);
  for (std::size_t k : spreadIndices(frontF2, options.paretoSize))
    result.pareto.push_back(front.points()[k].payload);
  if (result.best && result.best->evaluation.feasible()) {
    result.status = SearchStatus::Found;
  } else {
    result.status = SearchStatus::Impossible;
    result.binding = result.best ? result.best->evaluation.violations.binding(kViolationScaleMm) : "reach";
    result.message = impossibleMessage(brief, result.best.value_or(Design{}), result.binding);
  }
  return finish();
}

}  // namespace fivebar::design
