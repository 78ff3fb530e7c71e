// The studio plans as fast as the CLI (docs/performance.md, "Studio planning"): on a drawing of
// 400,000 straight lines (a hatched page), the studio's planning pipeline (runPipeline: core's
// planJob at the document's placement, then the paint-ready scenes and the timed trajectory, all
// on a worker thread) against the CLI's planJob with the same options, in the same process.
// Counter ratio_vs_cli = studio wall time / CLI wall time, the two run alternately. Also the time a cancel takes to stop
// the studio's planning.
#include <benchmark/benchmark.h>

#include <QGuiApplication>

#include <atomic>
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
  StageTimes studio;
  const auto seconds = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  for (auto _ : state) {
    cliS += seconds([&] {
      const PlanResult r = planJob(lines(), machine(), o);
      if (!r.ok()) state.SkipWithError(r.message.text().c_str());
    });
    studioS += seconds([&] {
      const widgets::PreviewResult r = widgets::runPipeline(in);
      if (r.status != widgets::PreviewStatus::Planned) state.SkipWithError("not planned");
      studio.append(r.timings);
    });
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["cli_s"] = cliS / runs;
  state.counters["studio_s"] = studioS / runs;
  state.counters["ratio_vs_cli"] = studioS / cliS;
  for (const StageTime& t : studio.stages)
    if (t.name == "drawing scene" || t.name == "job scene and trajectory")
      state.counters[t.name] = t.wallS / runs;
}
BENCHMARK(BM_StudioPipeline)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

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
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
