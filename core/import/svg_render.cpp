// In-process import: sanitise, render through Qt SVG into the capture engine, group into layers,
// then size, check and flip into the work frame (y up).
#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QSvgRenderer>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>
#include <limits>

#include "capture_engine.hpp"
#include "layers.hpp"
#include "svg_import.hpp"
#include "svg_sanitize.hpp"
#include "svg_units.hpp"

namespace fivebar::svg {

const char* toString(ImportStatus status) {
  switch (status) {
    case ImportStatus::Ok: return "ok";
    case ImportStatus::Cancelled: return "cancelled";
    case ImportStatus::FileError: return "file error";
    case ImportStatus::MalformedXml: return "malformed XML";
    case ImportStatus::InvalidDocument: return "invalid SVG document";
    case ImportStatus::InvalidNumber: return "invalid number";
    case ImportStatus::AbsurdCoordinates: return "absurd coordinates";
    case ImportStatus::RenderFailed: return "render failed";
    case ImportStatus::WorkerCrashed: return "SVG parser crashed";
    case ImportStatus::WorkerTimeout: return "SVG parser timed out";
    case ImportStatus::WorkerNotFound: return "SVG worker not found";
    case ImportStatus::InvalidOptions: return "invalid options";
  }
  return "unknown";
}

namespace {

ImportResult failure(ImportStatus status, const QString& source, const std::string& message) {
  ImportResult r;
  r.status = status;
  r.message = source.toStdString() + ": " + message;
  return r;
}

std::string validateOptions(const ImportOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.toleranceMm)) return "toleranceMm must be a positive number";
  if (!positive(o.dpi)) return "dpi must be a positive number";
  if (!std::isfinite(o.forcedWidthMm) || o.forcedWidthMm < 0.0) return "forcedWidthMm must be >= 0";
  if (!std::isfinite(o.forcedHeightMm) || o.forcedHeightMm < 0.0) return "forcedHeightMm must be >= 0";
  if (!positive(o.maxCoordinateMm)) return "maxCoordinateMm must be a positive number";
  return {};
}

struct Extent {
  double maxX = 0.0, maxY = 0.0;
  std::string problem;  // first refused point, empty when all are fine
};

// Finds the extent of the page-frame points and the first non-finite or absurd point.
Extent inspect(const std::vector<Layer>& layers, double limitMm) {
  Extent e;
  for (const Layer& layer : layers) {
    for (const Polyline& line : layer.paths) {
      for (const Vec2& p : line.points) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
          e.problem = "layer \"" + layer.name + "\" has a non-finite coordinate";
          return e;
        }
        if (std::abs(p.x()) > limitMm || std::abs(p.y()) > limitMm) {
          e.problem = "layer \"" + layer.name + "\" has a point at (" + std::to_string(p.x()) +
                      ", " + std::to_string(p.y()) + ") mm, beyond the " +
                      std::to_string(limitMm) + " mm limit";
          return e;
        }
        e.maxX = std::max(e.maxX, p.x());
        e.maxY = std::max(e.maxY, p.y());
      }
    }
  }
  return e;
}

// Scales for forced page sizes (uniform, fitted and centred when both are forced), then flips
// page (y down) into work (y up): workFromPage = (x, H - y).
void toWorkFrame(Drawing& drawing, const ImportOptions& o) {
  double scale = 1.0, dx = 0.0, dy = 0.0;
  const double w = drawing.widthMm, h = drawing.heightMm;
  if (o.forcedWidthMm > 0.0 && o.forcedHeightMm > 0.0 && w > 0.0 && h > 0.0) {
    scale = std::min(o.forcedWidthMm / w, o.forcedHeightMm / h);
    dx = 0.5 * (o.forcedWidthMm - w * scale);
    dy = 0.5 * (o.forcedHeightMm - h * scale);
    drawing.widthMm = o.forcedWidthMm;
    drawing.heightMm = o.forcedHeightMm;
  } else if (o.forcedWidthMm > 0.0 && w > 0.0) {
    scale = o.forcedWidthMm / w;
    drawing.widthMm = o.forcedWidthMm;
    drawing.heightMm = h * scale;
  } else if (o.forcedHeightMm > 0.0 && h > 0.0) {
    scale = o.forcedHeightMm / h;
    drawing.heightMm = o.forcedHeightMm;
    drawing.widthMm = w * scale;
  }
  const double height = drawing.heightMm;
  for (Layer& layer : drawing.layers)
    for (Polyline& line : layer.paths)
      for (Vec2& p : line.points) p = Vec2(p.x() * scale + dx, height - (p.y() * scale + dy));
}

