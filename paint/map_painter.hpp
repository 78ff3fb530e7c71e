// SPDX-License-Identifier: GPL-3.0-or-later
// Scalar workspace maps as canvas overlays: transmission angle, conditioning and mm-per-step
// resolution of one working mode, each as a colour image over the reachable cells with a
// colour-bar legend giving the values. Painting functions take a QPainter&.
#pragma once

#include <QImage>
#include <QPainter>
#include <QString>

#include "core/workspace/workspace.hpp"

namespace fivebar::paint {

enum class MapKind { None, Transmission, Conditioning, Resolution };

// Value range and presentation of one map.
struct MapScale {
  double low = 0.0;   // value at the left end of the colour bar (display units)
  double high = 1.0;  // value at the right end
  bool diverging = false;  // red at both ends, green in the middle (transmission angle)
  bool reversed = false;   // high values are bad (resolution): ramp runs good -> bad
  QString title;           // "Transmission angle (deg)"
  int decimals = 0;
};

// Display value of cell i (degrees, ratio, micrometres), NaN when unreachable.
double mapValue(const WorkspaceMap& map, MapKind kind, std::size_t i);
MapScale mapScale(const WorkspaceMap& map, MapKind kind);
// Colour of a display value on the scale (alpha applied by the caller).
QColor mapColour(const MapScale& scale, double value);

// One pixel per cell, rows top = largest y; transparent where unreachable.
QImage mapImage(const WorkspaceMap& map, MapKind kind, const MapScale& scale, int alpha = 150);
// Draws an image from mapImage() over the map's grid.
void paintMapImage(QPainter& painter, const QTransform& widgetFromMachine,
                   const WorkspaceMap& map, const QImage& image);
// A colour bar with its title and tick values inside `rectPx` (a white card).
void paintColourBar(QPainter& painter, const QRectF& rectPx, const MapScale& scale);

}  // namespace fivebar::paint
