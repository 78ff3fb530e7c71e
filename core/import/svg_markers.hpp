// SPDX-License-Identifier: GPL-3.0-or-later
// Markers (marker-start/mid/end) drawn as SVG 1.1 specifies (painting.html#Markers): the
// sanitiser writes each <marker> as a <g> inside <defs> and appends, after a path, line, polyline
// or polygon that references markers, a <g transform="the element's transform"> holding one
// <use transform="..."> of the marker content per vertex (svg_sanitize_rewrite.cpp). This file
// holds the geometry: the vertices with their orientation, and each instance's transform.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QStringView>
#include <QXmlStreamAttributes>

#include <map>
#include <optional>
#include <vector>

#include "svg_lengths.hpp"

namespace fivebar::svg {

struct MarkerInfo {
  QString viewBox, preserveAspectRatio, markerWidth, markerHeight, refX, refY, orient, markerUnits;
  bool clips = false;  // overflow hidden/scroll given explicitly (clipping is not applied)
};

// id -> the marker's attributes; one quick pass, only when the text holds "marker".
std::map<QString, MarkerInfo> scanMarkers(const QByteArray& document);

// A vertex of a marked shape, in the shape's user space. angleRad: the direction for
// orient="auto" (the bisector at inner vertices), radians, counter-clockwise in SVG's y-down frame
// (i.e. atan2(dy, dx)).
struct MarkerVertex {
  double x = 0.0, y = 0.0, angleRad = 0.0;
};

// The vertices of a path, line, polyline or polygon (empty for other tags or bad geometry): the
// path's moveto points and segment end points (closepath included), in order.
std::vector<MarkerVertex> markerVertices(QStringView tag, const QXmlStreamAttributes& attributes);

// The marker references of one element, "url(#id)" reduced to id; "none" -> empty.
struct MarkerRefs {
  QString start, mid, end;
  bool any() const { return !start.isEmpty() || !mid.isEmpty() || !end.isEmpty(); }
};

// Marker properties (marker, marker-start/mid/end) set by document style sheets (<style>): the
// rules whose selectors are simple (a type or *, #id, .class, or a compound of them such as
// path.arrow#a; comma lists), in document order. Rules with other selectors (descendant, child,
// attribute, pseudo-class) are listed in `unsupported` (the sanitiser warns about each).
struct MarkerRule {
  QString tag;          // empty or "*": any element
  QString id;           // empty: any
  QStringList classes;  // all must be present
  int specificity = 0;  // CSS: 100 per id, 10 per class, 1 for a type
  std::vector<std::pair<QString, QString>> declarations;  // property, value
};
struct MarkerSheet {
  std::vector<MarkerRule> rules;
  std::vector<QString> unsupported;  // selectors of rules with marker properties not applied
  bool empty() const { return rules.empty(); }
};

// The marker rules of every <style> element of the document (one quick pass, only when the text
// holds "marker").
MarkerSheet scanMarkerSheet(const QByteArray& document);
// The same for the text of one style sheet (exposed for tests).
MarkerSheet parseMarkerSheet(QStringView css);

// Applies the element's marker-start/mid/end over the inherited references, in CSS order:
// presentation attributes, then the style-sheet rules that match the element (by specificity,
// then document order), then marker/marker-* in its style attribute.
MarkerRefs markerRefs(const QXmlStreamAttributes& attributes, const MarkerRefs& inherited,
                      QStringView tag = {}, const MarkerSheet* sheet = nullptr);

// The element's stroke-width in user units (attribute or style), else the inherited one.
double strokeWidthUser(const QXmlStreamAttributes& attributes, double inherited);

enum class MarkerSlot { Start, Mid, End };

// The transform of one marker instance: translate(vertex) rotate(orient) scale(stroke width if
// markerUnits="strokeWidth") scale(viewBox -> markerWidth x markerHeight) translate(-refX, -refY).
// Lengths (markerWidth/Height, refX/refY) in units, em or % resolve in `lengths`.
// nullopt when the marker is not drawn (markerWidth/markerHeight <= 0, empty viewBox).
std::optional<QString> markerInstanceTransform(const MarkerInfo& marker, const MarkerVertex& vertex,
                                               MarkerSlot slot, double strokeWidth,
                                               const LengthContext& lengths = {});

}  // namespace fivebar::svg
