// SPDX-License-Identifier: GPL-3.0-or-later
// Nothing drawn that a browser does not show (issue 29): never-rendered elements wherever they
// stand, foreign namespaces, invisible paint, zero-length butt-capped subpaths, path data in error
// from its first command; a pattern fill drawn as the outline its warning promises; an element
// with a non-finite number or an absurd coordinate dropped with a warning naming it, the file
// refused only when nothing is left; viewBox messages in the SVG number grammar.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>

#include "core/import/path_data.hpp"
#include "core/import/svg_units.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::allPaths;
using test::importText;
using test::joined;
using test::page;
using test::warned;

// The frame every document below draws, so that an import is never empty: a 90 x 40 square at
// (5, 5) (page: 100 x 50 mm, 1 user unit = 1 mm).
const std::string kFrame = "<rect x=\"5\" y=\"5\" width=\"90\" height=\"40\" fill=\"none\" stroke=\"blue\"/>";

// The polylines drawn besides the frame (the frame is the only blue one).
std::vector<Polyline> besidesFrame(const ImportResult& r) {
  std::vector<Polyline> out;
  for (const Layer& l : r.drawing.layers)
    if (l.rgb != 0x0000FFu) out.insert(out.end(), l.paths.begin(), l.paths.end());
  return out;
}

const char* kShape = "<rect x=\"20\" y=\"20\" width=\"10\" height=\"10\" fill=\"none\" stroke=\"red\"/>";

TEST(Visibility, NeverRenderedElementsDrawNothingWhereverTheyStand) {
  for (const std::string tag : {"clipPath", "mask", "pattern", "filter", "metadata", "title", "desc",
                                "linearGradient", "radialGradient", "symbol", "marker"}) {
    for (const std::string& where : {std::string("%"), std::string("<g>%</g>"), std::string("<defs>%</defs>")}) {
      std::string body = where;
      body.replace(body.find('%'), 1, "<" + tag + " id=\"x\">" + kShape + "</" + tag + ">");
      const ImportResult r = importText(page(kFrame + body));
      ASSERT_TRUE(r.ok()) << tag << ": " << r.message;
      EXPECT_TRUE(besidesFrame(r).empty()) << "<" << tag << "> in " << where << " drew its content";
      EXPECT_EQ(allPaths(r.drawing).size(), 1u) << tag;
    }
  }
}

