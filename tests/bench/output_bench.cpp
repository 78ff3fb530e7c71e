// SPDX-License-Identifier: GPL-3.0-or-later
// Job output benchmarks (docs/performance/output.md): writeGcode and estimateJobTime on a seeded
// synthetic PlannedJob of 1.8 million Draw moves, the size of the generated 10 MB SVG job.
// The job is a joint-space random walk with small steps (0.02 .. 0.3 deg, turning up to 0.3 rad
// a move, or 0.05 rad for the "smooth" variant of the time estimate; feed changing every move
// as the planner's per-segment F does) and a pen-up / travel / pen-down every
// 30 .. 50 moves, on the maker-plotter profile (pen servo with settle dwells).
//
// Both functions split a job this size over up to two threads, so the figures are wall clock
// (best_ms, mean_ms over 5 runs), with the CPU time of the calling thread (cpu_ms) and of all
// threads (cpu_all_threads_ms). Each reports the ratio of best_ms to a single-threaded baseline
// measured in the same process (wall clock, best of 3):
//  - BM_WriteGcode: baseline = the same G1 lines ("G1 X%.4f Y%.4f F%.1f") written with a plain
//    snprintf loop into one reserved std::string (no "-0" handling, no comments, no F dedup).
//  - BM_EstimateJobTime: baseline = one pass over the moves computing the constant-speed time
//    |dtheta| / F of each motion move and the running start times (no acceleration model).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <string>

#include "core/output/gcode.hpp"
#include "core/planning/time_estimate.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar {
namespace {

constexpr int kDrawMoves = 1'800'000;
constexpr std::uint64_t kSeed = 20261122;

double cpuS(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
// CPU time of the calling thread, and of all threads of the process (both writeGcode and the
// time estimate split large jobs over two threads).
double threadCpuS() { return cpuS(CLOCK_THREAD_CPUTIME_ID); }
double processCpuS() { return cpuS(CLOCK_PROCESS_CPUTIME_ID); }

double wallS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

JobMove motion(JobMoveKind kind, const JointAngles& target, double feedRadPerS, int stroke) {
  JobMove m;
  m.kind = kind;
  m.target = target;
  m.jointFeedRadPerS = feedRadPerS;
  m.strokeIndex = stroke;
  m.layerIndex = 0;
  return m;
}

JobMove toolMove(JobMoveKind kind, const JointAngles& at, double toolValue, double dwellS) {
  JobMove m;
  m.kind = kind;
  m.target = at;
  m.toolValue = toolValue;
  m.dwellS = dwellS;
  return m;
}

// maxTurnRad: largest change of direction between two draw moves (0.3: jagged, most junctions
// slow; 0.05: smooth curves, the look-ahead window decides).
PlannedJob syntheticJob(const MachineProfile& p, int drawMoves, double maxTurnRad) {
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 1.0), turn(-maxTurnRad, maxTurnRad),
      travelDeg(-8.0, 8.0);
  PlannedJob job;
  job.profileName = p.name;
  job.start = {radFromDeg(120.0), radFromDeg(60.0)};
  job.moves.reserve(static_cast<size_t>(drawMoves) * 11 / 10);
  JointAngles at = job.start;
  double heading = 0.0;
  int drawn = 0;
  while (drawn < drawMoves) {
    const int stroke = static_cast<int>(job.strokes.size());
    const int count = std::min(drawMoves - drawn, 30 + static_cast<int>(u(rng) * 21));
    at = {at.theta1 + radFromDeg(travelDeg(rng)), at.theta2 + radFromDeg(travelDeg(rng))};
    job.moves.push_back(motion(JobMoveKind::Travel, at, radFromDeg(150.0), stroke));
    job.moves.push_back(toolMove(JobMoveKind::PenDown, at, p.tool.penDownS, 0.15));
    PlannedStroke s;
    s.pathIndex = stroke;
    s.firstMove = static_cast<int>(job.moves.size());
    s.moveCount = count;
    job.strokes.push_back(s);
    for (int k = 0; k < count; ++k) {
      heading += turn(rng);
      const double stepDeg = 0.02 + 0.28 * u(rng);
      at = {at.theta1 + radFromDeg(stepDeg * std::cos(heading)),
            at.theta2 + radFromDeg(stepDeg * std::sin(heading))};
      job.moves.push_back(motion(JobMoveKind::Draw, at, radFromDeg(20.0 + 60.0 * u(rng)), stroke));
    }
    drawn += count;
    job.moves.push_back(toolMove(JobMoveKind::PenUp, at, p.tool.penUpS, 0.15));
  }
  job.summary.segments = drawMoves;
  return job;
}

struct Fixture {
  explicit Fixture(double maxTurnRad) : job(syntheticJob(profile, kDrawMoves, maxTurnRad)) {}
  MachineProfile profile = *preset("maker-plotter");
  PlannedJob job;
};
const Fixture& fixture(bool smooth = false) {
  static const Fixture jagged(0.3);
  if (!smooth) return jagged;
  static const Fixture smoothCurves(0.05);
  return smoothCurves;
}

// Baseline for the G-code: the G1 lines with snprintf into one reserved string.
double snprintfBaselineS(const PlannedJob& job, std::string& out) {
  const double t0 = wallS();
  out.clear();
  out.reserve(job.moves.size() * 40);
  char line[128];
  for (const JobMove& m : job.moves) {
    if (!isMotion(m.kind)) continue;
    const int n = std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f F%.1f\n",
                                degFromRad(m.target.theta1), degFromRad(m.target.theta2),
                                degFromRad(m.jointFeedRadPerS) * 60.0);
    out.append(line, static_cast<size_t>(n));
  }
  return wallS() - t0;
}

