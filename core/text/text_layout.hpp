// SPDX-License-Identifier: GPL-3.0-or-later
// Lays out UTF-8 text in a Hershey font (hershey_font.hpp) as single-stroke polylines in
// millimetres, work frame (x right, y UP). Each stroke of each glyph becomes one polyline, drawn
// once (a stroke, not an outline). docs/text.md.
//
// Geometry:
//  - scale = heightMm / the font's cap height (the 'H' measured from the glyph data), so an 'H'
//    is exactly heightMm tall;
//  - glyphs follow each other by their Hershey advance (right - left bound: Hershey's own
//    spacing), the pen x starting at the left bound of the first glyph;
//  - the origin (0, 0) is on the first line's baseline (the bottom of the 'H'): at its left end
//    (Align::Left), its middle (Center) or its right end (Right); every line is aligned the same
//    way about x = 0;
//  - '\n' starts a new line; line n's baseline is at y = -n * lineSpacing * lineHeightMm, where
//    lineHeightMm is the font's line height (the full vertical extent of its glyphs) at this
//    scale: lineSpacing 1 keeps the glyphs of neighbouring lines from ever overlapping.
// Characters the font lacks are skipped (they take no space) and listed in `missing`, so the
// caller can name them; "\r" is ignored, a tab is one space.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/planning/drawing.hpp"
#include "core/text/hershey_font.hpp"

namespace fivebar::text {

enum class Align { Left, Center, Right };

struct TextStyle {
  double heightMm = 10.0;    // cap height: the height of an 'H'
  double lineSpacing = 1.0;  // baseline to baseline = lineSpacing x the font's line height
  Align align = Align::Left;
};

// Empty when the style is usable, else what is wrong ("the height must be a positive number of
// mm, got -1").
std::string validate(const TextStyle& style);

// A character of the text the font has no glyph for, or a byte that is not UTF-8.
struct MissingGlyph {
  char32_t codePoint = 0;  // U+FFFD for invalid UTF-8
  std::size_t byteOffset = 0;  // into the text
  int line = 0;    // 0-based line of the text
  int column = 0;  // 0-based character (code point) within its line
  bool invalidUtf8 = false;
};

// "'é' (U+00E9) at line 1, character 4" or "invalid UTF-8 at byte 4": for messages (numbers
// from 1 there).
std::string describe(const MissingGlyph& missing);

// One glyph placed: where it is and which strokes are its.
struct PlacedGlyph {
  char32_t codePoint = 0;
  std::size_t byteOffset = 0;  // into the text
  int line = 0;                // 0-based
  double penXMm = 0.0;         // x of its left bound on the baseline
  double advanceMm = 0.0;      // right - left bound, scaled
  std::size_t firstStroke = 0;  // its strokes are strokes[firstStroke, firstStroke + strokeCount)
  std::size_t strokeCount = 0;
};

struct TextLayout {
  std::vector<Polyline> strokes;  // mm, work frame; open, `flattened` false (they ARE the geometry)
  std::vector<PlacedGlyph> glyphs;   // in text order (spaces included; '\n' not)
  std::vector<MissingGlyph> missing;  // skipped characters, in text order
  std::vector<double> lineWidthsMm;   // advance width of each line (one entry per line)
  double scaleMmPerUnit = 0.0;  // mm per Hershey unit
  double capHeightMm = 0.0;     // = style.heightMm
  double lineAdvanceMm = 0.0;   // baseline to baseline
};

// Lays out `utf8` (the style must pass validate(); an invalid one gives an empty layout).
TextLayout layoutText(const HersheyFont& font, std::string_view utf8, const TextStyle& style);

// Lays out one line of text along a polyline baseline (mm, work frame, at least two distinct
// points): each glyph keeps its shape and is turned to the baseline's direction at its middle;
// the text starts at the path's start (Left), is centred on its length (Center) or ends at its
// end (Right); past either end the path goes on straight. '\n' counts as a space here. The
// glyphs stand on the left of the direction of travel (above a baseline drawn left to right).
TextLayout layoutTextOnPath(const HersheyFont& font, std::string_view utf8, const TextStyle& style,
                            const std::vector<Vec2>& baselineMm);

// The sum of the strokes' lengths (mm): what a plotter draws pen down.
double strokeLengthMm(const std::vector<Polyline>& strokes);

// The smallest box holding every stroke point; false when there is none.
bool strokeBounds(const std::vector<Polyline>& strokes, Vec2& minMm, Vec2& maxMm);

}  // namespace fivebar::text
