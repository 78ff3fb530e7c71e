// Lengths, viewBox and preserveAspectRatio of an SVG root element, and the page set-up derived
// from them: how big the page is in mm and where the viewBox lands on it (page frame: mm, y down,
// origin top-left; the flip to the y-up work frame happens later, in svg_render.cpp).
#pragma once

#include <QRectF>
#include <QString>
#include <QStringView>

#include <optional>
#include <string>

#include "core/support/message.hpp"

namespace fivebar::svg {

enum class LengthUnit { None, Px, Mm, Cm, In, Pt, Pc, Em, Ex, Percent };

struct Length {
  double value = 0.0;
  LengthUnit unit = LengthUnit::None;
};

// "12.5mm", "3in", "100", "50%"; nullopt when the text is not a length.
std::optional<Length> parseLength(QStringView text);

// Millimetres for an absolute or unitless length ("px" and no unit are 1/dpi inch, em = 16 px,
// ex = 8 px); nullopt for percentages.
std::optional<double> lengthToMm(const Length& length, double dpi);

// "minx miny width height" (spaces and/or commas); nullopt unless 4 finite numbers.
std::optional<QRectF> parseViewBox(QStringView text);

inline constexpr double kMaxViewBoxNumber = 1e12;  // user units; beyond: refused as too large

// What is wrong with a root viewBox text ("not four numbers (3 values)", "a number too large
// (9e80; at most 1e12)", ...); empty when it is usable.
std::string viewBoxProblem(QStringView text);

enum class Align { None, Min, Mid, Max };

struct AspectRatio {
  Align alignX = Align::Mid;  // Align::None in both = preserveAspectRatio="none"
  Align alignY = Align::Mid;
  bool slice = false;         // false = "meet"
};

AspectRatio parsePreserveAspectRatio(QStringView text);

// The attributes of the root <svg>, as written in the file.
struct RootAttributes {
  QString width;
  QString height;
  QString viewBox;
  QString preserveAspectRatio;
  bool hasWidth = false;
  bool hasHeight = false;
  bool hasViewBox = false;
  qint64 line = 0;
};

struct PageSetup {
  bool sizeKnown = false;  // false: no size and no viewBox; the page is the drawing's extent
  double widthMm = 0.0;
  double heightMm = 0.0;
  QRectF viewBoxUser;      // user-space rectangle handed to QSvgRenderer::setViewBox
  QRectF targetMm;         // where viewBoxUser lands on the page (mm, y down)
};

// Derives the page from the root attributes; returns an error text (empty when fine) for
// zero/negative sizes or an unusable viewBox.
Message computePage(const RootAttributes& root, double dpi, PageSetup& page);

// Where a viewBox of size (vbWidth x vbHeight) lands inside a viewport, per preserveAspectRatio.
QRectF placeViewBox(const QRectF& viewBox, const QRectF& viewport, const AspectRatio& ratio);

// Attributes of a nested <svg> element that define its viewport.
struct NestedViewport {
  QString x, y, width, height, viewBox, preserveAspectRatio;
};

// The SVG transform text that maps a nested <svg>'s content into its parent's user space
// (lengths: unitless/px = user units, absolute units at dpi, % of the root viewBox (when known)).
// Clipping to the nested viewport is not modelled.
QString nestedViewportTransform(const NestedViewport& nested, const RootAttributes& root, double dpi);

}  // namespace fivebar::svg
