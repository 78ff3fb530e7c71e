// SPDX-License-Identifier: GPL-3.0-or-later
// Batch kinematics (core/batch.hpp) against the scalar API in a loop, on 10 million points of
// the hoang2015 machine. Every benchmark reports ns_per_point (wall clock) and speedup = scalar
// ns/point divided by its own, the scalar figure being measured in this same process; and the
// same two from process CPU time (all threads summed: cpu_ns_per_point, cpu_speedup), which
// stay meaningful on a machine shared with other work.
// Reproduce: see docs/performance/kinematics.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/kinematics/batch.hpp"
#include "core/kinematics/kinematics.hpp"

namespace fivebar {
namespace {

constexpr std::size_t kPoints = 10'000'000;
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};
constexpr WorkingMode kMode = WorkingMode::PlusPlus;
constexpr AssemblyMode kAssembly = AssemblyMode::Plus;

// Inputs and outputs shared by all benchmarks: points in a box around the work area (about 9 in
// 10 reachable) and their ++ angles as FK input.
struct Data {
  std::vector<double> x, y, t1, t2, outA, outB;
  std::vector<std::uint8_t> ok, reachable;
  Data()
      : x(kPoints),
        y(kPoints),
        t1(kPoints),
        t2(kPoints),
        outA(kPoints),
        outB(kPoints),
        ok(kPoints),
        reachable(kPoints) {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> ux(-150.0, 150.0), uy(60.0, 250.0);
    for (std::size_t i = 0; i < kPoints; ++i) {
      x[i] = ux(rng);
      y[i] = uy(rng);
      const IkResult ik = inverse(kHoang, Vec2(x[i], y[i]), kMode);
      t1[i] = ik.ok() ? ik.angles.theta1 : 0.0;
      t2[i] = ik.ok() ? ik.angles.theta2 : 0.0;
      reachable[i] = ik.ok() ? 1 : 0;
    }
  }
};
Data& data() {
  static Data d;
  return d;
}

// Largest batch error over the reachable points after a pass: IK angles against the scalar
// angles t1, t2 (rad); FK positions against the original points x, y (mm, a round trip).
double maxAngleErrorRad(const Data& d) {
  double worst = 0.0;
  for (std::size_t i = 0; i < kPoints; ++i)
    if (d.reachable[i])
      worst = std::max({worst, std::abs(std::remainder(d.outA[i] - d.t1[i], 2.0 * kPi)),
                        std::abs(std::remainder(d.outB[i] - d.t2[i], 2.0 * kPi))});
  return worst;
}
double maxRoundTripErrorMm(const Data& d) {
  double worst = 0.0;
  for (std::size_t i = 0; i < kPoints; ++i)
    if (d.reachable[i]) worst = std::max(worst, std::hypot(d.outA[i] - d.x[i], d.outB[i] - d.y[i]));
  return worst;
}

using Clock = std::chrono::steady_clock;

// CPU seconds used by the whole process (all threads) so far.
double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Wall and CPU seconds of one pass.
struct PassTime {
  double wall = 0.0;
  double cpu = 0.0;
};
template <class Fn>
PassTime timePass(Fn fn) {
  Data& d = data();  // generated once, outside the timing
  const auto t0 = Clock::now();
  const double c0 = processCpuSeconds();
  fn(d);
  benchmark::ClobberMemory();
  return {std::chrono::duration<double>(Clock::now() - t0).count(), processCpuSeconds() - c0};
}

void scalarInverse(Data& d) {
  for (std::size_t i = 0; i < kPoints; ++i) {
    const IkResult r = inverse(kHoang, Vec2(d.x[i], d.y[i]), kMode);
    d.outA[i] = r.angles.theta1;
    d.outB[i] = r.angles.theta2;
    d.ok[i] = r.ok() ? 1 : 0;
  }
}
void scalarForward(Data& d) {
  for (std::size_t i = 0; i < kPoints; ++i) {
    const FkResult r = forward(kHoang, JointAngles{d.t1[i], d.t2[i]}, kAssembly);
    d.outA[i] = r.p.x();
    d.outB[i] = r.p.y();
    d.ok[i] = r.ok() ? 1 : 0;
  }
}

// One pass of fn (best of two, wall and CPU separately), measured once per process: the baseline.
template <class Fn>
PassTime bestPass(Fn fn) {
  PassTime best{1e30, 1e30};
  for (int k = 0; k < 2; ++k) {
    const PassTime t = timePass(fn);
    best.wall = std::min(best.wall, t.wall);
    best.cpu = std::min(best.cpu, t.cpu);
  }
  return best;
}
PassTime scalarInverseBaseline() {
  static const PassTime t = bestPass(scalarInverse);
  return t;
}
PassTime scalarForwardBaseline() {
  static const PassTime t = bestPass(scalarForward);
  return t;
}

// Times fn per iteration by hand and reports per-point times and speed-ups against baseline.
template <class Fn>
void runTimed(benchmark::State& state, PassTime baseline, std::optional<BatchKernel> kernel,
              Fn fn) {
  PassTime total;
  for (auto _ : state) {
    const PassTime t = timePass(fn);
    benchmark::DoNotOptimize(data().outA.data());
    state.SetIterationTime(t.wall);
    total.wall += t.wall;
    total.cpu += t.cpu;
  }
  const double passes = static_cast<double>(state.iterations());
  const double wall = total.wall / passes, cpu = total.cpu / passes;
  state.counters["ns_per_point"] = wall * 1e9 / static_cast<double>(kPoints);
  state.counters["speedup"] = baseline.wall / wall;
  state.counters["cpu_ns_per_point"] = cpu * 1e9 / static_cast<double>(kPoints);
  state.counters["cpu_speedup"] = baseline.cpu / cpu;
  if (!kernel) {
    state.SetLabel("scalar libm");
  } else {
    state.SetLabel("batch " + std::string(*kernel == BatchKernel::Auto ? batchKernelName()
                                                                       : toString(*kernel)));
  }
}

void BM_InverseScalar(benchmark::State& state) {
  runTimed(state, scalarInverseBaseline(), std::nullopt, scalarInverse);
}

// Batch arguments: threads, kernel (BatchKernel as an int).
BatchOptions batchOptions(const benchmark::State& state) {
  return {static_cast<unsigned>(state.range(0)), std::size_t{1} << 16,
          static_cast<BatchKernel>(state.range(1))};
}
bool skipUnsupported(benchmark::State& state) {
  if (batchKernelSupported(static_cast<BatchKernel>(state.range(1)))) return false;
  state.SkipWithError("kernel not supported by this CPU");
  return true;
}

void BM_InverseBatch(benchmark::State& state) {
  if (skipUnsupported(state)) return;
  const BatchOptions options = batchOptions(state);
  runTimed(state, scalarInverseBaseline(), options.kernel, [&](Data& d) {
    inverseBatch(kHoang, kMode, d.x.data(), d.y.data(), kPoints, d.outA.data(), d.outB.data(),
                 d.ok.data(), options);
  });
  state.counters["max_err_rad"] = maxAngleErrorRad(data());
}
void BM_ForwardScalar(benchmark::State& state) {
  runTimed(state, scalarForwardBaseline(), std::nullopt, scalarForward);
}
void BM_ForwardBatch(benchmark::State& state) {
  if (skipUnsupported(state)) return;
  const BatchOptions options = batchOptions(state);
  runTimed(state, scalarForwardBaseline(), options.kernel, [&](Data& d) {
    forwardBatch(kHoang, kAssembly, d.t1.data(), d.t2.data(), kPoints, d.outA.data(), d.outB.data(),
                 d.ok.data(), options);
  });
  state.counters["max_roundtrip_mm"] = maxRoundTripErrorMm(data());
}

// (threads, kernel): each variant on one thread, then the automatic choice on two.
void batchArgs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"threads", "kernel"});
  b->Args({1, static_cast<int>(BatchKernel::Generic)});
  b->Args({1, static_cast<int>(BatchKernel::Avx2)});
  b->Args({1, static_cast<int>(BatchKernel::Avx512)});
  b->Args({2, static_cast<int>(BatchKernel::Auto)});
  b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(10);
}

BENCHMARK(BM_InverseScalar)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_InverseBatch)->Apply(batchArgs);
BENCHMARK(BM_ForwardScalar)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ForwardBatch)->Apply(batchArgs);

}  // namespace
}  // namespace fivebar

BENCHMARK_MAIN();
