// SPDX-License-Identifier: GPL-3.0-or-later
// In-process import: the direct reader for plain documents (fast_import.hpp); otherwise sanitise
// and render through Qt SVG into the capture engine. Then group into layers, size, check and flip
// into the work frame (y up).
#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QXmlStreamReader>

#include <algorithm>
#include <cmath>
#include <limits>

#include "capture_engine.hpp"
#include "core/text/hershey_font.hpp"
#include "clip.hpp"
#include "fast_import.hpp"
#include "import_pipeline.hpp"
#include "layers.hpp"
#include "svg_import.hpp"
#include "svg_sanitize.hpp"
#include "svg_units.hpp"
#include "svgz.hpp"
#include "svg_text_redraw.hpp"

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
    case ImportStatus::TooManyPoints: return "too many points";
  }
  return "unknown";
}

namespace {

ImportResult failure(ImportStatus status, const QString& source, Message message) {
  ImportResult r;
  r.status = status;
  r.message = FB_TR("ImportError", "%1: %2").arg(source.toStdString()).arg(std::move(message));
  return r;
}

std::string validateOptions(const ImportOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.toleranceMm)) return "toleranceMm must be a positive number";
  if (!positive(o.dpi)) return "dpi must be a positive number";
  if (!std::isfinite(o.forcedWidthMm) || o.forcedWidthMm < 0.0) return "forcedWidthMm must be >= 0";
  if (!std::isfinite(o.forcedHeightMm) || o.forcedHeightMm < 0.0) return "forcedHeightMm must be >= 0";
  if (!positive(o.maxCoordinateMm)) return "maxCoordinateMm must be a positive number";
  if (!o.textFont.empty())
    if (const text::FontLoad load = text::loadFont(o.textFont); !load.font)
      return "text font: " + text::toString(load.error);
  return {};
}

struct Extent {
  double maxX = 0.0, maxY = 0.0;
  Message problem;  // first refused point, empty when all are fine
};

// Finds the extent of the page-frame points and the first non-finite or absurd point.
Extent inspect(const std::vector<Layer>& layers, double limitMm) {
  Extent e;
  for (const Layer& layer : layers) {
    for (const Polyline& line : layer.paths) {
      for (const Vec2& p : line.points) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
          e.problem = FB_TR("ImportError", "layer \"%1\" has a non-finite coordinate").arg(layer.name);
          return e;
        }
        if (std::abs(p.x()) > limitMm || std::abs(p.y()) > limitMm) {
          e.problem = FB_TR("ImportError", "layer \"%1\" has a point at (%2, %3) mm, beyond the %4 mm limit")
                          .arg(layer.name)
                          .arg(p.x(), 6)
                          .arg(p.y(), 6)
                          .arg(limitMm, 6);
          return e;
        }
        e.maxX = std::max(e.maxX, p.x());
        e.maxY = std::max(e.maxY, p.y());
      }
    }
  }
  return e;
}

// Drops every page-frame polyline with a non-finite point or a point beyond limitMm (an absurd
// transform or coordinate), with one warning per top-level element naming it and the first such
// point; returns the first problem (empty when none), which refuses the file when nothing is left.
Message dropAbsurdLines(std::vector<CapturedRun>& runs, const std::vector<TopLevelElement>& topLevel,
                        double limitMm, std::vector<Message>& warnings) {
  Message first;
  int warnedTop = -2;
  for (CapturedRun& run : runs) {
    std::erase_if(run.paths, [&](const Polyline& line) {
      const auto bad = std::find_if(line.points.begin(), line.points.end(), [&](const Vec2& p) {
        return !std::isfinite(p.x()) || !std::isfinite(p.y()) || std::abs(p.x()) > limitMm ||
               std::abs(p.y()) > limitMm;
      });
      if (bad == line.points.end()) return false;
      std::string element = "the drawing";
      if (run.topIndex >= 0 && static_cast<std::size_t>(run.topIndex) < topLevel.size()) {
        const TopLevelElement& top = topLevel[static_cast<std::size_t>(run.topIndex)];
        element = (top.id.isEmpty() ? QStringLiteral("<%1>").arg(top.tag)
                                    : QStringLiteral("<%1 id=\"%2\">").arg(top.tag, top.id))
                      .toStdString();
      }
      Message problem =
          std::isfinite(bad->x()) && std::isfinite(bad->y())
              ? FB_TR("ImportError", "%1 has a point at (%2, %3) mm, beyond the %4 mm limit")
                    .arg(element).arg(bad->x(), 6).arg(bad->y(), 6).arg(limitMm, 6)
              : FB_TR("ImportError", "%1 has a non-finite coordinate").arg(element);
      if (run.topIndex != warnedTop) {
        warnings.push_back(FB_TR("ImportWarning", "%1: its lines there are not drawn").arg(problem));
        warnedTop = run.topIndex;
      }
      if (first.empty()) first = std::move(problem);
      return true;
    });
  }
  if (!first.empty()) std::erase_if(runs, [](const CapturedRun& run) { return run.paths.empty(); });
  return first;
}

