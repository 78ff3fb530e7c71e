// SPDX-License-Identifier: GPL-3.0-or-later
// SVG <text> redrawn in a Hershey single-stroke font (ImportOptions::textFont,
// core/import/svg_text_redraw.hpp): size, position, anchor, tspans, inheritance, transform and
// colour, against the font's own layout; the rest of the document untouched, line numbers kept.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QString>

#include <filesystem>
#include <fstream>

#include "../core/hershey_test_font.hpp"
#include "core/import/svg_text_redraw.hpp"
#include "core/text/text_layout.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

namespace fs = std::filesystem;

// The test font (its H: cap height 21 units, advance 22) as a .jhf file, named by its path.
class TextRedraw : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-redraw-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
    fontPath_ = (dir_ / "testfont.jhf").string();
    std::ofstream(fontPath_) << test::testFontText();
    font_ = *text::loadFont(fontPath_).font;
  }
  void TearDown() override { fs::remove_all(dir_); }
  ImportResult import(const std::string& body) {
    ImportOptions o;
    o.textFont = fontPath_;
    return test::importText(test::page(body, 100, 60), o);
  }
  // The layout length of `s` at cap height 0.7 x fontSize.
  double layoutLength(const std::string& s, double fontSize) const {
    text::TextStyle style;
    style.heightMm = kTextCapHeightPerEm * fontSize;
    return text::strokeLengthMm(text::layoutText(font_, s, style).strokes);
  }
  double layoutWidth(const std::string& s, double fontSize) const {
    text::TextStyle style;
    style.heightMm = kTextCapHeightPerEm * fontSize;
    return text::layoutText(font_, s, style).lineWidthsMm.front();
  }
  fs::path dir_;
  std::string fontPath_;
  text::HersheyFont font_;
};

std::vector<Polyline> allPaths(const Drawing& d) {
  std::vector<Polyline> out;
  for (const Layer& l : d.layers) out.insert(out.end(), l.paths.begin(), l.paths.end());
  return out;
}

TEST_F(TextRedraw, AnHIsDrawnAsItsThreeStrokesAtSevenTenthsOfTheFontSize) {
  const ImportResult r = import("<text x=\"10\" y=\"30\" font-size=\"10\">H</text>");
  ASSERT_TRUE(r.ok()) << r.message.text();
  const std::vector<Polyline> paths = allPaths(r.drawing);
  EXPECT_EQ(paths.size(), 3u);
  Vec2 lo, hi;
  ASSERT_TRUE(text::strokeBounds(paths, lo, hi));
  EXPECT_NEAR(hi.y() - lo.y(), 7.0, 1e-3);
  EXPECT_NEAR(lo.y(), 60.0 - 30.0, 1e-3);                 // on the baseline y = 30 (work frame: 60 - 30)
  EXPECT_NEAR(lo.x(), 10.0 + 4.0 * 7.0 / 21.0, 1e-3);     // the H's stem 4 units right of its bound
  EXPECT_NEAR(text::strokeLengthMm(paths), layoutLength("H", 10.0), 1e-3);
  // Without the option the outlines are drawn (closed rings, not three strokes).
  const ImportResult outlines = test::importText(test::page("<text x=\"10\" y=\"30\" font-size=\"10\">H</text>", 100, 60));
  ASSERT_TRUE(outlines.ok());
  const auto rings = allPaths(outlines.drawing);
  ASSERT_FALSE(rings.empty());
  EXPECT_TRUE(rings.front().closed);
}

TEST_F(TextRedraw, AnchorsTspansInheritanceAndWhiteSpaceFollowTheSvg) {
  for (const char* anchor : {"start", "middle", "end"}) {
    const ImportResult r = import(std::string("<g font-size=\"20\"><text x=\"50\" y=\"40\" text-anchor=\"") + anchor +
                                  "\">\n   HA  H\n</text></g>");
    ASSERT_TRUE(r.ok()) << r.message.text();
    Vec2 lo, hi;
    ASSERT_TRUE(text::strokeBounds(allPaths(r.drawing), lo, hi));
    const double w = layoutWidth("HA H", 20.0);  // white space collapsed, ends trimmed
    const double start = std::string(anchor) == "start" ? 50.0 : std::string(anchor) == "middle" ? 50.0 - 0.5 * w : 50.0 - w;
    // The first glyph is an H: its stem is 4 units (of 14 / 21 mm at cap 14) right of the start.
    EXPECT_NEAR(lo.x(), start + 4.0 * 14.0 / 21.0, 1e-3) << anchor;
    EXPECT_NEAR(text::strokeLengthMm(allPaths(r.drawing)), layoutLength("HA H", 20.0), 1e-3) << anchor;
  }
  // A tspan continues the line in its own size and colour; a tspan with x starts a new chunk.
  const ImportResult r = import("<text x=\"10\" y=\"20\" font-size=\"10\" fill=\"#0000ff\">H<tspan font-size=\"5\" "
                                "fill=\"#ff0000\">A</tspan>H<tspan x=\"60\" y=\"50\">A</tspan></text>");
  ASSERT_TRUE(r.ok()) << r.message.text();
  double blue = 0.0, red = 0.0;
  for (const Layer& l : r.drawing.layers)
    (l.rgb == 0xff0000 ? red : blue) += text::strokeLengthMm(l.paths);
  EXPECT_NEAR(red, layoutLength("A", 5.0), 1e-3);
  EXPECT_NEAR(blue, 2.0 * layoutLength("H", 10.0) + layoutLength("A", 10.0), 1e-3);
  // The last A at (60, 50): its lowest point on that baseline.
  double lowestNearX60 = 1e300;
  for (const Polyline& p : allPaths(r.drawing))
    for (const Vec2& q : p.points)
      if (q.x() > 59.0) lowestNearX60 = std::min(lowestNearX60, q.y());
  EXPECT_NEAR(lowestNearX60, 60.0 - 50.0, 1e-3);
}

