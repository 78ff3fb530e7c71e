// SPDX-License-Identifier: GPL-3.0-or-later
// One length resolver for every SVG attribute that takes a length (shapes, use, nested svg,
// symbol/marker viewports, text): CSS units at `dpi` user units per inch (96: 1in = 96, 1cm =
// 96/2.54, 1mm = 96/25.4, 1Q = 96/101.6, 1pt = 4/3, 1pc = 16, px and no unit = 1), em and ex from
// the element's font size (1ex = 0.5em, as resvg and browsers without font metrics use), and
// percentages against the axis the attribute belongs to (SVG 2, "Units": width for x-like
// lengths, height for y-like ones, the normalised diagonal sqrt((w^2 + h^2) / 2) for the rest).
// The result is in the element's user units, so the sanitiser can hand Qt SVG plain numbers
// (Qt 6.4 reads absolute units at 90 dpi, ignores pc and em/ex, and takes every % of the height).
#pragma once

#include <QString>
#include <QStringView>

#include <optional>

#include "svg_rewrite.hpp"

namespace fivebar::svg {

enum class LengthAxis { Width, Height, Diagonal };

struct LengthContext {
  UserViewport viewport;        // for %: user units; 0 = unknown (then % is not resolved)
  double fontSizeUser = 16.0;   // the element's font size, user units (em, ex)
  double dpi = 96.0;            // user units per inch
};

// The length in user units; nullopt when the text is not a length, or a percentage whose
// reference is unknown.
std::optional<double> resolveLength(QStringView text, LengthAxis axis, const LengthContext& context);

// The axis of a length attribute of `tag` (x, cx, x1, x2, dx, width, rx, refX, markerWidth:
// Width; the y-like ones: Height; r and anything else: Diagonal); nullopt when the attribute does
// not take a single length on that element.
std::optional<LengthAxis> lengthAttributeAxis(QStringView tag, QStringView attribute);

// True when the value carries a unit or % (its last non-space character is not a digit or '.'):
// a plain number needs no rewriting.
bool hasLengthUnit(QStringView value);

// The value of a property in a style attribute ("a: b; c: d"), empty when absent.
QString styleValue(QStringView style, QStringView property);

}  // namespace fivebar::svg
