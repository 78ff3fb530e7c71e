// SPDX-License-Identifier: GPL-3.0-or-later
// Text layout in Hershey fonts (core/text/text_layout.hpp), the drawing it makes
// (text_drawing.hpp) and the SVG of a drawing (core/output/drawing_svg.hpp). The numbers are
// derived from the test font's own glyphs (hershey_test_font.hpp), not stored.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <regex>

#include "core/output/drawing_svg.hpp"
#include "core/text/text_drawing.hpp"
#include "core/text/text_layout.hpp"
#include "hershey_test_font.hpp"
#include "test_support.hpp"

namespace fivebar::text {
namespace {

constexpr double kTolMm = 1e-9;

HersheyFont testFont() {
  FontLoad load = parseJhf(test::testFontText(), "test", "test.jhf");
  EXPECT_TRUE(load.font) << toString(load.error);
  return *load.font;
}

// The bounding box of one placed glyph's strokes.
void glyphBounds(const TextLayout& layout, const PlacedGlyph& g, Vec2& lo, Vec2& hi) {
  const std::vector<Polyline> mine(layout.strokes.begin() + static_cast<long>(g.firstStroke),
                                   layout.strokes.begin() + static_cast<long>(g.firstStroke + g.strokeCount));
  ASSERT_TRUE(strokeBounds(mine, lo, hi));
}

TEST(TextLayout, AnHIsExactlyTheAskedHeightAndStandsOnTheBaseline) {
  const HersheyFont font = testFont();
  auto rng = test::rng();
  std::uniform_real_distribution<double> height(0.5, 80.0);
  for (int i = 0; i < 20; ++i) {
    TextStyle style;
    style.heightMm = height(rng);
    const TextLayout layout = layoutText(font, "H", style);
    Vec2 lo, hi;
    ASSERT_TRUE(strokeBounds(layout.strokes, lo, hi));
    EXPECT_NEAR(hi.y() - lo.y(), style.heightMm, kTolMm * style.heightMm);
    EXPECT_NEAR(lo.y(), 0.0, kTolMm * style.heightMm);  // the baseline is y = 0
    // The H's strokes start 4 units right of its left bound (-7 - -11), scaled.
    EXPECT_NEAR(lo.x(), 4.0 * style.heightMm / 21.0, kTolMm * style.heightMm);
    EXPECT_EQ(layout.strokes.size(), 3u);  // one polyline per stroke, not an outline
  }
}

TEST(TextLayout, GlyphsAdvanceByTheirHersheyBoundsAndEachStrokeIsDrawnOnce) {
  const HersheyFont font = testFont();
  TextStyle style;
  style.heightMm = 21.0;  // 1 mm per unit
  const std::string text = "HAx H";
  const TextLayout layout = layoutText(font, text, style);
  ASSERT_EQ(layout.glyphs.size(), text.size());
  EXPECT_DOUBLE_EQ(layout.scaleMmPerUnit, 1.0);
  double pen = 0.0, length = 0.0;
  std::size_t strokes = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const HersheyGlyph& g = *font.glyph(static_cast<char32_t>(text[i]));
    EXPECT_NEAR(layout.glyphs[i].penXMm, pen, kTolMm) << i;
    EXPECT_NEAR(layout.glyphs[i].advanceMm, g.advance(), kTolMm) << i;
    EXPECT_EQ(layout.glyphs[i].strokeCount, g.strokes.size());
    EXPECT_EQ(layout.glyphs[i].firstStroke, strokes);
    pen += g.advance();
    strokes += g.strokes.size();
    for (const auto& s : g.strokes)
      for (std::size_t k = 1; k < s.size(); ++k) length += std::hypot(s[k].x - s[k - 1].x, s[k].y - s[k - 1].y);
  }
  EXPECT_EQ(layout.strokes.size(), strokes);
  ASSERT_EQ(layout.lineWidthsMm.size(), 1u);
  EXPECT_NEAR(layout.lineWidthsMm[0], pen, kTolMm);
  EXPECT_NEAR(strokeLengthMm(layout.strokes), length, 1e-9 * length);
  // Twice the height: twice the length, the same shapes.
  style.heightMm = 42.0;
  EXPECT_NEAR(strokeLengthMm(layoutText(font, text, style).strokes), 2.0 * length, 1e-9 * length);
}

TEST(TextLayout, AlignmentPutsEachLinesLeftMiddleOrRightAtZero) {
  const HersheyFont font = testFont();
  const std::string text = "HA\nH\nxxxx";
  for (const Align align : {Align::Left, Align::Center, Align::Right}) {
    TextStyle style;
    style.heightMm = 7.0;
    style.align = align;
    const TextLayout layout = layoutText(font, text, style);
    ASSERT_EQ(layout.lineWidthsMm.size(), 3u);
    for (int line = 0; line < 3; ++line) {
      double first = 1e300, last = -1e300;
      for (const PlacedGlyph& g : layout.glyphs)
        if (g.line == line) {
          first = std::min(first, g.penXMm);
          last = std::max(last, g.penXMm + g.advanceMm);
        }
      const double width = layout.lineWidthsMm[static_cast<std::size_t>(line)];
      EXPECT_NEAR(last - first, width, kTolMm);
      const double expectedFirst = align == Align::Left ? 0.0 : align == Align::Center ? -0.5 * width : -width;
      EXPECT_NEAR(first, expectedFirst, kTolMm) << line;
    }
  }
}

TEST(TextLayout, LinesAreKTimesTheFontsLineHeightApart) {
  const HersheyFont font = testFont();
  for (const double k : {0.8, 1.0, 1.5, 2.25}) {
    TextStyle style;
    style.heightMm = 10.0;
    style.lineSpacing = k;
    const TextLayout layout = layoutText(font, "H\nH\n\nH", style);
    const double advance = k * font.lineHeight * 10.0 / font.capHeight();
    EXPECT_NEAR(layout.lineAdvanceMm, advance, kTolMm);
    ASSERT_EQ(layout.glyphs.size(), 3u);
    EXPECT_EQ(layout.lineWidthsMm.size(), 4u);  // the empty line counts
    const int lines[] = {0, 1, 3};
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(layout.glyphs[i].line, lines[i]);
      Vec2 lo, hi;
      glyphBounds(layout, layout.glyphs[i], lo, hi);
      EXPECT_NEAR(lo.y(), -lines[i] * advance, kTolMm) << i;  // each H stands on its baseline
    }
  }
}

