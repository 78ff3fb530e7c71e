// SPDX-License-Identifier: GPL-3.0-or-later
// SVG import, through the worker's own pipeline in process (importSvgData: the direct reader or
// the sanitiser + Qt SVG, then layers, extent check, page size, work frame; the worker runs the
// same capture on its file). Asserts: a refusal names the file; an accepted drawing has finite
// points within the coordinate bound and no more points than the budget asked.
#include <QByteArray>
#include <QGuiApplication>
#include <QString>

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/import/svg_import.hpp"
#include "fuzz_check.hpp"

namespace {
void quiet(QtMsgType, const QMessageLogContext&, const QString&) {}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  setenv("QT_QPA_PLATFORM", "offscreen", 1);
  qInstallMessageHandler(quiet);
  static QGuiApplication app(*argc, *argv);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar;
  svg::ImportOptions options;
  options.toleranceMm = 0.1;
  options.maxPoints = 200'000;  // the studio's budget question, answered "no"
  options.isolation = svg::Isolation::InProcess;
  const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  const svg::ImportResult result = svg::importSvgData(bytes, QStringLiteral("fuzz.svg"), options);
  if (!result.ok()) {
    const std::string message = result.message.text();
    FUZZ_CHECK(!message.empty(), "a refusal without a message");
    FUZZ_CHECK(fuzz::namesSource(message, "fuzz.svg"), message);
    return 0;
  }
  std::size_t points = 0;
  for (const Layer& layer : result.drawing.layers)
    for (const Polyline& path : layer.paths)
      for (const Vec2& p : path.points) {
        ++points;
        FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()), "a point that is not finite");
        FUZZ_CHECK(std::abs(p.x()) <= options.maxCoordinateMm && std::abs(p.y()) <= options.maxCoordinateMm,
                   "a point beyond the coordinate bound");
      }
  FUZZ_CHECK(points <= options.maxPoints, "more points than the budget");
  return 0;
}
