// SPDX-License-Identifier: GPL-3.0-or-later
// Design search (core/design) on the goal brief: 110 x 90 mm, links <= 200 mm, motor
// spacing <= 250 mm, clearance 10 mm, type II margin >= 15 deg, all four working modes.
// Baselines in the same process: the same search on one thread (parallel speed-up), and a
// seeded random search over the same variables and rules given the same wall time (what the
// NLopt global + local methods buy). Figures: docs/performance.md ("Design search").
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <random>

#include "core/design/placement.hpp"
#include "core/design/search.hpp"

namespace fivebar::design {
namespace {

using Clock = std::chrono::steady_clock;

DesignBrief goalBrief() {
  DesignBrief b;
  b.widthMm = 110.0;
  b.heightMm = 90.0;
  b.bounds.maxLinkMm = 200.0;
  b.bounds.maxBaseMm = 250.0;
  b.rules.clearanceMm = 10.0;
  b.rules.workspace.typeIIMarginRad = radFromDeg(15.0);
  return b;
}

double lastSearchSeconds = 4.0;  // wall time of the last 2-thread search: the random budget

void BM_Search(benchmark::State& state) {
  const DesignBrief b = goalBrief();
  SearchOptions o;
  o.threads = static_cast<unsigned>(state.range(0));
  double kappa = 0.0, seconds = 0.0;
  long evaluations = 0;
  for (auto _ : state) {
    const SearchResult r = searchDesigns(b, o);
    kappa = r.best ? r.best->evaluation.measures.worstCondition : 0.0;
    seconds = r.seconds;
    evaluations = r.evaluations;
  }
  if (o.threads == 2) lastSearchSeconds = seconds;
  state.counters["worstCondition"] = kappa;
  state.counters["evaluations"] = static_cast<double>(evaluations);
  state.counters["evalsPerSecond"] = evaluations / std::max(seconds, 1e-9);
}
BENCHMARK(BM_Search)->Arg(1)->Arg(2)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// Random search: uniform lengths, spacing and rectangle centre in a uniformly chosen mode, each
// candidate evaluated like the search's local phase (110 / 24 mm sampling); the best feasible
// one re-evaluated at 1 mm. Runs for the 2-thread search's wall time on one thread per core.
void BM_RandomSearchSameTime(benchmark::State& state) {
  const DesignBrief b = goalBrief();
  const DesignRules rules = searchRules(b.rules);
  double best = 0.0;
  long evaluations = 0;
  for (auto _ : state) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> link(b.bounds.minLinkMm, b.bounds.maxLinkMm),
        base(b.bounds.minBaseMm, b.bounds.maxBaseMm), cx(-b.bounds.maxLinkMm, b.bounds.maxLinkMm),
        cy(45.0, 2.0 * b.bounds.maxLinkMm - 45.0);
    std::uniform_int_distribution<int> mode(0, 3);
    double bestScore = kInfeasibleScore * 10.0;
    Design bestDesign;
    evaluations = 0;
    const auto deadline = Clock::now() + std::chrono::duration<double>(2.0 * lastSearchSeconds);
    while (Clock::now() < deadline) {  // 2 x wall time on one thread = the search's 2 cores
      for (int k = 0; k < 64; ++k, ++evaluations) {
        Design d;
        d.geometry = {link(rng), link(rng), link(rng), link(rng), base(rng)};
        d.mode = kAllWorkingModes[static_cast<std::size_t>(mode(rng))];
        d.rect = centredRect(cx(rng), cy(rng), b.widthMm, b.heightMm);
        const double s = penalisedScore(b.objective, evaluateDesign(d.geometry, d.mode, d.rect, rules, Sampling{110.0 / 24.0}), b.weights);
        if (s < bestScore) {
          bestScore = s;
          bestDesign = d;
        }
      }
    }
    const Evaluation e = evaluateDesign(bestDesign.geometry, bestDesign.mode, bestDesign.rect, b.rules);
    best = e.feasible() ? e.measures.worstCondition : std::numeric_limits<double>::infinity();
  }
  state.counters["worstCondition"] = best;
  state.counters["evaluations"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_RandomSearchSameTime)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// One evaluation of hoang2015's rectangle at the search's three samplings.
void BM_Evaluate(benchmark::State& state) {
  const Geometry g{70, 200, 70, 200, 250};
  const DesignRules rules;
  const Rect r = centredRect(0.0, 155.7, 110.0, 90.0);
  const double spacing = 110.0 / static_cast<double>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(evaluateDesign(g, WorkingMode::PlusPlus, r, rules, Sampling{spacing}));
  state.counters["samples"] = static_cast<double>(rectangleSamples(r, spacing).size());
}
BENCHMARK(BM_Evaluate)->Arg(8)->Arg(24)->Arg(110)->Unit(benchmark::kMicrosecond);

// Best placement of the 110 x 90 mm rectangle for hoang2015 (scan + local Subplex).
void BM_BestPlacementHoang(benchmark::State& state) {
  const Geometry g{70, 200, 70, 200, 250};
  double kappa = 0.0;
  for (auto _ : state) kappa = bestPlacement(g, WorkingMode::PlusPlus, 110.0, 90.0, DesignRules{}).evaluation.measures.worstCondition;
  state.counters["worstCondition"] = kappa;
}
BENCHMARK(BM_BestPlacementHoang)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fivebar::design

BENCHMARK_MAIN();
