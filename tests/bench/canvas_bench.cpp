// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas painting of a one-million-segment job (docs/performance/studio.md).
// Baseline, measured in the same run: every path drawn with QPainter::drawPolyline and a wide
// antialiased pen, as a naive canvas would. Against it: the level-of-detail PathScene painted
// directly (a re-render, what a zoom step costs) and through the SceneRenderer cache (a pan
// frame). Frames are painted offscreen into a 1280 x 800 QImage.
#include <benchmark/benchmark.h>

#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>

#include "core/kinematics/kinematics.hpp"
#include "paint/machine_painter.hpp"
#include "widgets/canvas/path_scene.hpp"
#include "widgets/canvas/scene_renderer.hpp"
#include "paint/studio_palette.hpp"
#include "paint/view_transform.hpp"

namespace paint = fivebar::paint;

namespace {

using fivebar::widgets::PathKind;
using fivebar::widgets::PathScene;
using fivebar::widgets::SceneRenderer;
using fivebar::widgets::ScenePaintOptions;
using fivebar::widgets::ScenePath;
using fivebar::paint::ViewTransform;

constexpr int kSegments = 1000000;
constexpr int kPointsPerPath = 500;
const QSize kFrame(1280, 800);

// 2000 wavy strokes of 500 points (about 0.3 mm apart) over a 200 x 150 mm page centred at
// (0, 180) mm, joined by travel moves: a dense hatch-like plot of one million segments.
const std::vector<ScenePath>& jobPaths() {
  static const std::vector<ScenePath> paths = [] {
    std::vector<ScenePath> out;
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int strokes = kSegments / (kPointsPerPath - 1);
    int order = 0;
    QPointF last(0.0, 100.0);
    for (int s = 0; s < strokes; ++s) {
      ScenePath p;
      const double y0 = 105.0 + 150.0 * u(rng), x0 = -100.0 + 50.0 * u(rng);
      const double phase = 6.28 * u(rng), amp = 1.0 + 4.0 * u(rng);
      for (int i = 0; i < kPointsPerPath; ++i) {
        const double x = x0 + 0.3 * i;
        p.pointsMm.emplace_back(x, y0 + amp * std::sin(phase + 0.05 * i));
        // Planned feeds vary smoothly along a stroke (slower in the bends).
        if (i > 0) {
          p.speedsMmPerS.push_back(static_cast<float>(20.0 + 20.0 * std::abs(std::cos(phase + 0.05 * i))));
        }
      }
      ScenePath travel;
      travel.kind = PathKind::Travel;
      travel.pointsMm = {last, p.pointsMm.front()};
      travel.firstOrder = order++;
      p.firstOrder = order;
      order += kPointsPerPath - 1;
      last = p.pointsMm.back();
      out.push_back(std::move(travel));
      out.push_back(std::move(p));
    }
    return out;
  }();
  return paths;
}

std::shared_ptr<const PathScene> jobScene() {
  static const auto scene = std::make_shared<const PathScene>(jobPaths());
  return scene;
}

paint::ViewTransform fitView() {
  paint::ViewTransform v(QPointF(0.0, 180.0), 1.0, QSizeF(kFrame));
  v.fit(QRectF(-110.0, 100.0, 220.0, 160.0), 20.0);
  return v;
}

double gBaselineMs = 0.0;

void setRatio(benchmark::State& state, double ownMs) {
  state.counters["ms_per_frame"] = ownMs;
  if (gBaselineMs > 0.0) state.counters["speedup_vs_baseline"] = gBaselineMs / ownMs;
}

double elapsedMs(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void BM_Baseline_WidePolylineAntialiased(benchmark::State& state) {
  const auto& paths = jobPaths();
  const paint::ViewTransform view = fitView();
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  double totalMs = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setTransform(view.widgetFromMachine());
    QPen pen(QColor(0x1d, 0x4e, 0xd8), 0.4);  // 0.4 mm wide, scaled with the view
    painter.setPen(pen);
    for (const ScenePath& p : paths) {
      painter.drawPolyline(p.pointsMm.data(), static_cast<int>(p.pointsMm.size()));
    }
    painter.end();
    totalMs += elapsedMs(t0);
  }
  gBaselineMs = totalMs / static_cast<double>(state.iterations());
  state.counters["ms_per_frame"] = gBaselineMs;
}

void BM_SceneBuild(benchmark::State& state) {
  for (auto _ : state) {
    PathScene scene(jobPaths());
    benchmark::DoNotOptimize(scene.segmentCount());
  }
  state.counters["segments"] = static_cast<double>(jobScene()->segmentCount());
}

// A full re-render (a zoom step) at the given zoom relative to the fitted view.
void BM_Scene_Render(benchmark::State& state) {
  const auto scene = jobScene();
  paint::ViewTransform view = fitView();
  view.zoomAround(QPointF(640.0, 400.0), static_cast<double>(state.range(0)));
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  ScenePaintOptions options;
  options.colourBySpeed = true;
  double totalMs = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    image.fill(Qt::white);
    QPainter painter(&image);
    scene->paint(painter, view, options);
    painter.end();
    totalMs += elapsedMs(t0);
  }
  state.counters["level"] = scene->levelFor(view.pxPerMm());
  state.counters["segments_painted_max"] =
      static_cast<double>(scene->segmentCount(scene->levelFor(view.pxPerMm())));
  setRatio(state, totalMs / static_cast<double>(state.iterations()));
}