// The page is the root viewport: a browser shows nothing outside it (a viewBox not at the
// origin, "slice", content beyond the size). Lines reaching outside are cut at its edge (clip.hpp),
// with one warning; a page of unknown size (the drawing's extent) cuts nothing.
void clipToPage(std::vector<CapturedRun>& runs, const PageSetup& page, std::vector<Message>& warnings) {
  if (!page.sizeKnown || !(page.widthMm > 0.0) || !(page.heightMm > 0.0)) return;
  constexpr double kEdgeMm = 1e-9;
  const double w = page.widthMm, h = page.heightMm;
  auto outside = [&](const Polyline& line) {
    return std::any_of(line.points.begin(), line.points.end(), [&](const Vec2& p) {
      return p.x() < -kEdgeMm || p.y() < -kEdgeMm || p.x() > w + kEdgeMm || p.y() > h + kEdgeMm;
    });
  };
  const std::vector<ClipShape> pageRect{{{{Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)}}, FillRule::NonZero}};
  bool cut = false;
  for (CapturedRun& run : runs) {
    if (std::none_of(run.paths.begin(), run.paths.end(), outside)) continue;
    cut = true;
    run.paths = clipLines(std::move(run.paths), pageRect);
  }
  if (!cut) return;
  std::erase_if(runs, [](const CapturedRun& run) { return run.paths.empty(); });
  warnings.push_back(FB_TR("ImportWarning", "lines outside the page (the SVG viewport) are not drawn: cut at its edge"));
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
                   const ProgressFn& progress, std::vector<CapturedRun>& runs, bool& overBudget) {
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
  settings.dashes = o.dashes == DashMode::Dashed;
  settings.cancel = o.cancel;
  settings.maxPoints = o.maxPoints;
  const double shapes = static_cast<double>(std::max<long long>(1, clean.shapeCount));
  if (progress)
    settings.onShape = [&](long long painted) {
      progress(0.6 + 0.35 * std::min(1.0, static_cast<double>(painted) / shapes));
    };
  CaptureDevice device(page.targetMm.right(), page.targetMm.bottom(), settings);
  QPainter painter(&device);
  renderer.render(&painter, page.targetMm);
  painter.end();
  overBudget = device.engine().overBudget();
  runs = device.engine().takeRuns();
  return {};
}

Message tooManyPoints(const ImportOptions& o) {
  return FB_TR("ImportError", "more than %1 points after flattening (the points budget): reading stopped there")
      .arg(static_cast<long long>(o.maxPoints));
}

Message cancelledMessage() { return FB_TR("ImportError", "import cancelled"); }

Capture failed(ImportStatus status, const QString& source, Message message) {
  Capture c;
  c.status = status;
  c.message = FB_TR("ImportError", "%1: %2").arg(source.toStdString()).arg(std::move(message));
  return c;
}

