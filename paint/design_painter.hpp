// SPDX-License-Identifier: GPL-3.0-or-later
// Painting of a design (core/design): its workspace, singularity curves and placed rectangle
// over one of the measure maps (conditioning, transmission, resolution), into any QPainter.
// The studio's Design dialog preview, the canvas overlay and `fivebar design --png` share it.
// The maps are computed once per design (computeDesignMaps), never while painting.
#pragma once

#include <QImage>
#include <QPainter>
#include <QString>

#include "core/design/search.hpp"
#include "core/workspace/workspace.hpp"
#include "paint/map_painter.hpp"

namespace fivebar::paint {

struct DesignMaps {
  WorkspaceMap map;            // the design's working mode, its brief's margins
  WorkspaceAnalysis analysis;  // boundaries and type II curves of that map
};

// Maps of the design's mode over its whole workspace, `cellsOnLongSide` cells across.
DesignMaps computeDesignMaps(const design::Design& d, const design::DesignRules& rules,
                             int cellsOnLongSide = 320, int threads = 2);

// The machine-frame box (mm) that shows the reachable region, the motors, the pose and the
// rectangle.
QRectF designBoxMm(const design::Design& d, const DesignMaps& maps);

// The overlay: the map `kind` (None: the singularity-free region tinted), reach and
// singularity-free boundaries, type II curves, the placed rectangle and the machine with its
// pen at the rectangle's centre.
void paintDesignOverlay(QPainter& painter, const QTransform& widgetFromMachine,
                        const design::Design& d, const DesignMaps& maps, MapKind kind);

// One panel of the atlas inside `panelPx`: grid, overlay, title and colour bar.
void paintDesignPanel(QPainter& painter, const QRectF& panelPx, const design::Design& d,
                      const DesignMaps& maps, MapKind kind);

// A header with the lengths and measures, then four panels: the workspace, conditioning,
// transmission angle and resolution.
QImage designAtlas(const design::Design& d, const DesignMaps& maps, const QString& title,
                   QSize sizePx = QSize(1800, 1350));

// Text lines describing the design's measures (translated).
QStringList designMeasureLines(const design::Design& d);

}  // namespace fivebar::paint
