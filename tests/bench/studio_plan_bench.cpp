// SPDX-License-Identifier: GPL-3.0-or-later
// The studio plans as fast as the CLI (docs/performance.md, "Studio planning"): on a drawing of
// 400,000 straight lines (a hatched page), the studio's planning pipeline (runPipeline: core's
// planJob at the document's placement, then the paint-ready scenes and the timed trajectory, all
// on a worker thread) against the CLI's planJob with the same options, in the same process.
// Counter ratio_vs_cli = studio wall time / CLI wall time, the two run alternately (4 pairs,
// each going first in turn). Also the time a cancel takes to stop
// the studio's planning.
#include <benchmark/benchmark.h>

#include <QGuiApplication>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <chrono>
#include <random>
#include <thread>

#include "core/planning/auto_placement.hpp"
#include "core/planning/planner.hpp"
#include "widgets/document/job_pipeline.hpp"

namespace fivebar {
namespace {

constexpr int kLines = 400000;

// Short straight lines (2 to 10 mm) over a 150 x 100 mm page, seeded.
const Drawing& lines() {
  static const Drawing d = [] {
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> x(0, 150), y(0, 100), len(2, 10), angle(0, 6.283185307179586);
    Drawing out;
    out.source = "lines.svg";
    out.widthMm = 150;
    out.heightMm = 100;
    out.layers.resize(1);
    out.layers[0].id = out.layers[0].name = "ink";
    out.layers[0].paths.reserve(kLines);
    for (int i = 0; i < kLines; ++i) {
      const Vec2 a(x(rng), y(rng));
      const double l = len(rng), t = angle(rng);
      out.layers[0].paths.push_back({{a, a + l * Vec2(std::cos(t), std::sin(t))}, false});
    }
    return out;
  }();
  return d;
}

const MachineProfile& machine() {
  static const MachineProfile p = *preset("maker-plotter");
  return p;
}

const Placement& placement() {
  static const Placement p =
      autoPlacement(lines(), machine(), std::nullopt, 0.0, PlacementSizing::TrueSize)->placement;
  return p;
}

void BM_CliPlanJob(benchmark::State& state) {
  const PlanOptions o = widgets::studioPlanOptions(placement(), std::nullopt, 0.1);
  for (auto _ : state) {
    const PlanResult r = planJob(lines(), machine(), o);
    if (!r.ok()) state.SkipWithError(r.message.text().c_str());
    state.counters["segments"] = r.report.segments;
  }
}
BENCHMARK(BM_CliPlanJob)->Unit(benchmark::kSecond)->Iterations(2)->UseRealTime();

// The CLI's planJob and the studio's runPipeline alternately (so that a change of the machine's
// load hits both alike); ratio_vs_cli = summed studio wall time / summed CLI wall time. The
// studio's own stages (after the plan) are reported in seconds per run.
void BM_StudioPipeline(benchmark::State& state) {
  widgets::PipelineInput in;
  in.drawing = std::make_shared<const Drawing>(lines());
  in.placement = placement();
  in.profile = machine();
  in.toleranceMm = 0.1;
  in.cancel = std::make_shared<std::atomic<bool>>(false);
  const PlanOptions o = widgets::studioPlanOptions(placement(), std::nullopt, 0.1);
  double cliS = 0.0, studioS = 0.0;
  StageTimes studioStages, cliStages;
  const auto seconds = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  // Which of the two goes first alternates too: the second of a pair finds the memory the first
  // freed (fewer page faults), which favours it by about 0.1 s.
  bool cliFirst = true;
  for (auto _ : state) {
    const auto cli = [&] {
      cliS += seconds([&] {
        // The very drawing the studio plans (the same memory): a copy laid out afresh plans
        // measurably faster or slower than the original.
        const PlanResult r = planJob(*in.drawing, machine(), o);
        if (!r.ok()) state.SkipWithError(r.message.text().c_str());
        cliStages.append(r.timings);
      });
    };
    const auto studio = [&] {
      studioS += seconds([&] {
        const widgets::PreviewResult r = widgets::runPipeline(in);
        if (r.status != widgets::PreviewStatus::Planned) state.SkipWithError("not planned");
        studioStages.append(r.timings);
      });
    };
    if (cliFirst) {
      cli();
      studio();
    } else {
      studio();
      cli();
    }
    cliFirst = !cliFirst;
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["cli_s"] = cliS / runs;
  state.counters["studio_s"] = studioS / runs;
  state.counters["ratio_vs_cli"] = studioS / cliS;
  // Every stage's wall time per run, the CLI's and the studio's (the studio's own stages come
  // after its plan).
  for (const StageTime& t : cliStages.stages) state.counters["cli: " + t.name] = t.wallS / runs;
  for (const StageTime& t : studioStages.stages) state.counters["studio: " + t.name] = t.wallS / runs;
}
BENCHMARK(BM_StudioPipeline)->Unit(benchmark::kSecond)->Iterations(4)->UseRealTime();

// The studio's own stages one by one on one planned job (seconds, the fastest of 7 runs, no
// other thread busy): the job scene, and the trajectory built and then sampled at 1,000 times
// spread over the job (as scrubbing does: each sample in another chain of moves, timed then).
void BM_StudioStages(benchmark::State& state) {
  const PlanOptions o = widgets::studioPlanOptions(placement(), std::nullopt, 0.1);
  const PlanResult r = planJob(lines(), machine(), o);
  if (!r.ok()) state.SkipWithError(r.message.text().c_str());
  const auto job = std::make_shared<const PlannedJob>(r.job);
  const auto seconds = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  // The fastest of the runs: the cost of the work itself, least disturbed by this virtual
  // machine's neighbours.
  double sceneS = 1e9, buildS = 1e9, sampleS = 1e9;
  for (auto _ : state) {
    sceneS = std::min(sceneS, seconds([&] { benchmark::DoNotOptimize(widgets::jobSceneOf(*job)); }));
    std::shared_ptr<Trajectory> trajectory;
    buildS = std::min(buildS, seconds([&] { trajectory = std::make_shared<Trajectory>(job, machine()); }));
    sampleS = std::min(sampleS, seconds([&] {
      for (int k = 0; k < 1000; ++k) benchmark::DoNotOptimize(trajectory->at(trajectory->durationS() * k / 1000.0));
    }));
  }
  state.counters["job_scene_s"] = sceneS;
  state.counters["trajectory_build_s"] = buildS;
  state.counters["trajectory_1000_samples_s"] = sampleS;
  state.counters["moves"] = static_cast<double>(job->moves.size());
}
BENCHMARK(BM_StudioStages)->Unit(benchmark::kSecond)->Iterations(7)->UseRealTime();

// Cancel raised 1 s into the studio's planning: how long until runPipeline returns.
void BM_StudioCancel(benchmark::State& state) {
  widgets::PipelineInput in;
  in.drawing = std::make_shared<const Drawing>(lines());
  in.placement = placement();
  in.profile = machine();
  in.toleranceMm = 0.1;
  double stopS = 0.0;
  for (auto _ : state) {
    in.cancel = std::make_shared<std::atomic<bool>>(false);
    std::chrono::steady_clock::time_point raised;
    std::thread canceller([&] {
      std::this_thread::sleep_for(std::chrono::seconds(1));
      raised = std::chrono::steady_clock::now();
      in.cancel->store(true);
    });
    const widgets::PreviewResult r = widgets::runPipeline(in);
    const auto done = std::chrono::steady_clock::now();
    canceller.join();
    stopS = std::chrono::duration<double>(done - raised).count();
    if (r.status != widgets::PreviewStatus::Cancelled) state.SkipWithError("not cancelled");
  }
  state.counters["stop_after_cancel_s"] = stopS;
}
BENCHMARK(BM_StudioCancel)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace fivebar

int main(int argc, char** argv) {
  // `--write-svg FILE`: the benchmark's drawing as an SVG (about 16 MB), to time the studio and
  // the CLI end to end on it (fivebar-studio --timings, fivebar plan --timings).
  if (argc == 3 && std::strcmp(argv[1], "--write-svg") == 0) {
    std::ofstream out(argv[2]);
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"150mm\" height=\"100mm\" viewBox=\"0 0 150 100\">\n";
    char buf[128];
    for (const fivebar::Polyline& line : fivebar::lines().layers[0].paths) {
      std::snprintf(buf, sizeof buf, "<path d=\"M%.4f %.4fL%.4f %.4f\" stroke=\"#000\" fill=\"none\"/>\n",
                    line.points[0].x(), line.points[0].y(), line.points[1].x(), line.points[1].y());
      out << buf;
    }
    out << "</svg>\n";
    std::cout << "wrote " << argv[2] << "\n";
    return out ? 0 : 1;
  }
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