// The general path: sanitiser, Qt SVG, capture engine (options already validated).
Capture captureGeneral(QIODevice& input, const QString& source, const ImportOptions& o,
                       const ProgressFn& progress) {
  auto cancelled = [&] { return o.cancel && o.cancel->load(); };
  SanitizeResult clean = sanitizeSvg(input, o.dpi, [&](double f) {
    if (progress) progress(0.5 * f);
    return !cancelled();
  });
  if (clean.status != ImportStatus::Ok) return failed(clean.status, source, clean.error);
  Capture capture;
  if (Message bad = computePage(clean.root, o.dpi, capture.page); !bad.empty())
    return failed(ImportStatus::InvalidDocument, source,
                  FB_TR("ImportError", "line %1: %2").arg(static_cast<long long>(clean.root.line)).arg(std::move(bad)));
  if (progress) progress(0.5);
  bool overBudget = false;
  if (const std::string bad = render(clean, capture.page, o, progress, capture.runs, overBudget);
      !bad.empty())
    return failed(ImportStatus::RenderFailed, source, bad);
  if (overBudget) return failed(ImportStatus::TooManyPoints, source, tooManyPoints(o));
  if (cancelled()) return failed(ImportStatus::Cancelled, source, cancelledMessage());
  capture.topLevel = std::move(clean.topLevel);
  capture.warnings = std::move(clean.warnings);
  return capture;
}

ImportOptions withoutTextFont(ImportOptions o) {
  o.textFont.clear();
  return o;
}

// The document with its <text> redrawn in o.textFont (svg_text_redraw.hpp). Documents in UTF-8
// (or ASCII) only: another declared encoding keeps its text as outlines, with a warning.
QByteArray redrawText(const QByteArray& data, const ImportOptions& o, std::vector<Message>& warnings) {
  static const QRegularExpression declaredEncoding(QStringLiteral("^\\s*<\\?xml[^>]*encoding\\s*=\\s*[\"']([^\"']+)"));
  const QRegularExpressionMatch m = declaredEncoding.match(QString::fromLatin1(data.left(200)));
  if (m.hasMatch() && m.captured(1).compare(QStringLiteral("utf-8"), Qt::CaseInsensitive) != 0 &&
      m.captured(1).compare(QStringLiteral("us-ascii"), Qt::CaseInsensitive) != 0) {
    warnings.push_back(FB_TR("ImportWarning", "text in a single-stroke font: only UTF-8 documents, this one is "
                                              "%1: its text is drawn as outlines").arg(m.captured(1).toStdString()));
    return data;
  }
  text::FontLoad load = text::loadFont(o.textFont);
  if (!load.font) return data;  // validateOptions refused it already
  return redrawTextInFont(QString::fromUtf8(data), *load.font, o.dpi, warnings).toUtf8();
}

// The direct reader when the document is in its subset, else the general path.
Capture captureBytes(const QByteArray& data, const QString& source, const ImportOptions& o,
                     const ProgressFn& progress, bool allowDirect, const RunSink& sink) {
  if (const std::string bad = validateOptions(o); !bad.empty())
    return failed(ImportStatus::InvalidOptions, source, bad);
  if (isGzip(data)) {  // .svgz
    QByteArray plain;
    if (const std::string bad = gunzip(data, kMaxDecompressedBytes, plain); !bad.empty())
      return failed(ImportStatus::FileError, source, FB_TR("ImportError", "compressed SVG (gzip): %1").arg(bad));
    if (plain.isEmpty()) return failed(ImportStatus::FileError, source, FB_TR("ImportError", "the compressed file is empty"));
    return captureBytes(plain, source, o, progress, allowDirect, sink);
  }
  if (!o.textFont.empty() && data.contains("<text")) {
    // <text> redrawn in the single-stroke font before anything else reads the document.
    std::vector<Message> textWarnings;
    QByteArray redrawn = redrawText(data, o, textWarnings);
    Capture capture = captureBytes(redrawn, source, withoutTextFont(o), progress, allowDirect, sink);
    capture.warnings.insert(capture.warnings.begin(), textWarnings.begin(), textWarnings.end());
    return capture;
  }
  if (allowDirect) {
    DirectCapture direct;
    const ProgressFn scaled = [&](double f) {
      if (progress) progress(0.95 * f);
    };
    switch (captureDirect(data, o, scaled, direct, sink)) {
      case DirectStatus::Cancelled: return failed(ImportStatus::Cancelled, source, cancelledMessage());
      case DirectStatus::TooManyPoints:
        return failed(ImportStatus::TooManyPoints, source, tooManyPoints(o));
      case DirectStatus::Captured: {
        Capture capture;
        capture.runs = std::move(direct.runs);
        capture.topLevel = std::move(direct.topLevel);
        capture.page = direct.page;
        return capture;
      }
      case DirectStatus::Declined:
        if (sink && sink.restart) sink.restart();
        break;
    }
  }
  QBuffer buffer;
  buffer.setData(data);
  buffer.open(QIODevice::ReadOnly);
  return captureGeneral(buffer, source, o, progress);
}

}  // namespace

