// SPDX-License-Identifier: GPL-3.0-or-later
// The direct reader: a single pass over the bytes of a "plain" SVG, the subset that plotter
// generators write, producing the same captured runs as the general path (sanitiser, Qt SVG,
// capture engine) without building an XML rewrite or a Qt SVG document (docs/svg-import.md,
// "Direct reader").
//
// The subset (anything else, anywhere in the file, makes the reader decline):
//  - ASCII text without '&', an optional <?xml version="1.0" ...?> declaration, comments,
//    whitespace between elements; no DOCTYPE, no processing instructions, no CDATA;
//  - elements svg (root, default namespace SVG), g, path, polyline, polygon, line; no xmlns
//    below the root; attributes: id, fill, stroke, stroke-width, and the geometry of each
//    element (d; points; x1 y1 x2 y2), root width/height/viewBox/preserveAspectRatio/version, and
//    attributes in namespaces declared on the root (inkscape:label and inkscape:groupmode are
//    used for layers, others are ignored as Qt SVG ignores them);
//  - colours: none, #rgb, #rrggbb, lower-case SVG colour names (not transparent/currentColor);
//    stroke-width: a plain positive number; path data: M L H V C S Q T Z (either case) with
//    well-formed numbers (no arcs); polyline/polygon points: an even count of numbers.
// Declining is always safe: the caller then runs the general path, which is the reference.
// Scope and how the equivalence is tested: docs/svg-import.md.
#pragma once

#include <QByteArray>

#include <vector>

#include "import_pipeline.hpp"

namespace fivebar::svg {

enum class DirectStatus {
  Captured,   // the document is in the subset; `out` holds what the general path would capture
  Declined,   // outside the subset (or invalid): use the general path
  Cancelled,  // options.cancel was raised
  TooManyPoints,  // more than options.maxPoints points (reading stopped there)
};

struct DirectCapture {
  RootAttributes root;
  PageSetup page;
  std::vector<TopLevelElement> topLevel;
  std::vector<CapturedRun> runs;  // page frame: mm, y down
};

// progress(fraction of the bytes read, in [0, 1]) may be empty. `sink`, when given, receives
// completed runs every few hundred kB of points (the rest stays in out.runs). Needs a
// QGuiApplication only for the one-off Qt SVG probe of the root's viewport transform.
DirectStatus captureDirect(const QByteArray& data, const ImportOptions& options,
                           const ProgressFn& progress, DirectCapture& out, const RunSink& sink = {});

}  // namespace fivebar::svg