void BM_WriteGcode(benchmark::State& state) {
  const Fixture& f = fixture();
  std::string baselineText;
  double baselineS = 1e300;
  for (int i = 0; i < 3; ++i) baselineS = std::min(baselineS, snprintfBaselineS(f.job, baselineText));
  double bestS = 1e300, bestWallS = 1e300, sumWallS = 0.0, bestTotalS = 1e300;
  int runs = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    const double w0 = wallS(), t0 = threadCpuS(), p0 = processCpuS();
    const std::string text = writeGcode(f.job, f.profile);
    bestS = std::min(bestS, threadCpuS() - t0);
    bestTotalS = std::min(bestTotalS, processCpuS() - p0);
    bestWallS = std::min(bestWallS, wallS() - w0);
    sumWallS += wallS() - w0;
    ++runs;
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.counters["moves"] = static_cast<double>(f.job.moves.size());
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
  state.counters["cpu_ms"] = bestS * 1e3;
  state.counters["cpu_all_threads_ms"] = bestTotalS * 1e3;
  state.counters["best_ms"] = bestWallS * 1e3;
  state.counters["mean_ms"] = sumWallS / runs * 1e3;
  state.counters["snprintf_ms"] = baselineS * 1e3;
  state.counters["ratio_vs_snprintf"] = bestWallS / baselineS;
}
BENCHMARK(BM_WriteGcode)->Unit(benchmark::kMillisecond)->Iterations(5);

// Baseline for the time estimate: constant-speed |dtheta| / F per motion move, start times.
double constantSpeedBaselineS(PlannedJob& job) {
  const double t0 = wallS();
  JointAngles at = job.start;
  double t = 0.0;
  for (JobMove& m : job.moves) {
    m.startTimeS = t;
    m.durationS = m.kind == JobMoveKind::Dwell || !isMotion(m.kind)
                      ? m.dwellS
                      : std::hypot(m.target.theta1 - at.theta1, m.target.theta2 - at.theta2) /
                            m.jointFeedRadPerS;
    if (isMotion(m.kind)) at = m.target;
    t += m.durationS;
  }
  job.summary.estimatedTimeS = t;
  return wallS() - t0;
}

// state.range(0): 0 = estimateJobTime (returns every move's timing, as the trajectory needs),
// 1 = fillJobTimes (the moves' times only, as the planner needs). state.range(1): 1 = the job
// with smooth curves instead of the jagged one. Both use up to two threads
// on a job this size, so the figures are wall-clock; cpu_ms is the calling thread's share.
void BM_EstimateJobTime(benchmark::State& state) {
  const Fixture& f = fixture(state.range(1) != 0);
  PlannedJob job = f.job;
  double baselineS = 1e300;
  for (int i = 0; i < 3; ++i) baselineS = std::min(baselineS, constantSpeedBaselineS(job));
  const double constantSpeedTotalS = job.summary.estimatedTimeS;
  double bestS = 1e300, bestCpuS = 1e300, sumS = 0.0, bestTotalS = 1e300;
  int runs = 0;
  for (auto _ : state) {
    const double w0 = wallS(), t0 = threadCpuS(), p0 = processCpuS();
    if (state.range(0) == 0) {
      const std::vector<GrblBlockTiming> timings = estimateJobTime(job, f.profile);
      benchmark::DoNotOptimize(timings.data());
    } else {
      fillJobTimes(job, f.profile);
    }
    const double s = wallS() - w0;
    bestCpuS = std::min(bestCpuS, threadCpuS() - t0);
    bestTotalS = std::min(bestTotalS, processCpuS() - p0);
    bestS = std::min(bestS, s);
    sumS += s;
    ++runs;
  }
  state.counters["moves"] = static_cast<double>(job.moves.size());
  state.counters["job_s"] = job.summary.estimatedTimeS;
  state.counters["const_speed_job_s"] = constantSpeedTotalS;
  state.counters["best_ms"] = bestS * 1e3;
  state.counters["mean_ms"] = sumS / runs * 1e3;
  state.counters["cpu_ms"] = bestCpuS * 1e3;
  state.counters["cpu_all_threads_ms"] = bestTotalS * 1e3;
  state.counters["baseline_ms"] = baselineS * 1e3;
  state.counters["ratio_vs_const_speed"] = bestS / baselineS;
}
BENCHMARK(BM_EstimateJobTime)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

}  // namespace
}  // namespace fivebar

BENCHMARK_MAIN();
