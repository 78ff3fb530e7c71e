// SPDX-License-Identifier: GPL-3.0-or-later
// Job planning speed: preflight (core/feasibility.hpp) of a 100k-point job and optimisation
// (core/optimise.hpp) of 100k strokes, on the dai2022 machine. Baseline measured in the same
// process: the bare scalar inverse kinematics of the same points (what any per-point check
// must at least do). Counters: ms per job (CPU time of this thread), ratio_vs_ik = job CPU time
// divided by the baseline's, and for the optimiser the travel time before / after.
// Reproduce: see docs/performance/planning.md.
#include <benchmark/benchmark.h>

#include <ctime>
#include <random>
#include <vector>

#include "core/planning/feasibility.hpp"
#include "core/planning/optimise.hpp"

namespace fivebar {
namespace {

const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};

MachineProfile daiProfile() {
  MachineProfile p;
  p.geometry = kDai;
  p.homeAngles = inverse(kDai, {0.0, 180.0}, WorkingMode::PlusPlus).angles;
  return p;
}

// 1000 hatch lines of 100 points (0.8 mm apart) inside the '++' safe region.
const std::vector<Stroke>& hatchJob() {
  static const std::vector<Stroke> job = [] {
    std::vector<Stroke> out;
    for (int i = 0; i < 1000; ++i) {
      Stroke s;
      s.pathIndex = i;
      const double y = 150.0 + 0.06 * i;
      for (int k = 0; k < 100; ++k) s.points.push_back({-40.0 + 0.8 * k, y});
      out.push_back(s);
    }
    return out;
  }();
  return job;
}

// 100k random short strokes (4 points) in a reachable patch, in random order.
const std::vector<Stroke>& randomStrokes() {
  static const std::vector<Stroke> strokes = [] {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> x(-50.0, 50.0), y(130.0, 200.0), step(-4.0, 4.0);
    std::vector<Stroke> out;
    for (int i = 0; i < 100000; ++i) {
      Stroke s;
      s.pathIndex = i;
      Vec2 p(x(rng), y(rng));
      for (int k = 0; k < 4; ++k, p += Vec2(step(rng), step(rng))) s.points.push_back(p);
      out.push_back(s);
    }
    return out;
  }();
  return strokes;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// CPU seconds of the scalar IK of every point of `strokes` (best of 5).
double ikBaselineS(const std::vector<Stroke>& strokes) {
  double best = 1e9;
  for (int rep = 0; rep < 5; ++rep) {
    const double t0 = cpuSeconds();
    double sink = 0.0;
    for (const Stroke& s : strokes)
      for (const Vec2& p : s.points) sink += inverse(kDai, p, WorkingMode::PlusPlus).angles.theta1;
    benchmark::DoNotOptimize(sink);
    best = std::min(best, cpuSeconds() - t0);
  }
  return best;
}

void report(benchmark::State& state, double cpuS, double baselineS) {
  const double perJob = cpuS / static_cast<double>(state.iterations());
  state.counters["ms_per_job"] = 1e3 * perJob;
  state.counters["baseline_ik_ms"] = 1e3 * baselineS;
  state.counters["ratio_vs_ik"] = perJob / baselineS;
}

void BM_Preflight100kPoints(benchmark::State& state) {
  const MachineProfile pr = daiProfile();
  const double baseline = ikBaselineS(hatchJob());
  double cpu = 0.0;
  bool feasible = false;
  for (auto _ : state) {
    const double t0 = cpuSeconds();
    feasible = preflight(hatchJob(), pr, WorkingMode::PlusPlus).feasible;
    cpu += cpuSeconds() - t0;
  }
  if (!feasible) state.SkipWithError("the benchmark job must be feasible");
  report(state, cpu, baseline);
}
BENCHMARK(BM_Preflight100kPoints)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_Optimise100kStrokes(benchmark::State& state) {
  const MachineProfile pr = daiProfile();
  const double baseline = ikBaselineS(randomStrokes());
  OptimiseOptions o;
  o.join = state.range(0) != 0;
  o.maxTwoOptPasses = static_cast<int>(state.range(1));
  double cpu = 0.0;
  OptimiseReport r;
  for (auto _ : state) {
    const double t0 = cpuSeconds();
    r = optimise(randomStrokes(), pr, WorkingMode::PlusPlus, o).report;
    cpu += cpuSeconds() - t0;
  }
  report(state, cpu, baseline);
  state.counters["travel_before_s"] = r.travelBeforeS;
  state.counters["travel_after_s"] = r.travelAfterS;
  state.counters["joins"] = static_cast<double>(r.joins);
}
// Args: join (0/1), 2-opt passes (0 = greedy nearest neighbour only).
BENCHMARK(BM_Optimise100kStrokes)->Args({0, 0})->Args({0, 50})->Args({1, 50})
    ->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace fivebar

BENCHMARK_MAIN();