// Pan frames: the cached image is blitted; a re-render happens only when the pan leaves the
// cached margin (every ~10 frames here), and its cost is included in the mean.
void BM_Renderer_Pan(benchmark::State& state) {
  const auto scene = jobScene();
  paint::ViewTransform view = fitView();
  view.zoomAround(QPointF(640.0, 400.0), static_cast<double>(state.range(0)));
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  SceneRenderer renderer;
  ScenePaintOptions options;
  options.colourBySpeed = true;
  double totalMs = 0.0;
  int frame = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const double dx = (frame % 40 < 20) ? 37.0 : -37.0;
    const double dy = 11.0 * ((frame % 7) - 3);
    ++frame;
    view.panByPx(QPointF(dx, dy));
    image.fill(Qt::white);
    QPainter painter(&image);
    renderer.paint(painter, view, scene, options, 1);
    painter.end();
    totalMs += elapsedMs(t0);
  }
  state.counters["full_renders"] = renderer.fullRenders();
  setRatio(state, totalMs / static_cast<double>(state.iterations()));
}

// Wheel zoom frames around the cursor: every frame is at a new scale (a full re-render).
void BM_Renderer_WheelZoom(benchmark::State& state) {
  const auto scene = jobScene();
  paint::ViewTransform view = fitView();
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  SceneRenderer renderer;
  ScenePaintOptions options;
  options.colourBySpeed = true;
  double totalMs = 0.0;
  int frame = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    view.zoomAround(QPointF(500.0, 300.0), (frame++ % 24 < 12) ? 1.2 : 1.0 / 1.2);
    image.fill(Qt::white);
    QPainter painter(&image);
    renderer.paint(painter, view, scene, options, 1);
    painter.end();
    totalMs += elapsedMs(t0);
  }
  setRatio(state, totalMs / static_cast<double>(state.iterations()));
}

// Wheel zoom with quick zoom (the studio's canvas): zoom frames scale the cached image; the
// settled re-render after each burst of 6 wheel steps is included in the mean.
void BM_Renderer_WheelZoomQuick(benchmark::State& state) {
  const auto scene = jobScene();
  paint::ViewTransform view = fitView();
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  SceneRenderer renderer;
  ScenePaintOptions options;
  options.colourBySpeed = true;
  double totalMs = 0.0;
  int frame = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const bool settle = frame % 7 == 6;
    if (!settle) view.zoomAround(QPointF(500.0, 300.0), (frame % 28 < 14) ? 1.2 : 1.0 / 1.2);
    ++frame;
    renderer.setQuickZoom(!settle);
    image.fill(Qt::white);
    QPainter painter(&image);
    renderer.paint(painter, view, scene, options, 1);
    painter.end();
    totalMs += elapsedMs(t0);
  }
  state.counters["preview_frames"] = renderer.previewFrames();
  state.counters["full_renders"] = renderer.fullRenders();
  setRatio(state, totalMs / static_cast<double>(state.iterations()));
}

