// SPDX-License-Identifier: GPL-3.0-or-later
// The import in two halves, so that the worker can stream what it captures while the caller
// builds the Drawing (worker_client.cpp, worker_main.cpp):
//   capture: file -> page-frame polylines (direct reader or sanitiser + Qt SVG),
//   finish:  layers, extent check, page size, work frame (svg_render.cpp).
// importSvgInProcess is exactly finishImport(captureSvgFile(...)).
#pragma once

#include <QByteArray>
#include <QString>

#include <functional>
#include <string>
#include <vector>

#include "capture_engine.hpp"
#include "svg_import.hpp"
#include "svg_sanitize.hpp"
#include "svg_units.hpp"

namespace fivebar::svg {

struct Capture {
  ImportStatus status = ImportStatus::Ok;
  Message message;                        // when not Ok: names the source, as ImportResult does
  std::vector<CapturedRun> runs;          // page frame; runs handed to a sink are not repeated
  std::vector<TopLevelElement> topLevel;  // for layers
  PageSetup page;                         // finishImport uses sizeKnown, widthMm, heightMm
  std::vector<Message> warnings;
};

// Receives captured runs in order as they are completed. May be empty (everything then stays in
// Capture::runs).
struct RunSink {
  std::function<void(std::vector<CapturedRun>& runs)> take;  // moves the runs out
  std::function<void()> restart;  // forget every run taken: the direct reader declined late
  explicit operator bool() const { return static_cast<bool>(take); }
};

// Progress reaches 0.95 at most; finishImport reports 1.0.
Capture captureSvgFile(const QString& path, const ImportOptions& options,
                       const ProgressFn& progress = {}, const RunSink& sink = {});

// Layers, extent check, page size, work frame; a failed capture becomes the failed result.
ImportResult finishImport(Capture&& capture, const QString& source, const ImportOptions& options,
                          const ProgressFn& progress = {});

// The general path alone (sanitiser + Qt SVG), never the direct reader: the reference the
// direct reader is tested against.
ImportResult importSvgDataGeneral(const QByteArray& data, const QString& sourceName,
                                  const ImportOptions& options = {}, const ProgressFn& progress = {});

}  // namespace fivebar::svg