// Renders the sanitised document into the capture engine; fills runs or returns an error.
// The sanitised text is released once Qt SVG has parsed it.
std::string render(SanitizeResult& clean, const PageSetup& page, const ImportOptions& o,
                   const ProgressFn& progress, std::vector<CapturedRun>& runs) {
  QSvgRenderer renderer;
  bool loaded = false;
  {
    QXmlStreamReader reader(clean.svg);
    loaded = renderer.load(&reader);
  }
  clean.svg = QString();
  if (!loaded) return "Qt SVG could not parse the (sanitised) document";
  renderer.setViewBox(page.viewBoxUser);
  if (progress) progress(0.6);
  CaptureSettings settings;
  settings.toleranceMm = o.toleranceMm;
  settings.outlineFills = o.outlineFills;
  settings.cancel = o.cancel;
  const double shapes = static_cast<double>(std::max<long long>(1, clean.shapeCount));
  if (progress)
    settings.onShape = [&](long long painted) {
      progress(0.6 + 0.35 * std::min(1.0, static_cast<double>(painted) / shapes));
    };
  CaptureDevice device(page.targetMm.right(), page.targetMm.bottom(), settings);
  QPainter painter(&device);
  renderer.render(&painter, page.targetMm);
  painter.end();
  runs = device.engine().takeRuns();
  return {};
}

ImportResult importDevice(QIODevice& input, const QString& source, const ImportOptions& o,
                          const ProgressFn& progress) {
  if (const std::string bad = validateOptions(o); !bad.empty())
    return failure(ImportStatus::InvalidOptions, source, bad);
  auto cancelled = [&] { return o.cancel && o.cancel->load(); };
  SanitizeResult clean = sanitizeSvg(input, o.dpi, [&](double f) {
    if (progress) progress(0.5 * f);
    return !cancelled();
  });
  if (clean.status != ImportStatus::Ok) return failure(clean.status, source, clean.error);
  PageSetup page;
  if (const std::string bad = computePage(clean.root, o.dpi, page); !bad.empty())
    return failure(ImportStatus::InvalidDocument, source,
                   "line " + std::to_string(clean.root.line) + ": " + bad);
  if (progress) progress(0.5);
  std::vector<CapturedRun> runs;
  if (const std::string bad = render(clean, page, o, progress, runs); !bad.empty())
    return failure(ImportStatus::RenderFailed, source, bad);
  if (cancelled()) return failure(ImportStatus::Cancelled, source, "import cancelled");

  ImportResult result;
  result.warnings = clean.warnings;
  Drawing& drawing = result.drawing;
  drawing.source = source.toStdString();
  drawing.layers = buildLayers(std::move(runs), clean.topLevel, o.layerMode);
  const Extent extent = inspect(drawing.layers, o.maxCoordinateMm);
  if (!extent.problem.empty()) return failure(ImportStatus::AbsurdCoordinates, source, extent.problem);
  drawing.widthMm = page.widthMm > 0.0 ? page.widthMm : extent.maxX;
  drawing.heightMm = page.heightMm > 0.0 ? page.heightMm : extent.maxY;
  if (!page.sizeKnown)
    result.warnings.push_back("no usable width/height/viewBox: page size taken from the drawing's extent");
  toWorkFrame(drawing, o);
  if (progress) progress(1.0);
  return result;
}

}  // namespace

ImportResult importSvgData(const QByteArray& data, const QString& sourceName,
                           const ImportOptions& options, const ProgressFn& progress) {
  QBuffer buffer;
  buffer.setData(data);
  buffer.open(QIODevice::ReadOnly);
  return importDevice(buffer, sourceName, options, progress);
}

ImportResult importSvgInProcess(const QString& path, const ImportOptions& options,
                                const ProgressFn& progress) {
  QFile file(path);
  if (!QFileInfo(path).isFile())
    return failure(ImportStatus::FileError, path, "no such file");
  if (!file.open(QIODevice::ReadOnly))
    return failure(ImportStatus::FileError, path, "cannot open: " + file.errorString().toStdString());
  if (file.size() == 0) return failure(ImportStatus::FileError, path, "the file is empty");
  return importDevice(file, path, options, progress);
}

}  // namespace fivebar::svg
