// SPDX-License-Identifier: GPL-3.0-or-later
// Workspace maps: all four working modes' overlay maps of hoang2015 on a 512 x 512 grid.
// Baseline (same process): per cell and per mode, the scalar core path (inverse, makePose,
// singularityMargins, transmissionAngles, inverseCondition and the Jacobian's SVD), one thread.
// Figures and the reproducing command: docs/performance/workspace.md.
#include <benchmark/benchmark.h>
#include <time.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

using Clock = std::chrono::steady_clock;

struct PassTime {
  double wall = 0.0;
  double cpu = 0.0;
};

double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class Fn>
PassTime timePass(Fn fn) {
  const auto t0 = Clock::now();
  const double c0 = processCpuSeconds();
  fn();
  benchmark::ClobberMemory();
  return {std::chrono::duration<double>(Clock::now() - t0).count(), processCpuSeconds() - c0};
}

// Benchmarked machines: hoang2015 (a thin crescent, ~30 % of the cells reachable) and
// maker-plotter (~60 % reachable, the heavier case).
constexpr const char* kMachines[] = {"hoang2015", "maker-plotter"};
int current = 0;  // index into kMachines of the running benchmark

const MachineProfile& machine() {
  static const MachineProfile p[2] = {*preset(kMachines[0]), *preset(kMachines[1])};
  return p[current];
}
const WorkspaceSettings& settings() {
  static const WorkspaceSettings s[2] = {workspaceSettings(*preset(kMachines[0])),
                                         workspaceSettings(*preset(kMachines[1]))};
  return s[current];
}
// 512 x 512 cells over the work side (y >= 0) of the reach.
GridSpec makeGrid(int m) {
  GridSpec g = gridCovering(preset(kMachines[m])->geometry, 512, true);
  g.nx = g.ny = 512;
  return g;
}
const GridSpec& grid() {
  static const GridSpec g[2] = {makeGrid(0), makeGrid(1)};
  return g[current];
}

bool withinLimits(double theta, double lo, double hi) {
  for (int k = -2; k <= 2; ++k)
    if (theta + 2.0 * kPi * k >= lo && theta + 2.0 * kPi * k <= hi) return true;
  return false;
}

// The straightforward way: every quantity from the scalar core functions, cell by cell.
void naiveMaps(std::array<WorkspaceMap, 4>& maps) {
  const Geometry& g = machine().geometry;
  const WorkspaceSettings& s = settings();
  const GridSpec& gs = grid();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t m = 0; m < 4; ++m) {
    WorkspaceMap& map = maps[m];
    map.grid = gs;
    map.mode = kAllWorkingModes[m];
    for (auto* v : {&map.reachSlackMm, &map.typeIIMarginRadMap, &map.typeIMarginRadMap,
                    &map.muRad, &map.signedTypeII, &map.inverseCondition, &map.resolutionMm})
      v->assign(gs.size(), nan);
    map.reachable.assign(gs.size(), 0);
    for (int iy = 0; iy < gs.ny; ++iy) {
      for (int ix = 0; ix < gs.nx; ++ix) {
        const std::size_t i = gs.index(ix, iy);
        const Vec2 p(gs.xCenter(ix), gs.yCenter(iy));
        const IkResult ik = inverse(g, p, map.mode);
        if (!ik.ok() || !withinLimits(ik.angles.theta1, s.limits.theta1Min, s.limits.theta1Max) ||
            !withinLimits(ik.angles.theta2, s.limits.theta2Min, s.limits.theta2Max))
          continue;
        const Pose pose = makePose(g, ik.angles, p);
        const SingularityMargins margins = singularityMargins(g, pose);
        map.reachable[i] = 1;
        map.typeIIMarginRadMap[i] = static_cast<float>(margins.typeII);
        map.typeIMarginRadMap[i] = static_cast<float>(margins.typeI());
        map.muRad[i] = static_cast<float>(transmissionAngles(g, pose).mu);
        map.signedTypeII[i] = static_cast<float>(jacobians(g, pose).A.determinant() / (g.b1 * g.b2));
        map.inverseCondition[i] = static_cast<float>(inverseCondition(g, pose));
        if (const auto J = cartesianJacobian(g, pose)) {
          const Eigen::Matrix2d scaled = *J * Eigen::Vector2d(s.stepRad1, s.stepRad2).asDiagonal();
          map.resolutionMm[i] =
              static_cast<float>(Eigen::JacobiSVD<Eigen::Matrix2d>(scaled).singularValues()(0));
        }
      }
    }
  }
}