ImportResult finishImport(Capture&& capture, const QString& source, const ImportOptions& o,
                          const ProgressFn& progress) {
  ImportResult result;
  if (capture.status != ImportStatus::Ok) {
    result.status = capture.status;
    result.message = std::move(capture.message);
    return result;
  }
  result.warnings = std::move(capture.warnings);
  Message absurd = dropAbsurdLines(capture.runs, capture.topLevel, o.maxCoordinateMm, result.warnings);
  if (absurd.empty()) clipToPage(capture.runs, capture.page, result.warnings);
  Drawing& drawing = result.drawing;
  drawing.source = source.toStdString();
  drawing.layers = buildLayers(std::move(capture.runs), capture.topLevel, o.layerMode);
  if (!absurd.empty() && std::none_of(drawing.layers.begin(), drawing.layers.end(),
                                      [](const Layer& l) { return !l.paths.empty(); }))
    return failure(ImportStatus::AbsurdCoordinates, source, std::move(absurd));  // nothing left
  Extent extent = inspect(drawing.layers, o.maxCoordinateMm);
  if (!extent.problem.empty()) return failure(ImportStatus::AbsurdCoordinates, source, std::move(extent.problem));
  const PageSetup& page = capture.page;
  drawing.widthMm = page.widthMm > 0.0 ? page.widthMm : extent.maxX;
  drawing.heightMm = page.heightMm > 0.0 ? page.heightMm : extent.maxY;
  if (!page.sizeKnown)
    result.warnings.push_back(FB_TR("ImportWarning", "no usable width/height/viewBox: page size taken from the drawing's extent"));
  toWorkFrame(drawing, o);
  if (progress) progress(1.0);
  return result;
}

ImportResult importSvgData(const QByteArray& data, const QString& sourceName,
                           const ImportOptions& options, const ProgressFn& progress) {
  return finishImport(captureBytes(data, sourceName, options, progress, true, {}), sourceName,
                      options, progress);
}

ImportResult importSvgDataGeneral(const QByteArray& data, const QString& sourceName,
                                  const ImportOptions& options, const ProgressFn& progress) {
  return finishImport(captureBytes(data, sourceName, options, progress, false, {}), sourceName,
                      options, progress);
}

Capture captureSvgFile(const QString& path, const ImportOptions& options, const ProgressFn& progress,
                       const RunSink& sink) {
  QFile file(path);
  if (!QFileInfo(path).isFile()) return failed(ImportStatus::FileError, path, FB_TR("ImportError", "no such file"));
  if (!file.open(QIODevice::ReadOnly))
    return failed(ImportStatus::FileError, path, FB_TR("ImportError", "cannot open: %1").arg(file.errorString().toStdString()));
  if (file.size() == 0) return failed(ImportStatus::FileError, path, FB_TR("ImportError", "the file is empty"));
  const QByteArray data = file.readAll();
  if (file.error() != QFileDevice::NoError)
    return failed(ImportStatus::FileError, path, FB_TR("ImportError", "cannot read: %1").arg(file.errorString().toStdString()));
  return captureBytes(data, path, options, progress, true, sink);
}

ImportResult importSvgInProcess(const QString& path, const ImportOptions& options,
                                const ProgressFn& progress) {
  return finishImport(captureSvgFile(path, options, progress), path, options, progress);
}

}  // namespace fivebar::svg
