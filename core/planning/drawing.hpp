// SPDX-License-Identifier: GPL-3.0-or-later
// The drawing model shared by import, planning and the studio: layers of polylines in the work
// frame (millimetres, y up). Import produces it; placement maps it into the machine frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar {

// How the area a polyline bounds is filled in the source drawing (core/planning/hatch.hpp).
enum class FillRule : std::uint8_t { None = 0, NonZero, EvenOdd };

struct Polyline {
  std::vector<Vec2> points;  // mm; consecutive points are joined by straight segments
  bool closed = false;       // true when the last point joins back to the first
  // Fill: a filled shape is one polyline with fillStart set followed by its other rings (holes,
  // further subpaths), all with the shape's fill rule; each ring is taken as closed.
  FillRule fill = FillRule::None;
  bool fillStart = false;  // first ring of a filled shape
  bool fillOnly = false;   // the outline of a shape that is filled but not stroked
  // True when the points approximate curves (Bezier, arc, ellipse, glyph outline): they lie
  // within Drawing::flatteningToleranceMm of the true geometry. False when the polyline IS the
  // geometry (straight segments only): the planner spends no tolerance on flattening it.
  bool flattened = false;
};

// How a layer's filled shapes are drawn (core/planning/hatch.hpp): outline (the shape's geometry,
// as AxiDraw and vpype draw it), hatch (parallel lines clipped by the shape), or none.
enum class FillMode { Outline, Hatch, None };

struct HatchSettings {
  double spacingMm = 1.0;   // distance between neighbouring hatch lines
  double angleRad = 0.0;    // direction of the lines, counter-clockwise from +x (work frame)
  bool crosshatch = false;  // a second set at angle + 90 deg
  bool outline = true;      // keep the outline of fill-only shapes when hatching
  bool operator==(const HatchSettings&) const = default;
};

// Tool settings a layer may override; unset values fall back to the machine profile.
struct LayerToolSettings {
  double drawSpeedMmPerS = 0.0;  // 0 = profile default
  double power = -1.0;           // laser S value or pen-down servo S; < 0 = profile default
  bool pauseBefore = false;      // pen change: pause the job before this layer
};

struct Layer {
  std::string id;           // stable identifier (SVG id, Inkscape layer id, or "color:#rrggbb")
  std::string name;         // what the user sees
  std::uint32_t rgb = 0;    // stroke colour 0xRRGGBB
  bool visible = true;      // hidden layers are neither drawn nor planned
  LayerToolSettings tool;
  // The fill its filled shapes are drawn with; applied where the drawing is placed (placeDrawing,
  // core/planning/placement.hpp), so `paths` keep the imported geometry and the fill can change.
  FillMode fill = FillMode::Outline;
  HatchSettings hatch;
  std::vector<Polyline> paths;
};

// The default budget of points a drawing may have after flattening and hatching: a guard against
// runaway files (an entity expansion, a hatch at a tiny spacing), raised on request.
inline constexpr std::size_t kDefaultMaxPoints = 2'000'000;

struct Drawing {
  std::string source;      // file name it came from, for messages
  double widthMm = 0.0;    // physical page size
  double heightMm = 0.0;
  // Largest distance (work-frame mm) between the polylines and the curves they were flattened
  // from: the tolerance the import was asked for; 0 when the polylines are the geometry. It
  // applies to the polylines marked `flattened` only; the planner scales it by the placement and
  // spends the rest of the tolerance on the moves, stroke by stroke.
  double flatteningToleranceMm = 0.0;
  std::vector<Layer> layers;  // in plotting order
};

}  // namespace fivebar
