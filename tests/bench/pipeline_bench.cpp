// SPDX-License-Identifier: GPL-3.0-or-later
// Job pipeline benchmarks (docs/performance/planning.md):
//  - Segments: adaptive segmentation vs the firmware-style baseline (every flattened piece cut to
//    0.5 mm) at EQUAL maximum deviation from the true curves (circles, measured analytically);
//    counters: segments of each and their ratio.
//  - Pipeline: planJob (placement, preflight, optimise, segmentation, feeds, travel, timing) and
//    writeGcode on a generated drawing the size of a 10 MB SVG; baseline in the same process: the
//    bare inverse kinematics of every point; counter ratio_vs_ik.
// `fivebar_bench_pipeline --write-svg FILE` writes that generated drawing as an SVG (~10 MB) for
// the end-to-end CLI timing.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>

#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/segmentation.hpp"

namespace fivebar {
namespace {

// --- generated drawing: cubic Bezier "petals" and straight hatching, 200 x 150 mm page ---
struct Cubic {
  Vec2 p0, p1, p2, p3;
};
struct Generated {
  std::vector<std::vector<Cubic>> curves;          // each a path of joined cubics
  std::vector<std::vector<Vec2>> lines;            // each a straight polyline
};

Generated generate(int paths, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(10, 190), y(10, 140), d(-6, 6), u(0, 1);
  Generated g;
  for (int i = 0; i < paths; ++i) {
    if (u(rng) < 0.6) {
      std::vector<Cubic> path;
      Vec2 at(x(rng), y(rng));
      const int n = 3 + static_cast<int>(u(rng) * 8);
      for (int k = 0; k < n; ++k) {
        const Vec2 p1 = at + Vec2(d(rng), d(rng)), p3 = at + Vec2(d(rng), d(rng));
        const Vec2 p2 = p3 + Vec2(d(rng), d(rng));
        const Vec2 clamp3(std::clamp(p3.x(), 1.0, 199.0), std::clamp(p3.y(), 1.0, 149.0));
        path.push_back({at, p1, p2, clamp3});
        at = clamp3;
      }
      g.curves.push_back(path);
    } else {
      std::vector<Vec2> line;
      const int n = 2 + static_cast<int>(u(rng) * 6);
      for (int k = 0; k < n; ++k) line.emplace_back(x(rng), y(rng));
      g.lines.push_back(line);
    }
  }
  return g;
}

Vec2 bezier(const Cubic& c, double t) {
  const double s = 1 - t;
  return s * s * s * c.p0 + 3 * s * s * t * c.p1 + 3 * s * t * t * c.p2 + t * t * t * c.p3;
}

// Flattening as an importer does: enough uniform pieces that the chord error is below tol
// (bound from the second derivative of the cubic).
Drawing toDrawing(const Generated& g, double tolMm) {
  Drawing d;
  d.source = "generated";
  d.layers.resize(1);
  d.layers[0].name = "ink";
  for (const auto& path : g.curves) {
    Polyline pl;
    for (const Cubic& c : path) {
      const double dd = std::max((c.p0 - 2 * c.p1 + c.p2).norm(), (c.p1 - 2 * c.p2 + c.p3).norm());
      const int n = std::max(1, static_cast<int>(std::ceil(std::sqrt(6.0 * dd / (8.0 * tolMm)))));
      if (pl.points.empty()) pl.points.push_back(c.p0);
      for (int k = 1; k <= n; ++k) pl.points.push_back(bezier(c, static_cast<double>(k) / n));
    }
    d.layers[0].paths.push_back(pl);
  }
  for (const auto& line : g.lines) d.layers[0].paths.push_back({line, false});
  return d;
}

void writeSvg(const Generated& g, const std::string& file) {
  std::ofstream out(file);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"150mm\" "
         "viewBox=\"0 0 200 150\">\n<g fill=\"none\" stroke=\"black\" stroke-width=\"0.3\">\n";
  out.setf(std::ios::fixed);
  out.precision(3);
  auto pt = [&](const Vec2& p) { out << p.x() << ' ' << (150.0 - p.y()); };
  for (const auto& path : g.curves) {
    out << "<path d=\"M";
    pt(path[0].p0);
    for (const Cubic& c : path) {
      out << " C";
      pt(c.p1);
      out << ' ';
      pt(c.p2);
      out << ' ';
      pt(c.p3);
    }
    out << "\"/>\n";
  }
  for (const auto& line : g.lines) {
    out << "<polyline points=\"";
    for (const Vec2& p : line) { pt(p); out << ' '; }
    out << "\"/>\n";
  }
  out << "</g>\n</svg>\n";
}

// About 10 MB of SVG text (measured with --write-svg).
constexpr int kTenMegabytePaths = 42000;
constexpr std::uint64_t kSeed = 20261122;

void BM_PipelineGenerated(benchmark::State& state) {
  const MachineProfile p = *preset("maker-plotter");
  const Drawing d = toDrawing(generate(static_cast<int>(state.range(0)), kSeed), 0.04);
  size_t points = 0;
  for (const Polyline& pl : d.layers[0].paths) points += pl.points.size();
  // Baseline: bare IK of every point at true size around (0, 170).
  auto ikRun = [&] {
    double sum = 0.0;
    for (const Polyline& pl : d.layers[0].paths)
      for (const Vec2& q : pl.points)
        sum += inverse(p.geometry, Vec2(q.x() - 100, q.y() + 95), WorkingMode::PlusPlus).angles.theta1;
    return sum;
  };
  const auto t0 = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(ikRun());
  const double ikS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  PlanResult r;
  double planS = 0.0;
  for (auto _ : state) {
    const auto t1 = std::chrono::steady_clock::now();
    PlanOptions o;  // fit into the ++ singularity-free rectangle
    o.mode = WorkingMode::PlusPlus;
    r = planJob(d, p, o);
    const std::string gcode = writeGcode(r.job, p);
    benchmark::DoNotOptimize(gcode.data());
    planS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["segments"] = r.report.segments;
  state.counters["ok"] = r.ok() ? 1 : 0;
  state.counters["plan_ms"] = planS * 1000;
  state.counters["ik_ms"] = ikS * 1000;
  state.counters["ratio_vs_ik"] = planS / ikS;
}
BENCHMARK(BM_PipelineGenerated)->Arg(kTenMegabytePaths)->Unit(benchmark::kMillisecond)->Iterations(2);

// Circles flattened with chords of sagitta <= flattenMm.
std::vector<Vec2> flattenedCircle(const Vec2& c, double r, double flattenMm) {
  const int n = static_cast<int>(std::ceil(kPi / std::acos(1.0 - flattenMm / r)));
  std::vector<Vec2> pts;
  for (int i = 0; i <= n; ++i)
    pts.emplace_back(c + r * Vec2(std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n)));
  return pts;
}

double deviationFromCircle(const MachineProfile& p, const SegmentedStroke& s, const Vec2& c,
                           double r) {
  double worst = 0.0;
  for (size_t k = 1; k < s.waypoints.size(); ++k) {
    const JointAngles a = s.waypoints[k - 1].q, b = s.waypoints[k].q;
    for (int i = 0; i <= 40; ++i) {
      const double u = i / 40.0;
      const FkResult fk = forward(p.geometry, {a.theta1 + u * (b.theta1 - a.theta1),
                                               a.theta2 + u * (b.theta2 - a.theta2)}, p.assembly);
      worst = std::max(worst, std::abs((fk.p - c).norm() - r));
    }
  }
  return worst;
}

// state.range(0): baseline piece length in micrometres (500 = 0.5 mm; 200 = 200 segments/s at
// 40 mm/s).
void BM_SegmentsAtEqualDeviation(benchmark::State& state) {
  const MachineProfile p = *preset("maker-plotter");
  const double step = state.range(0) / 1000.0;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> cx(-40, 40), cy(150, 190), rr(2, 40);
  struct Case { Vec2 c; double r; };
  std::vector<Case> cases;
  for (int i = 0; i < 200; ++i) cases.push_back({{cx(rng), cy(rng)}, rr(rng)});
  double fixedSegs = 0, adaptiveSegs = 0, worstFixed = 0, worstAdaptive = 0, fixedS = 0, adaptiveS = 0;
  for (auto _ : state) {
    fixedSegs = adaptiveSegs = worstFixed = worstAdaptive = fixedS = adaptiveS = 0;
    for (const Case& k : cases) {
      const auto t0 = std::chrono::steady_clock::now();
      const SegmentedStroke f = segmentFixedLength(p.geometry, WorkingMode::PlusPlus, p.assembly,
                                                   flattenedCircle(k.c, k.r, 0.05), p.homeAngles, step);
      const auto t1 = std::chrono::steady_clock::now();
      const double total = deviationFromCircle(p, f, k.c, k.r);
      const auto t2 = std::chrono::steady_clock::now();
      const SegmentedStroke a =
          segmentStroke(p.geometry, WorkingMode::PlusPlus, p.assembly,
                        flattenedCircle(k.c, k.r, 0.4 * total), p.homeAngles, {0.6 * total});
      const auto t3 = std::chrono::steady_clock::now();
      fixedS += std::chrono::duration<double>(t1 - t0).count();
      adaptiveS += std::chrono::duration<double>(t3 - t2).count();
      fixedSegs += static_cast<double>(f.waypoints.size() - 1);
      adaptiveSegs += static_cast<double>(a.waypoints.size() - 1);
      worstFixed = std::max(worstFixed, total);
      worstAdaptive = std::max(worstAdaptive, deviationFromCircle(p, a, k.c, k.r) / total);
    }
  }
  state.counters["fixed_segments"] = fixedSegs;
  state.counters["adaptive_segments"] = adaptiveSegs;
  state.counters["segment_ratio"] = adaptiveSegs / fixedSegs;
  state.counters["worst_dev_fixed_mm"] = worstFixed;
  state.counters["adaptive_dev_over_fixed"] = worstAdaptive;  // <= 1: equal or better
  state.counters["time_ratio"] = adaptiveS / fixedS;
}
BENCHMARK(BM_SegmentsAtEqualDeviation)->Arg(500)->Arg(200)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace fivebar

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--write-svg") == 0) {
    fivebar::writeSvg(fivebar::generate(fivebar::kTenMegabytePaths, fivebar::kSeed), argv[2]);
    std::cout << "wrote " << argv[2] << "\n";
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
