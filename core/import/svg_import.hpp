// SPDX-License-Identifier: GPL-3.0-or-later
// SVG import: an SVG file -> fivebar::Drawing (docs/svg-import.md).
//
// Output frame: the work frame, millimetres, y UP, origin at the bottom-left corner of the page
// (the SVG viewport). The SVG's y-down frame is flipped here and nowhere else:
//   workFromPage: x_work = x_page, y_work = heightMm - y_page.
// Curves are flattened so that every point of the true curve lies within toleranceMm of the
// polyline. Each SVG subpath becomes its own Polyline (pen up in between).
//
// Two entry points:
//  - importSvgFile: the safe one. Sanitises and parses in a child process (fivebar-svg-worker)
//    under a time and memory limit; a crash or hang of Qt SVG ends in an error, not in the caller.
//  - importSvgInProcess: the same work in this process (used by the worker itself, and by callers
//    that trust their input). Needs a QGuiApplication (text outlines need fonts).
#pragma once

#include <QString>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/support/message.hpp"

namespace fivebar::svg {

// How painted shapes are grouped into Drawing layers.
enum class LayerMode {
  Auto,     // Inkscape layers if any; else top-level groups if >= 2; everything else by colour
  ByGroup,  // every top-level <g> is a layer; loose top-level shapes by colour
  ByColor,  // one layer per stroke colour (fill colour for outlined fills)
};

// How a dashed stroke (stroke-dasharray) is drawn.
enum class DashMode {
  Dashed,  // as SVG draws it: the dashes, pen up between them (dasharray, dashoffset)
  Solid,   // the whole stroke, as if it had no dasharray
};

enum class Isolation {
  WorkerProcess,  // parse in fivebar-svg-worker (default for importSvgFile)
  InProcess,      // parse in this process: faster start, no protection against Qt SVG crashes
};

struct ImportOptions {
  double toleranceMm = 0.05;  // max distance between a true curve and its polyline, mm (> 0)
  double dpi = 96.0;          // user units and "px" per inch (CSS/Inkscape: 96)
  double forcedWidthMm = 0.0;   // > 0: page width in mm regardless of the file
  double forcedHeightMm = 0.0;  // > 0: page height in mm; one forced side keeps the aspect ratio
  bool outlineFills = true;     // fill-only shapes are drawn as their outline; false: skipped
  DashMode dashes = DashMode::Dashed;  // dashed strokes: their dashes (pen up between), or solid
  LayerMode layerMode = LayerMode::Auto;
  double maxCoordinateMm = 1.0e6;  // any point beyond this (absolute, mm) refuses the file
  // Points after flattening the import may produce; 0 = no limit. Reading stops as soon as the
  // count passes it (status TooManyPoints), before the rest of the file is flattened.
  std::size_t maxPoints = 0;
  // Non-empty: SVG <text> is redrawn in this Hershey single-stroke font (core/text: a font
  // name such as "futural", or a .jhf path) instead of the outlines of its own font. Empty:
  // the outlines, as Qt SVG draws them (docs/svg-import.md).
  std::string textFont;

  // Process isolation (importSvgFile only).
  Isolation isolation = Isolation::WorkerProcess;
  QString workerPath;               // explicit worker executable; empty = search (see docs)
  double timeoutS = 10.0;           // wall-clock limit for the worker ...
  double timeoutPerMegabyteS = 1.0; // ... plus this much per MB of input file
  std::uint64_t memoryLimitBytes = std::uint64_t{4} << 30;  // worker address-space limit
  const std::atomic<bool>* cancel = nullptr;  // set to true to abandon the import
};

enum class ImportStatus {
  Ok = 0,
  Cancelled,           // the cancel flag was raised
  FileError,           // missing, unreadable or empty file
  MalformedXml,        // not well-formed XML, unsupported encoding, entity bomb
  InvalidDocument,     // not an <svg> root, zero/negative size, nesting too deep
  InvalidNumber,       // NaN or infinite number in the file
  AbsurdCoordinates,   // a point beyond ImportOptions::maxCoordinateMm
  RenderFailed,        // Qt SVG refused the sanitised document
  WorkerCrashed,       // the worker process died (crash, memory limit)
  WorkerTimeout,       // the worker exceeded its time limit
  WorkerNotFound,      // no fivebar-svg-worker executable found
  InvalidOptions,      // tolerance <= 0, dpi <= 0, ...
  TooManyPoints,       // more than ImportOptions::maxPoints points after flattening
};

const char* toString(ImportStatus status);

struct ImportResult {
  ImportStatus status = ImportStatus::Ok;
  Message message;                  // empty when Ok; else names the file and, when known, line/element (translatable)
  Drawing drawing;                  // empty unless Ok
  std::vector<Message> warnings;  // translatable; things dropped or approximated (images, scripts, split paths)
  bool ok() const { return status == ImportStatus::Ok; }
};

// Called with the completed fraction in [0, 1]; may be called from the caller's thread only.
using ProgressFn = std::function<void(double fraction)>;

ImportResult importSvgFile(const QString& path, const ImportOptions& options = {},
                           const ProgressFn& progress = {});

ImportResult importSvgInProcess(const QString& path, const ImportOptions& options = {},
                                const ProgressFn& progress = {});

// Same as importSvgInProcess for an in-memory document; sourceName is used in messages.
ImportResult importSvgData(const QByteArray& data, const QString& sourceName,
                           const ImportOptions& options = {}, const ProgressFn& progress = {});

// The worker executable importSvgFile would use, or empty when none is found. Search order:
// options.workerPath, $FIVEBAR_SVG_WORKER, the running executable's directory, the installed
// location beside it (PREFIX/bin/../libexec/fivebar-studio, as the package installs it), the
// build location.
QString findSvgWorker(const ImportOptions& options = {});

}  // namespace fivebar::svg