TEST(TextLayout, AMissingGlyphIsNamedAndSkippedWithoutTakingSpace) {
  const HersheyFont font = testFont();
  TextStyle style;
  const TextLayout plain = layoutText(font, "HH\nA", style);
  const TextLayout withMissing = layoutText(font, "H\xC3\xA9H\nA\xE2\x82\xAC", style);  // "HéH\nA€"
  ASSERT_EQ(withMissing.missing.size(), 2u);
  EXPECT_EQ(withMissing.missing[0].codePoint, U'\u00E9');
  EXPECT_EQ(withMissing.missing[0].byteOffset, 1u);
  EXPECT_EQ(withMissing.missing[0].line, 0);
  EXPECT_EQ(withMissing.missing[0].column, 1);
  EXPECT_EQ(describe(withMissing.missing[0]), "'\xC3\xA9' (U+00E9) at line 1, character 2");
  EXPECT_EQ(withMissing.missing[1].codePoint, U'\u20AC');
  EXPECT_EQ(describe(withMissing.missing[1]), "'\xE2\x82\xAC' (U+20AC) at line 2, character 2");
  ASSERT_EQ(withMissing.strokes.size(), plain.strokes.size());
  for (std::size_t i = 0; i < plain.strokes.size(); ++i)
    EXPECT_EQ(withMissing.strokes[i].points, plain.strokes[i].points) << i;

  const TextLayout invalid = layoutText(font, "H\xFFH\xC3", style);  // a bad byte, a cut sequence
  ASSERT_EQ(invalid.missing.size(), 2u);
  EXPECT_TRUE(invalid.missing[0].invalidUtf8);
  EXPECT_EQ(describe(invalid.missing[0]), "invalid UTF-8 at byte 2");
  EXPECT_EQ(describe(invalid.missing[1]), "invalid UTF-8 at byte 4");
  EXPECT_EQ(invalid.glyphs.size(), 2u);
}

TEST(TextLayout, ABadStyleIsNamedAndLaysOutNothing) {
  const HersheyFont font = testFont();
  TextStyle style;
  style.heightMm = -2.0;
  EXPECT_EQ(validate(style), "the height must be a positive number of mm, got -2");
  EXPECT_TRUE(layoutText(font, "H", style).strokes.empty());
  style.heightMm = 5.0;
  style.lineSpacing = 0.0;
  EXPECT_EQ(validate(style), "the line spacing must be a positive factor, got 0");
  style.lineSpacing = std::nan("");
  EXPECT_FALSE(validate(style).empty());
  style.lineSpacing = 1.0;
  EXPECT_EQ(validate(style), "");
}