PassTime measureBaseline() {
  std::array<WorkspaceMap, 4> maps;
  PassTime best{1e30, 1e30};
  for (int k = 0; k < 2; ++k) {
    const PassTime p = timePass([&] { naiveMaps(maps); });
    best.wall = std::min(best.wall, p.wall);
    best.cpu = std::min(best.cpu, p.cpu);
  }
  return best;
}
// The naive pass, measured once per machine and process.
PassTime baseline() {
  static PassTime t[2] = {{-1, -1}, {-1, -1}};
  if (t[current].wall < 0) t[current] = measureBaseline();
  return t[current];
}

// range(0) selects the machine (index into kMachines).
template <class Fn>
void runTimed(benchmark::State& state, Fn fn) {
  current = static_cast<int>(state.range(0));
  state.SetLabel(kMachines[current]);
  const PassTime base = baseline();
  PassTime total;
  for (auto _ : state) {
    const PassTime t = timePass(fn);
    state.SetIterationTime(t.wall);
    total.wall += t.wall;
    total.cpu += t.cpu;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["ms_wall"] = 1e3 * total.wall / n;
  state.counters["ms_cpu"] = 1e3 * total.cpu / n;
  state.counters["speedup"] = base.wall / (total.wall / n);
  state.counters["cpu_speedup"] = base.cpu / (total.cpu / n);
}

void BM_NaiveAllModes(benchmark::State& state) {
  std::array<WorkspaceMap, 4> maps;
  runTimed(state, [&] { naiveMaps(maps); });
}

// Fresh maps each pass (allocation and first touch of ~30 MB included).
void BM_AllModesCold(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  runTimed(state, [&] {
    auto maps = computeAllModes(machine().geometry, settings(), grid(), threads);
    benchmark::DoNotOptimize(maps[0].muRad.data());
  });
}

// Storage reused from the previous pass, as the studio's overlay cache does.
void BM_AllModesWarm(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  current = static_cast<int>(state.range(0));
  std::array<WorkspaceMap, 4> maps;
  computeAllModes(machine().geometry, settings(), grid(), maps, 1);  // allocate outside the timing
  runTimed(state, [&] {
    computeAllModes(machine().geometry, settings(), grid(), maps, threads);
    benchmark::DoNotOptimize(maps[0].muRad.data());
  });
}

// Analysis of one mode's map: areas, contours, the refined rectangle.
void BM_AnalyseOneMode(benchmark::State& state) {
  current = static_cast<int>(state.range(0));
  const WorkspaceMap map = computeMap(machine().geometry, settings(), WorkingMode::PlusPlus, grid());
  runTimed(state, [&] {
    const WorkspaceAnalysis a = analyse(map, machine().geometry, settings());
    benchmark::DoNotOptimize(a.safeAreaMm2);
  });
}

void machines(benchmark::internal::Benchmark* b) {
  b->ArgNames({"machine"})->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond);
}
void machinesAndThreads(benchmark::internal::Benchmark* b) {
  b->ArgNames({"machine", "threads"});
  for (int m = 0; m < 2; ++m)
    for (int t = 1; t <= 2; ++t) b->Args({m, t});
  b->UseManualTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_NaiveAllModes)->Apply(machines)->Iterations(2);
BENCHMARK(BM_AllModesCold)->Apply(machinesAndThreads)->Iterations(10);
BENCHMARK(BM_AllModesWarm)->Apply(machinesAndThreads)->Iterations(20);
BENCHMARK(BM_AnalyseOneMode)->Apply(machines)->Iterations(5);

}  // namespace
}  // namespace fivebar

BENCHMARK_MAIN();
