// SPDX-License-Identifier: GPL-3.0-or-later
// Painting of a workspace analysis (core/workspace.hpp) for one working mode, into any QPainter:
// the studio's overlay, the CLI's `workspace --png` image and tests share these functions.
// They draw what core computed; nothing here evaluates kinematics.
#pragma once

#include <QPainter>
#include <QPointF>
#include <QTransform>

#include "core/workspace/workspace.hpp"

namespace fivebar::paint {

struct WorkspacePaintOptions {
  bool fillRegions = true;     // singularity-free region and the margin band, as tinted areas
  bool drawBoundaries = true;  // reach boundary (solid) and singularity-free boundary (dashed)
  bool drawTypeII = true;      // type II singularity curves
  bool drawRectangle = true;   // largest singularity-free rectangle with its size
  double opacity = 1.0;        // in [0, 1], multiplies everything
};

// The overlay of `analysis` (made from `map`) in machine coordinates mapped by
// widgetFromMachine (mm, y up -> px, y down).
void paintWorkspace(QPainter& painter, const QTransform& widgetFromMachine,
                    const WorkspaceMap& map, const WorkspaceAnalysis& analysis,
                    const WorkspacePaintOptions& options = {});

// A legend box (top-left corner at topLeftPx) naming each element and the margins; returns its
// height in px.
double paintWorkspaceLegend(QPainter& painter, QPointF topLeftPx, const WorkspaceMap& map,
                            const WorkspaceAnalysis& analysis);

// A scale bar of a round length (1, 2 or 5 x 10^k mm) about `targetPx` long, its left end at
// leftPx (the baseline).
void paintScaleBar(QPainter& painter, const QTransform& widgetFromMachine, QPointF leftPx,
                   double targetPx = 120.0);

}  // namespace fivebar::paint