TEST(TextLayout, OnAStraightPathTheTextIsTheStraightLayoutTurnedAndMoved) {
  const HersheyFont font = testFont();
  TextStyle style;
  style.heightMm = 6.0;
  const TextLayout straight = layoutText(font, "HAH", style);
  // A baseline from (10, 20) straight up (+y): the text is turned 90 deg counter-clockwise.
  const Vec2 start(10.0, 20.0);
  const TextLayout onPath = layoutTextOnPath(font, "HAH", style, {start, start + Vec2(0.0, 30.0), start + Vec2(0.0, 100.0)});
  ASSERT_EQ(onPath.strokes.size(), straight.strokes.size());
  for (std::size_t i = 0; i < straight.strokes.size(); ++i)
    for (std::size_t k = 0; k < straight.strokes[i].points.size(); ++k) {
      const Vec2 p = straight.strokes[i].points[k];
      const Vec2 expected = start + Vec2(-p.y(), p.x());
      EXPECT_NEAR((onPath.strokes[i].points[k] - expected).norm(), 0.0, 1e-9) << i << "," << k;
    }
  // Centred on a 100 mm path: the middle of the text at its middle.
  style.align = Align::Center;
  const TextLayout centred = layoutTextOnPath(font, "HAH", style, {Vec2(0, 0), Vec2(100, 0)});
  Vec2 lo, hi;
  ASSERT_TRUE(strokeBounds(centred.strokes, lo, hi));
  const double w = straight.lineWidthsMm[0];
  EXPECT_NEAR(centred.glyphs.front().penXMm, 50.0 - 0.5 * w, 1e-9);
  EXPECT_NEAR(centred.glyphs.back().penXMm + centred.glyphs.back().advanceMm, 50.0 + 0.5 * w, 1e-9);
  // Each glyph keeps its shape on a bent path: its strokes' length is unchanged.
  const TextLayout bent = layoutTextOnPath(font, "HAHAH", style, {Vec2(0, 0), Vec2(20, 0), Vec2(40, 20)});
  EXPECT_NEAR(strokeLengthMm(bent.strokes), strokeLengthMm(layoutText(font, "HAHAH", style).strokes), 1e-9);
  EXPECT_TRUE(layoutTextOnPath(font, "H", style, {Vec2(1, 1), Vec2(1, 1)}).strokes.empty());  // no direction
}

TEST(TextDrawing, TheDrawingHoldsTheStrokesInsideItsMarginsAndTheSvgIsInMm) {
  const HersheyFont font = testFont();
  TextStyle style;
  style.heightMm = 12.0;
  style.align = Align::Right;
  const TextLayout layout = layoutText(font, "HA\nAH", style);
  TextDrawingOptions options;
  options.marginMm = 2.5;
  options.rgb = 0x123abc;
  const Drawing drawing = drawingFromText(layout, options);
  ASSERT_EQ(drawing.layers.size(), 1u);
  const Layer& layer = drawing.layers[0];
  ASSERT_EQ(layer.paths.size(), layout.strokes.size());
  Vec2 lo, hi, textLo, textHi;
  ASSERT_TRUE(strokeBounds(layer.paths, lo, hi));
  ASSERT_TRUE(strokeBounds(layout.strokes, textLo, textHi));
  EXPECT_NEAR(lo.x(), 2.5, kTolMm);
  EXPECT_NEAR(lo.y(), 2.5, kTolMm);
  EXPECT_NEAR(drawing.widthMm, textHi.x() - textLo.x() + 5.0, kTolMm);
  EXPECT_NEAR(drawing.heightMm, textHi.y() - textLo.y() + 5.0, kTolMm);
  EXPECT_NEAR(strokeLengthMm(layer.paths), strokeLengthMm(layout.strokes), 1e-9);
  EXPECT_EQ(drawing.flatteningToleranceMm, 0.0);

  const std::string svg = svgFromDrawing(drawing);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("width=\"([0-9.]+)mm\" height=\"([0-9.]+)mm\" viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"")));
  EXPECT_EQ(m[1], m[3]);
  EXPECT_EQ(m[2], m[4]);
  EXPECT_NEAR(std::stod(m[1]), drawing.widthMm, 1e-4);
  EXPECT_NE(svg.find("stroke=\"#123abc\""), std::string::npos);
  EXPECT_NE(svg.find("fill=\"none\""), std::string::npos);
  std::size_t paths = 0;
  for (std::size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) ++paths;
  EXPECT_EQ(paths, layer.paths.size());
  // y flipped: the first point of the first stroke.
  const Vec2 p = layer.paths[0].points[0];
  char first[64];
  std::snprintf(first, sizeof first, "M%.4f %.4f", p.x(), drawing.heightMm - p.y());
  EXPECT_NE(svg.find(first), std::string::npos) << first;
}

// The Debian futural: "HELLO" at 10 mm.
TEST(TextLayout, FuturalHelloHasAnHOfTheAskedHeight) {
  const FontLoad load = loadFont("futural", kDefaultFontDirectory);
  if (!load.font) GTEST_SKIP() << kDefaultFontDirectory << "/futural.jhf absent (install hershey-fonts-data)";
  TextStyle style;
  style.heightMm = 10.0;
  const TextLayout layout = layoutText(*load.font, "HELLO", style);
  EXPECT_TRUE(layout.missing.empty());
  ASSERT_EQ(layout.glyphs.size(), 5u);
  Vec2 lo, hi;
  glyphBounds(layout, layout.glyphs[0], lo, hi);
  EXPECT_NEAR(hi.y() - lo.y(), 10.0, 1e-9);
  EXPECT_NEAR(layout.lineWidthsMm[0], (22 + 19 + 17 + 17 + 22) * 10.0 / 21.0, 1e-9);
}

}  // namespace
}  // namespace fivebar::text