TEST(Visibility, ElementsOfAForeignNamespaceAreNotDrawn) {
  const ImportResult r = importText(page(kFrame + "<foo:rect xmlns:foo=\"http://example.org/notsvg\" x=\"20\" "
                                         "y=\"20\" width=\"10\" height=\"10\" stroke=\"red\"/>"
                                         "<g xmlns=\"http://example.org/notsvg\">" + kShape + "</g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(besidesFrame(r).empty());
  // Text inside a foreign <a> (resvg structure/svg/mixed-namespaces.svg) is not drawn; inside an
  // SVG <a> it is.
  auto text = [](const std::string& ns) {
    return importText(page(kFrame + "<text x=\"20\" y=\"30\" font-size=\"10\" fill=\"red\"><a" + ns +
                           ">Valid</a></text>"));
  };
  const ImportResult svgA = text(""), foreignA = text(" xmlns=\"http://example.org/notsvg\"");
  ASSERT_TRUE(svgA.ok() && foreignA.ok()) << svgA.message << foreignA.message;
  EXPECT_FALSE(besidesFrame(svgA).empty());
  EXPECT_TRUE(besidesFrame(foreignA).empty());
}

TEST(Visibility, InvisiblePaintDrawsNothing) {
  for (const std::string attributes :
       {"opacity=\"0\"", "visibility=\"hidden\"", "display=\"none\"", "stroke-opacity=\"0\"",
        "style=\"visibility:hidden\"", "style=\"opacity:0\""}) {
    const ImportResult r = importText(page(kFrame + "<path d=\"M20 20 L60 30\" fill=\"none\" stroke=\"red\" " +
                                           attributes + "/><g " + attributes + ">" + kShape + "</g>"));
    ASSERT_TRUE(r.ok()) << attributes << ": " << r.message;
    EXPECT_TRUE(besidesFrame(r).empty()) << attributes;
  }
  // A visible child of a hidden group is shown (visibility is inherited, not a cut).
  const ImportResult child = importText(
      page(kFrame + "<g visibility=\"hidden\"><path d=\"M20 20 L60 30\" stroke=\"red\" visibility=\"visible\"/></g>"));
  ASSERT_TRUE(child.ok()) << child.message;
  EXPECT_EQ(besidesFrame(child).size(), 1u);
}

TEST(Visibility, ZeroLengthButtCappedSubpathsAreNotDrawnRoundCappedDotsAre) {
  // vpype-plotter/issue_59/halftone_*.svg: "a 0 0 ..." to a point 0.001 away and back.
  // A tiny closed circle (r = 0.01) encloses something: its stroke shows as a dot and is kept.
  const std::string dots = "M20 20 a 0 0 0 1 0 0.001 0 Z M30 20 l 0 0 M40 20 L60 20 M70 20 a 0.01 0.01 0 1 0 0.001 0 Z";
  const ImportResult butt = importText(page(kFrame + "<path d=\"" + dots + "\" fill=\"none\" stroke=\"red\"/>"));
  ASSERT_TRUE(butt.ok()) << butt.message;
  ASSERT_EQ(besidesFrame(butt).size(), 2u);  // the real segment and the tiny circle
  EXPECT_NEAR((besidesFrame(butt)[0].points.back() - besidesFrame(butt)[0].points.front()).norm(), 20.0, 1e-9);
  EXPECT_TRUE(besidesFrame(butt)[1].closed);
  const ImportResult round = importText(
      page(kFrame + "<path d=\"" + dots + "\" fill=\"none\" stroke=\"red\" stroke-linecap=\"round\"/>"));
  ASSERT_TRUE(round.ok()) << round.message;
  EXPECT_EQ(besidesFrame(round).size(), 3u);  // the zero-radius arc's dot is shown by a renderer
}

TEST(Visibility, APatternFilledShapeIsDrawnAsItsOutline) {
  for (const std::string fill : {"fill=\"url(#p)\"", "style=\"fill:url(#p)\"", "fill=\"url(#p) none\""}) {
    const ImportResult r = importText(page(
        kFrame + "<defs><pattern id=\"p\" width=\"4\" height=\"4\" patternUnits=\"userSpaceOnUse\">"
                 "<rect width=\"2\" height=\"2\" fill=\"red\"/></pattern></defs>"
                 "<rect x=\"20\" y=\"20\" width=\"30\" height=\"10\" " + fill + "/>"));
    ASSERT_TRUE(r.ok()) << fill << ": " << r.message;
    EXPECT_TRUE(warned(r, "pattern fills are drawn as outlines")) << joined(r);
    const std::vector<Polyline> drawn = besidesFrame(r);
    ASSERT_EQ(drawn.size(), 1u) << fill;
    EXPECT_TRUE(drawn[0].closed);
    EXPECT_EQ(drawn[0].points.size(), 4u);
  }
}

TEST(PathData, DataWhoseFirstCommandIsNoMovetoIsInErrorFromIt) {
  const ParsedPath parsed = parsePathData(u"  A 5 5 0 0 1 50 50");
  EXPECT_TRUE(parsed.error);
  EXPECT_EQ(parsed.errorOffset, 2);
  EXPECT_TRUE(parsed.commands.empty());
  EXPECT_FALSE(parsePathData(u" m 1 1 2 2").error);
  for (const std::string d : {"A 5 5 0 0 1 50 50", "L 60 30", "10 10 L 60 30", "z"}) {
    const ImportResult r = importText(page(kFrame + "\n<path id=\"a\" d=\"" + d + "\" fill=\"none\" stroke=\"red\"/>"));
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_TRUE(besidesFrame(r).empty()) << d;
    const std::string first = d[0] >= 'A' ? d.substr(0, 1) : d.substr(0, d.find(' '));
    EXPECT_TRUE(warned(r, "line 2: <path id=\"a\"> attribute d: path data begins with \"" + first +
                              "\", not a moveto"))
        << d << "\n" << joined(r);
  }
}

TEST(Numbers, AnElementWithANonFiniteNumberIsDroppedAndTheRestDrawn) {
  const ImportResult r = importText(page(kFrame + "\n<path id=\"sail\" transform=\"matrix(-inf,0,0,1,0,0)\" "
                                                  "d=\"M0 0 L10 10\" stroke=\"red\"/>\n<g id=\"g\" "
                                                  "transform=\"scale(NaN)\">" + kShape + "</g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(allPaths(r.drawing).size(), 1u);  // the frame
  EXPECT_TRUE(warned(r, "line 2: <path id=\"sail\"> attribute transform contains a value that is not a number "
                        "(inf): the element is not drawn"))
      << joined(r);
  EXPECT_TRUE(warned(r, "line 3: <g id=\"g\"> attribute transform")) << joined(r);
  // Nothing else to draw: refused, naming the element.
  const ImportResult alone = importText(page("\n<path id=\"p\" d=\"M0 0 L 1e308 5\" stroke=\"black\"/>"));
  EXPECT_EQ(alone.status, ImportStatus::InvalidNumber);
  EXPECT_NE(alone.message.text().find("line 2: <path id=\"p\"> attribute d contains a number beyond 1e300"),
            std::string::npos)
      << alone.message;
}

TEST(Numbers, AnAbsurdCoordinateDropsItsLinesWithAWarningNamingTheElement) {
  const ImportResult r = importText(page(kFrame + "<g id=\"far\"><path d=\"M0 0 L3e9 0\" stroke=\"red\"/></g>"
                                                  "<g id=\"near\">" + kShape + "</g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(allPaths(r.drawing).size(), 2u);  // the frame and the near shape
  EXPECT_TRUE(warned(r, "<g id=\"far\"> has a point at")) << joined(r);
  EXPECT_TRUE(warned(r, "mm, beyond the 1000000")) << joined(r);
  const ImportResult alone = importText(page("<path d=\"M0 0 L3e9 0\" stroke=\"red\"/>"));
  EXPECT_EQ(alone.status, ImportStatus::AbsurdCoordinates) << alone.message;
}

TEST(Visibility, NothingOutsideThePageIsDrawnAndTheCutIsWarned) {
  // The page is 100 x 50: a line from x = -20 to 120 at y = 10 is drawn from 0 to 100.
  const ImportResult r = importText(page("<path d=\"M-20 10 L120 10\" stroke=\"black\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  const Polyline line = allPaths(r.drawing)[0];
  EXPECT_NEAR(std::min(line.points.front().x(), line.points.back().x()), 0.0, 1e-9);
  EXPECT_NEAR(std::max(line.points.front().x(), line.points.back().x()), 100.0, 1e-9);
  EXPECT_TRUE(warned(r, "lines outside the page (the SVG viewport) are not drawn")) << joined(r);
  EXPECT_FALSE(warned(importText(page(kFrame)), "outside the page"));
  // A nested <svg> clips its content to its viewport (x 10..30 here).
  const ImportResult nested = importText(page("<svg x=\"10\" y=\"0\" width=\"20\" height=\"50\">"
                                              "<path d=\"M-50 10 L150 10\" stroke=\"black\"/></svg>"));
  ASSERT_TRUE(nested.ok()) << nested.message;
  ASSERT_EQ(allPaths(nested.drawing).size(), 1u);
  const Polyline cut = allPaths(nested.drawing)[0];
  EXPECT_NEAR(std::abs(cut.points.back().x() - cut.points.front().x()), 20.0, 1e-9);
}

TEST(Numbers, ViewBoxNumbersFollowTheSvgNumberGrammar) {
  const NumberList list = scanNumberList(u"0 0 9E80.7");
  EXPECT_EQ(list.badAt, -1);
  EXPECT_EQ(list.tokens, QStringList({"0", "0", "9E80", ".7"}));
  EXPECT_EQ(scanNumberList(u"1-2.5.5e1").tokens, QStringList({"1", "-2.5", ".5e1"}));
  EXPECT_EQ(scanNumberList(u"1,,2").badAt, 2);
  EXPECT_EQ(viewBoxProblem(u"0 0 9E80.7"), "a number too large (9E80; at most 1e12)");
  EXPECT_EQ(viewBoxProblem(u"0 0 100"), "not four numbers (3 numbers)");
  EXPECT_EQ(viewBoxProblem(u"0 0 100 abc"), "\"abc\" is not a number (after 3 numbers)");
  EXPECT_EQ(viewBoxProblem(u"0,0,100,50"), "");
  EXPECT_EQ(viewBoxProblem(u"0-10 100 50"), "");  // 0, -10, 100, 50
  const ImportResult r = importText(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 9E80.7\"><path d=\"M0 0 L1 1\" stroke=\"black\"/></svg>");
  EXPECT_EQ(r.status, ImportStatus::InvalidDocument);
  EXPECT_NE(r.message.text().find("viewBox=\"0 0 9E80.7\": a number too large (9E80; at most 1e12)"),
            std::string::npos)
      << r.message;
}

}  // namespace
}  // namespace fivebar::svg
