// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar plan` end to end, in process: SVG import (worker process), placement scale, re-import
// when a fit enlarges the drawing, planJob in auto mode (placement, mode screening, optimise,
// segmentation, safety checks, feeds, travel, GRBL time), G-code streamed to a file. Issue 3
// goal: the generated 10 MB SVG in under 2 s wall on the 2-core build machine.
// Reported per case: wall_s (best of the iterations), cpu_s (this process and the worker), the
// per-stage wall times, and two ratios against baselines measured in the same process:
//   vs_read = wall / reading the SVG file into memory (the floor of any import);
//   vs_ik   = wall / scalar inverse kinematics of every imported point (the least any planner
//             does per point).
// Run: build/<dir>/tests/bench/fivebar_bench_plan   (docs/performance/planning.md)
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <optional>
#include <string_view>
#include <string>

#include "core/output/gcode.hpp"
#include "core/import/svg_import.hpp"
#include "core/planning/planner.hpp"
#include "core/machine/profile.hpp"
#include "plotter_svg.hpp"

namespace fivebar {
namespace {

const QString k7kLines = QStringLiteral(FIVEBAR_SHARED_DIR "/corpus/svg/vpype-plotter/benchmark/7k_lines.svg");

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds of this process and its reaped children (the import worker).
double cpuSeconds() {
  double s = 0.0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    getrusage(who, &u);
    s += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return s;
}

std::optional<Drawing> importAt(const QString& path, double toleranceMm) {
  svg::ImportOptions io;
  io.toleranceMm = toleranceMm;
  svg::ImportResult r = svg::importSvgFile(path, io);
  if (!r.ok()) return std::nullopt;
  return std::move(r.drawing);
}

struct EndToEnd {
  bool ok = false;
  int segments = 0;
  std::size_t points = 0;
  double importS = 0.0, planS = 0.0, gcodeS = 0.0;
  Drawing drawing;
};

// What `fivebar plan FILE --machine maker-plotter -o OUT` does (app/cli/cmd_plan.cpp).
EndToEnd planFile(const QString& path, const MachineProfile& p, const std::string& output) {
  EndToEnd e;
  PlanOptions o;
  double t = wallSeconds();
  const double tolerance = importToleranceMm(o.toleranceMm);
  auto drawing = importAt(path, tolerance);
  if (!drawing) return e;
  drawing->flatteningToleranceMm = tolerance;
  e.importS = wallSeconds() - t;
  t = wallSeconds();
  const PlanResult r = planJob(*drawing, p, o);  // true size: no finer import needed
  e.planS = wallSeconds() - t;
  if (!r.ok()) return e;
  t = wallSeconds();
  std::ofstream out(output, std::ios::binary | std::ios::trunc);
  writeGcode(r.job, p, [&](std::string_view piece) {
    out.write(piece.data(), static_cast<std::streamsize>(piece.size()));
  });
  out.close();
  e.gcodeS = wallSeconds() - t;
  e.ok = static_cast<bool>(out);
  e.segments = r.report.segments;
  for (const Layer& l : drawing->layers)
    for (const Polyline& pl : l.paths) e.points += pl.points.size();
  e.drawing = std::move(*drawing);
  return e;
}

void BM_PlanSvgEndToEnd(benchmark::State& state) {
  QTemporaryDir dir;
  QString path = k7kLines;
  if (state.range(0) == 0) {
    path = dir.filePath(QStringLiteral("plotter-10MB.svg"));
    QFile f(path);
    const QByteArray svg = bench::plotterSvg();
    if (!f.open(QIODevice::WriteOnly) || f.write(svg) != svg.size())
      return state.SkipWithError("cannot write the generated SVG");
  } else if (!QFile::exists(path)) {
    return state.SkipWithError("../shared/corpus is absent");
  }
  const MachineProfile p = *preset("maker-plotter");
  const std::string output = dir.filePath(QStringLiteral("job.gcode")).toStdString();
  double best = 1e9, cpu = 0.0;
  EndToEnd last;
  for (auto _ : state) {
    const double start = wallSeconds(), cpuStart = cpuSeconds();
    last = planFile(path, p, output);
    best = std::min(best, wallSeconds() - start);
    cpu += cpuSeconds() - cpuStart;
    if (!last.ok) return state.SkipWithError("planning failed");
  }
  // Baselines, same process.
  double readS = 1e9;
  for (int i = 0; i < 3; ++i) {
    const double start = wallSeconds();
    QFile f(path);
    benchmark::DoNotOptimize(f.open(QIODevice::ReadOnly) ? f.readAll().size() : 0);
    readS = std::min(readS, wallSeconds() - start);
  }
  double ikS = wallSeconds(), sum = 0.0;
  for (const Layer& l : last.drawing.layers)
    for (const Polyline& pl : l.paths)
      for (const Vec2& q : pl.points)
        sum += inverse(p.geometry, Vec2(q.x() - 100, q.y() + 95), WorkingMode::PlusPlus).angles.theta1;
  benchmark::DoNotOptimize(sum);
  ikS = wallSeconds() - ikS;
  state.counters["wall_s"] = best;
  state.counters["cpu_s"] = cpu / static_cast<double>(state.iterations());
  state.counters["import_s"] = last.importS;
  state.counters["plan_s"] = last.planS;
  state.counters["gcode_s"] = last.gcodeS;
  state.counters["points"] = static_cast<double>(last.points);
  state.counters["segments"] = last.segments;
  state.counters["vs_read"] = best / readS;
  state.counters["vs_ik"] = best / ikS;
}
// 0: the generated 10 MB plotter SVG; 1: vpype-plotter's 7k_lines.svg (../shared).
BENCHMARK(BM_PlanSvgEndToEnd)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();

}  // namespace
}  // namespace fivebar

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);  // the import's worker process needs one
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
