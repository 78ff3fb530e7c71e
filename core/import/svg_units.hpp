// SPDX-License-Identifier: GPL-3.0-or-later
// Lengths, viewBox and preserveAspectRatio of an SVG root element, and the page set-up derived
// from them: how big the page is in mm and where the viewBox lands on it (page frame: mm, y down,
// origin top-left; the flip to the y-up work frame happens later, in svg_render.cpp).
#pragma once

#include <QRectF>
#include <QSizeF>
#include <QTransform>
#include <QString>
#include <QStringList>
#include <QStringView>

#include <optional>
#include <string>

#include "core/support/message.hpp"

namespace fivebar::svg {

enum class LengthUnit { None, Px, Mm, Cm, Q, In, Pt, Pc, Em, Ex, Percent };

struct Length {
  double value = 0.0;
  LengthUnit unit = LengthUnit::None;
};

// "12.5mm", "3in", "100", "50%"; nullopt when the text is not a length.
std::optional<Length> parseLength(QStringView text);

// Millimetres for an absolute or unitless length ("px" and no unit are 1/dpi inch, Q = 1/4 mm,
// em = 16 px, ex = 8 px: the initial font size); nullopt for percentages. Lengths inside the
// document go through resolveLength (svg_lengths.hpp), which knows the element's font size.
std::optional<double> lengthToMm(const Length& length, double dpi);

// A list of numbers in the SVG number grammar (SVG 2 "number", separated by whitespace and at
// most one comma): "9E80.7" is the two numbers 9E80 and .7, "1-2" is 1 and -2. badAt: offset of
// the first text that is no number (-1 when the whole text is numbers).
struct NumberList {
  QStringList tokens;
  qsizetype badAt = -1;
};
NumberList scanNumberList(QStringView text);

// "minx miny width height" (SVG number grammar); nullopt unless 4 finite numbers.
std::optional<QRectF> parseViewBox(QStringView text);

inline constexpr double kMaxViewBoxNumber = 1e12;  // user units; beyond: refused as too large

// What is wrong with a root viewBox text ("not four numbers (3 numbers)", "a number too large
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
// (lengths: unitless/px = user units, absolute units at dpi, % of the parent's viewport, whose
// size in user units is parentWidth x parentHeight; 0 = unknown). Clipping to the nested
// viewport is not modelled. `viewport` receives the size of the new viewport in its own user
// units (the viewBox's size, else the viewport's).
QString nestedViewportTransform(const NestedViewport& nested, double parentWidth, double parentHeight,
                                double dpi, QSizeF* viewport = nullptr);

// The same mapping as a matrix (parent user space from the nested <svg>'s content).
QTransform nestedViewportMatrix(const NestedViewport& nested, double parentWidth, double parentHeight,
                                double dpi);

}  // namespace fivebar::svg