TEST_F(TextRedraw, TheTextsTransformAppliesAndFillNoneDrawsNothing) {
  const ImportResult r = import("<text x=\"0\" y=\"0\" font-size=\"10\" transform=\"translate(30 20) rotate(90)\">HH</text>"
                                "<text x=\"5\" y=\"5\" fill=\"none\">H</text>");
  ASSERT_TRUE(r.ok()) << r.message.text();
  Vec2 lo, hi;
  ASSERT_TRUE(text::strokeBounds(allPaths(r.drawing), lo, hi));
  // Turned 90 deg (clockwise on the page): the run goes down the page, its height along x.
  EXPECT_NEAR(hi.x() - lo.x(), 7.0, 1e-3);
  EXPECT_GT(hi.y() - lo.y(), 7.0);
  EXPECT_NEAR(text::strokeLengthMm(allPaths(r.drawing)), layoutLength("HH", 10.0), 1e-3);
}

TEST_F(TextRedraw, TheRestOfTheDocumentKeepsItsBytesAndLineNumbers) {
  const QString doc = QStringLiteral(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"50mm\" height=\"50mm\" viewBox=\"0 0 50 50\">\n"
      "<text x=\"5\" y=\"20\"\n      font-size=\"8\">H<tspan>\nA</tspan></text><rect x=\"1\" y=\"1\" width=\"2\" height=\"2\"/>\n"
      "<path d=\"M 1 1 L 2 q\"/>\n<text x=\"1\" y=\"1\"/>\n</svg>\n");
  std::vector<Message> warnings;
  const QString out = redrawTextInFont(doc, font_, 96.0, warnings);
  EXPECT_EQ(out.count(u'\n'), doc.count(u'\n'));
  EXPECT_FALSE(out.contains(QStringLiteral("<text")));
  EXPECT_TRUE(out.startsWith(doc.left(doc.indexOf(QStringLiteral("<text")))));
  EXPECT_TRUE(out.endsWith(QStringLiteral("\n<path d=\"M 1 1 L 2 q\"/>\n<g></g>\n</svg>\n"))) << out.toStdString();
  EXPECT_TRUE(out.contains(QStringLiteral("<rect x=\"1\" y=\"1\" width=\"2\" height=\"2\"/>")));
  EXPECT_TRUE(warnings.empty());
  // The path's warning names its line (5), with the redraw as without it.
  ImportOptions o;
  o.textFont = fontPath_;
  const ImportResult r = importSvgData(doc.toUtf8(), QStringLiteral("doc.svg"), o);
  const ImportResult plain = importSvgData(doc.toUtf8(), QStringLiteral("doc.svg"));
  ASSERT_TRUE(r.ok() && plain.ok()) << r.message.text();
  EXPECT_TRUE(test::warned(r, "line 5: <path> attribute d: invalid path data")) << test::joined(r);
  EXPECT_TRUE(test::warned(plain, "line 5: <path> attribute d: invalid path data")) << test::joined(plain);
}

TEST_F(TextRedraw, TextOnAPathIsNamedAndAnUnknownFontRefusesTheImport) {
  const ImportResult r = import("<defs><path id=\"p\" d=\"M0 0 L50 0\"/></defs>"
                                "<text x=\"5\" y=\"20\">H<textPath xlink:href=\"#p\">AAA</textPath></text>");
  ASSERT_TRUE(r.ok()) << r.message.text();
  EXPECT_TRUE(test::warned(r, "text on a path (<textPath>) is not drawn")) << test::joined(r);
  EXPECT_NEAR(text::strokeLengthMm(allPaths(r.drawing)), layoutLength("H", 16.0), 1e-3);  // 16: the default size
  ImportOptions o;
  o.textFont = "no-such-font";
  const ImportResult bad = test::importText(test::page("<text x=\"1\" y=\"9\">H</text>"), o);
  EXPECT_EQ(bad.status, ImportStatus::InvalidOptions);
  EXPECT_NE(bad.message.text().find("text font: no-such-font"), std::string::npos) << bad.message.text();
}

}  // namespace
}  // namespace fivebar::svg