// Simulation playback frames (the studio at 60 Hz, speed x10). The file's job is ScenePaths, not
// a PlannedJob, so the clock is mimicked: each order (segment or travel move) lasts its length
// over its feed (travel at 100 mm/s); per frame the time advances by 10/60 s, the pen point is
// interpolated in the current move and the linkage posed by inverse kinematics (a 200/200 mm
// arm machine, motors 100 mm apart). The frame is painted as the canvas does while simulating:
// grid, the job faded (opacity 0.25), the trace up to the completed moves grown incrementally,
// then the machine (opacity 0.85). The workspace and legend layers are not painted.
struct SimTimeline {
  std::vector<double> endS;      // per order: cumulative time at its end
  std::vector<QPointF> fromMm;   // per order: start point
  std::vector<QPointF> toMm;     // per order: end point
};

const SimTimeline& simTimeline() {
  static const SimTimeline timeline = [] {
    SimTimeline t;
    double now = 0.0;
    for (const ScenePath& p : jobPaths()) {
      for (std::size_t i = 0; i + 1 < p.pointsMm.size(); ++i) {
        const QPointF a = p.pointsMm[i], b = p.pointsMm[i + 1];
        const double len = std::hypot(b.x() - a.x(), b.y() - a.y());
        const double feed = p.speedsMmPerS.empty() ? 100.0 : p.speedsMmPerS[i];
        now += len / feed;
        t.endS.push_back(now);
        t.fromMm.push_back(a);
        t.toMm.push_back(b);
      }
    }
    return t;
  }();
  return timeline;
}

void BM_Simulation_Frame(benchmark::State& state) {
  constexpr double kSpeed = 10.0;
  const auto scene = jobScene();
  const SimTimeline& timeline = simTimeline();
  fivebar::Geometry g;
  g.a1 = g.a2 = 200.0;
  g.b1 = g.b2 = 200.0;
  g.w = 100.0;
  const paint::ViewTransform view = fitView();
  QImage image(kFrame, QImage::Format_ARGB32_Premultiplied);
  SceneRenderer mainRenderer;
  SceneRenderer traceRenderer;
  ScenePaintOptions faded;
  faded.colourBySpeed = true;
  faded.opacity = 0.25;
  ScenePaintOptions trace;
  trace.colourBySpeed = false;
  trace.drawColour = fivebar::paint::palette::trace();
  trace.penWidthPx = 1.5;
  fivebar::Pose pose;
  bool havePose = false;
  double timeS = 0.0;
  int ikFailures = 0;
  double totalMs = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    timeS += kSpeed / 60.0;
    const auto it = std::upper_bound(timeline.endS.begin(), timeline.endS.end(), timeS);
    const int move = static_cast<int>(it - timeline.endS.begin());  // moves fully done
    QPointF penMm = timeline.toMm.back();
    if (move < static_cast<int>(timeline.endS.size())) {
      const double start = move > 0 ? timeline.endS[move - 1] : 0.0;
      const double span = timeline.endS[move] - start;
      const double f = span > 0.0 ? (timeS - start) / span : 1.0;
      penMm = timeline.fromMm[move] + f * (timeline.toMm[move] - timeline.fromMm[move]);
    }
    const fivebar::Vec2 p(penMm.x(), penMm.y());
    const fivebar::IkResult ik = fivebar::inverse(g, p, fivebar::WorkingMode::PlusMinus);
    if (ik.ok()) {
      pose = fivebar::makePose(g, ik.angles, p);
      havePose = true;
    } else {
      ++ikFailures;
    }
    trace.orderLimit = move;
    image.fill(Qt::white);
    QPainter painter(&image);
    fivebar::paint::paintGrid(painter, view);
    mainRenderer.paint(painter, view, scene, faded, 1u | 16u);
    traceRenderer.paint(painter, view, scene, trace, 32u);
    if (havePose) fivebar::paint::paintMachine(painter, view.widgetFromMachine(), g, pose, 0.85);
    painter.end();
    totalMs += elapsedMs(t0);
  }
  const double ms = totalMs / static_cast<double>(state.iterations());
  state.counters["fps"] = 1000.0 / ms;
  state.counters["sim_time_s"] = timeS;
  state.counters["ik_failures"] = ikFailures;
  state.counters["full_renders"] = mainRenderer.fullRenders() + traceRenderer.fullRenders();
  state.counters["trace_incremental_renders"] = traceRenderer.incrementalRenders();
  setRatio(state, ms);
}

BENCHMARK(BM_Baseline_WidePolylineAntialiased)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_SceneBuild)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Scene_Render)->Arg(1)->Arg(4)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Renderer_Pan)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Renderer_WheelZoom)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Renderer_WheelZoomQuick)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Simulation_Frame)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
