// SPDX-License-Identifier: GPL-3.0-or-later
// The scan of a calibration sheet (core/calibration/scan) on an A4 page at 600 dpi (4961 x 7016
// px): the hoang2015 pattern (37 marks, the accuracy lines) painted by QPainter, turned 93 deg,
// blurred and noisy. Baselines in the same process: decoding the same page from PNG (what reading
// the file costs anyway), and connected components by a per-pixel label image and flood fill
// (the textbook way, against the run-length labelling the scan uses). Figures:
// docs/performance.md ("Calibration scan").
#include <benchmark/benchmark.h>

#include <QBuffer>
#include <QGuiApplication>
#include <QImageReader>
#include <cstdint>
#include <vector>

#include "../scan/synthetic_scan.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/scan/scan.hpp"
#include "core/calibration/scan/scan_blobs.hpp"
#include "core/calibration/scan/scan_lines.hpp"

namespace fivebar {
namespace {

struct Page {
  CalibrationPattern pattern;
  std::vector<MarkRecord> marks;
  QImage image;
  QByteArray png;
};

const Page& page() {
  static const Page p = [] {
    Page x;
    x.pattern = *makeCalibrationPattern(*preset("hoang2015")).pattern;
    x.marks = parseMarksCsv(marksCsv(x.pattern), "MARKS.csv").marks;
    test::SheetOptions o;
    o.dpi = 600;
    o.rotationDeg = 93.0;
    o.pageWidthMm = 210.0;
    o.pageHeightMm = 297.0;
    o.blurSigmaPx = 1.2;
    o.noiseSigma = 6.0;
    o.seed = 20261201;
    x.image = test::renderSheet(x.pattern, o).image;
    QBuffer buffer(&x.png);
    buffer.open(QIODevice::WriteOnly);
    x.image.save(&buffer, "PNG");
    return x;
  }();
  return p;
}

void BM_ScanA4At600Dpi(benchmark::State& state) {
  const Page& p = page();
  std::size_t found = 0;
  for (auto _ : state) {
    const ScanOutcome s = scanImage(p.image, 600.0, p.marks, "A4");
    if (!s.ok()) state.SkipWithError(s.error.text().c_str());
    found = s.measured.size();
  }
  state.counters["marks"] = static_cast<double>(found);
  state.counters["Mpx"] = p.image.width() * static_cast<double>(p.image.height()) / 1e6;
}

// The page's accuracy lines (among its marks and numbers): their ends, centre and figures.
void BM_ScanLinesA4At600Dpi(benchmark::State& state) {
  const Page& p = page();
  std::size_t lines = 0;
  for (auto _ : state) {
    const LineScanOutcome s = scanAccuracyLines(p.image, 600.0, "A4");
    if (!s.ok()) state.SkipWithError(s.error.text().c_str());
    lines = s.lines.size();
  }
  state.counters["lines"] = static_cast<double>(lines);
}

void BM_RunLengthComponents(benchmark::State& state) {
  const Page& p = page();
  const scan::Levels levels = scan::levelsOf(p.image);
  std::size_t blobs = 0;
  for (auto _ : state) blobs = scan::darkBlobs(p.image, levels).size();
  state.counters["blobs"] = static_cast<double>(blobs);
}

// Baseline: a label per pixel and a flood fill from every unlabelled ink pixel (8-connected).
void BM_BaselineFloodFillComponents(benchmark::State& state) {
  const Page& p = page();
  const scan::Levels levels = scan::levelsOf(p.image);
  const int w = p.image.width(), h = p.image.height();
  std::size_t blobs = 0;
  for (auto _ : state) {
    std::vector<std::int32_t> label(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    std::vector<std::int32_t> stack;
    std::int32_t next = 0;
    for (int y = 0; y < h; ++y) {
      const uchar* row = p.image.constScanLine(y);
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        if (row[x] > levels.threshold || label[i] != 0) continue;
        label[i] = ++next;
        stack.push_back(static_cast<std::int32_t>(i));
        while (!stack.empty()) {
          const std::int32_t k = stack.back();
          stack.pop_back();
          const int ky = k / w, kx = k % w;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = kx + dx, ny = ky + dy;
              if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
              const std::size_t j = static_cast<std::size_t>(ny) * static_cast<std::size_t>(w) + static_cast<std::size_t>(nx);
              if (label[j] != 0 || p.image.constScanLine(ny)[nx] > levels.threshold) continue;
              label[j] = next;
              stack.push_back(static_cast<std::int32_t>(j));
            }
        }
      }
    }
    blobs = static_cast<std::size_t>(next);
    benchmark::DoNotOptimize(label.data());
  }
  state.counters["blobs"] = static_cast<double>(blobs);
}

// Baseline: decoding the page from PNG (reading the scan's file costs this anyway).
void BM_BaselineDecodePng(benchmark::State& state) {
  const Page& p = page();
  for (auto _ : state) {
    QImage img = QImage::fromData(p.png, "PNG");
    benchmark::DoNotOptimize(img.constBits());
  }
  state.counters["MB"] = p.png.size() / 1e6;
}

BENCHMARK(BM_ScanA4At600Dpi)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ScanLinesA4At600Dpi)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RunLengthComponents)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BaselineFloodFillComponents)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BaselineDecodePng)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace fivebar

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  QImageReader::setAllocationLimit(1024);  // MB: the decoded page is larger than the default 128
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
