// SPDX-License-Identifier: GPL-3.0-or-later
// Calibration (issue 13, docs/calibration.md): the goal scenario of tests/core/calibration_fit_test.cpp
// as a benchmark. Accuracy figures are counters (shape error over the working area before and after,
// their ratio); speed is the whole fit against the baseline of placing the paper on the nominal model
// (what a maker gets without calibration), in the same process.
// Run: build/release/tests/bench/fivebar_bench_calibration
#include <benchmark/benchmark.h>

#include "../core/calibration_scenario.hpp"

namespace fivebar {
namespace {

constexpr std::uint64_t kSeed = 20261122;

const MachineProfile& nominal() {
  static const MachineProfile p = *preset("maker-plotter");
  return p;
}
const Rect& area() {
  static const Rect r = test::workingArea(nominal());
  return r;
}
const std::vector<calibration::MarkMeasurement>& marks() {
  static const auto m = test::measuredMarks(nominal(), kSeed, true);
  return m;
}

// Baseline: the nominal model's predictions of the 25 marks placed rigidly on the measurements.
void BM_BaselineNominalPlacement(benchmark::State& state) {
  const calibration::MachineParameters m = calibration::parametersOf(nominal());
  for (auto _ : state) {
    std::vector<Vec2> predicted, measured;
    for (const auto& mark : marks()) {
      predicted.push_back(*calibration::penPosition(m, nominal().assembly, mark.commanded));
      measured.push_back(mark.paperMm);
    }
    benchmark::DoNotOptimize(calibration::bestRigidPlacement(predicted, measured, true));
  }
}
BENCHMARK(BM_BaselineNominalPlacement)->Unit(benchmark::kMicrosecond);

void fitAndReport(benchmark::State& state, const std::vector<calibration::MarkMeasurement>& input) {
  calibration::CalibrationFit fit;
  for (auto _ : state) {
    fit = calibration::fitMarks(nominal(), input);
    benchmark::DoNotOptimize(fit);
  }
  if (!fit.ok()) {
    state.SkipWithError(fit.reason.text().c_str());
    return;
  }
  const auto before = test::areaShapeError(nominal(), area());
  const auto after = test::areaShapeError(calibration::calibratedProfile(nominal(), fit, "2026-12-01"), area());
  state.counters["beforeMaxMm"] = before.maxMm;
  state.counters["afterMaxMm"] = after.maxMm;
  state.counters["afterRmsMm"] = after.rmsMm;
  state.counters["heldOutRmsMm"] = fit.heldOutRmsMm;
  state.counters["improvement"] = before.maxMm / after.maxMm;
  state.counters["outliers"] = double(fit.outlierIds.size());
  state.counters["cond"] = fit.conditionNumber;
  state.counters["evaluations"] = fit.functionEvaluations;
}

void BM_CalibrationFit25Marks(benchmark::State& state) { fitAndReport(state, marks()); }
BENCHMARK(BM_CalibrationFit25Marks)->Unit(benchmark::kMillisecond);

void BM_CalibrationFitOneMarkOff3Mm(benchmark::State& state) {
  auto input = marks();
  input[12].paperMm += Vec2(3.0, 0.0);
  fitAndReport(state, input);
}
BENCHMARK(BM_CalibrationFitOneMarkOff3Mm)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fivebar

BENCHMARK_MAIN();
