// SPDX-License-Identifier: GPL-3.0-or-later
// Markers (marker-start/mid/end) drawn as SVG 1.1 specifies: the content at each vertex, oriented
// (auto, auto-start-reverse, angle; the bisector at inner vertices), scaled (strokeWidth,
// userSpaceOnUse, viewBox, preserveAspectRatio), placed by refX/refY. Every expected position is
// worked out from the SVG by hand (page 100 x 50 mm, 1 user unit = 1 mm, y down).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/import/svg_markers.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::joined;
using test::warned;

using test::allPaths;
using test::importText;
using test::page;

// Page frame (y down) of a drawing point.
Vec2 onPage(const Drawing& d, const Vec2& p) { return {p.x(), d.heightMm - p.y()}; }

// True when some polyline has a point within tol of (x, y) (page frame).
bool hasPoint(const Drawing& d, double x, double y, double tol = 1e-6) {
  for (const Polyline& line : allPaths(d))
    for (const Vec2& p : line.points)
      if ((onPage(d, p) - Vec2(x, y)).norm() < tol) return true;
  return false;
}

// How many polylines run from a to b (either way; page frame): line-shaped marker content.
int segmentsFromTo(const Drawing& d, Vec2 a, Vec2 b, double tol = 1e-6) {
  int n = 0;
  for (const Polyline& line : allPaths(d)) {
    if (line.points.size() < 2) continue;
    const Vec2 p = onPage(d, line.points.front()), q = onPage(d, line.points.back());
    if (((p - a).norm() < tol && (q - b).norm() < tol) || ((p - b).norm() < tol && (q - a).norm() < tol)) ++n;
  }
  return n;
}

// A 10-unit stick from the reference point along +x: its far end shows position, scale, angle.
std::string stick(const std::string& id, const std::string& extra) {
  return "<marker id=\"" + id + "\" markerWidth=\"10\" markerHeight=\"10\" " + extra +
         "><path d=\"M0 0 L10 0\" fill=\"none\" stroke=\"black\"/></marker>";
}

TEST(Markers, EndMarkerIsATriangleAtTheLastVertexAlongThePath) {
  // The triangle's point (10, 5) is the reference-relative tip; refY 5 puts (0, 5) on the vertex.
  const ImportResult r = importText(page(
      "<defs><marker id=\"m\" markerWidth=\"10\" markerHeight=\"10\" refX=\"0\" refY=\"5\" orient=\"auto\""
      " markerUnits=\"userSpaceOnUse\"><path d=\"M0 0 L10 5 L0 10 Z\" fill=\"none\" stroke=\"black\"/></marker></defs>"
      "<path d=\"M10 10 L90 10\" stroke=\"black\" marker-end=\"url(#m)\"/>"
      "<path d=\"M50 40 L50 10\" stroke=\"black\" marker-end=\"url(#m)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 4u);
  EXPECT_TRUE(hasPoint(r.drawing, 90, 5));
  EXPECT_TRUE(hasPoint(r.drawing, 100, 10));
  EXPECT_TRUE(hasPoint(r.drawing, 90, 15));
  // Upward path (-90 degrees): the tip 10 above the end, the base across it.
  EXPECT_TRUE(hasPoint(r.drawing, 50, 0));
  EXPECT_TRUE(hasPoint(r.drawing, 45, 10));
  EXPECT_TRUE(hasPoint(r.drawing, 55, 10));
  EXPECT_FALSE(warned(r, "marker")) << joined(r);
}

TEST(Markers, StrokeWidthUnitsScaleAndFixedAngleAndStartReverse) {
  // Default markerUnits = strokeWidth: stroke-width 2 doubles the stick.
  const ImportResult w = importText(page("<defs>" + stick("s", "orient=\"auto\"") + "</defs>"
                                         "<line x1=\"10\" y1=\"10\" x2=\"60\" y2=\"10\" stroke=\"black\" "
                                         "stroke-width=\"2\" marker-end=\"url(#s)\"/>"));
  ASSERT_TRUE(w.ok()) << w.message;
  EXPECT_EQ(segmentsFromTo(w.drawing, {60, 10}, {80, 10}), 1);
  // orient="30": 30 degrees clockwise on the page (y down), whatever the direction.
  const ImportResult a = importText(page("<defs>" + stick("s", "orient=\"30\" markerUnits=\"userSpaceOnUse\"") +
                                         "</defs><line x1=\"10\" y1=\"10\" x2=\"10\" y2=\"40\" stroke=\"black\" "
                                         "marker-start=\"url(#s)\"/>"));
  ASSERT_TRUE(a.ok()) << a.message;
  const double c = 10 * std::cos(std::numbers::pi / 6), s = 10 * std::sin(std::numbers::pi / 6);
  EXPECT_EQ(segmentsFromTo(a.drawing, {10, 10}, {10 + c, 10 + s}), 1);
  // auto-start-reverse: the start marker points backwards, the end marker forwards.
  const ImportResult b = importText(page("<defs>" + stick("s", "orient=\"auto-start-reverse\" markerUnits=\"userSpaceOnUse\"") +
                                         "</defs><line x1=\"20\" y1=\"10\" x2=\"80\" y2=\"10\" stroke=\"black\" "
                                         "marker-start=\"url(#s)\" marker-end=\"url(#s)\"/>"));
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_EQ(segmentsFromTo(b.drawing, {20, 10}, {10, 10}), 1);
  EXPECT_EQ(segmentsFromTo(b.drawing, {80, 10}, {90, 10}), 1);
  EXPECT_EQ(allPaths(b.drawing).size(), 3u);
}

TEST(Markers, MidMarkersOnTheBisectorAtEveryInnerVertex) {
  // In along +x, out along -y (up the page): the bisector points 45 degrees up-right.
  const ImportResult r = importText(page("<defs>" + stick("s", "orient=\"auto\" markerUnits=\"userSpaceOnUse\"") +
                                         "</defs><polyline points=\"10 40 40 40 40 10 70 10\" fill=\"none\" "
                                         "stroke=\"black\" marker-mid=\"url(#s)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 3u);  // the polyline and two inner vertices, no ends
  const double h = 10 / std::sqrt(2.0);
  EXPECT_EQ(segmentsFromTo(r.drawing, {40, 40}, {40 + h, 40 - h}), 1);
  EXPECT_EQ(segmentsFromTo(r.drawing, {40, 10}, {40 + h, 10 - h}), 1);
}

TEST(Markers, CurveAndArcVerticesUseTheirTangents) {
  // Vertices: (10,10), the cubic's end (40,10), the next subpath's start (60,10), the arc's end
  // (80,10). The cubic arrives along (30,0)->(40,10): 45 degrees down. The arc (centre (70,10),
  // sweep 1) leaves (60,10) going up and arrives at (80,10) going down.
  const ImportResult r = importText(page("<defs>" + stick("s", "orient=\"auto\" markerUnits=\"userSpaceOnUse\"") +
                                         "</defs><path d=\"M10 10 C20 0 30 0 40 10 M60 10 A10 10 0 0 1 80 10\" "
                                         "fill=\"none\" stroke=\"black\" marker-start=\"url(#s)\" "
                                         "marker-mid=\"url(#s)\" marker-end=\"url(#s)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const double h = 10 / std::sqrt(2.0);
  EXPECT_EQ(segmentsFromTo(r.drawing, {10, 10}, {10 + h, 10 - h}), 1);  // start: along (10,-10)
  EXPECT_EQ(segmentsFromTo(r.drawing, {40, 10}, {40 + h, 10 + h}), 1);  // only a way in
  EXPECT_EQ(segmentsFromTo(r.drawing, {60, 10}, {60, 0}), 1);           // only a way out: up
  EXPECT_EQ(segmentsFromTo(r.drawing, {80, 10}, {80, 20}), 1);          // end of the arc: down
}

TEST(Markers, ViewBoxPreserveAspectRatioAndRefPoint) {
  // A 20 x 20 viewBox into 10 x 5, meet: scale 0.25, a 5 x 5 square centred on the vertex by
  // refX/refY 10 (viewBox units); none: 10 x 5.
  auto square = [](const std::string& ratio) {
    return page("<defs><marker id=\"q\" viewBox=\"0 0 20 20\" markerWidth=\"10\" markerHeight=\"5\" "
                "refX=\"10\" refY=\"10\" markerUnits=\"userSpaceOnUse\" preserveAspectRatio=\"" + ratio + "\">"
                "<rect width=\"20\" height=\"20\" fill=\"none\" stroke=\"black\"/></marker></defs>"
                "<line x1=\"10\" y1=\"25\" x2=\"50\" y2=\"25\" stroke=\"black\" marker-end=\"url(#q)\"/>");
  };
  const ImportResult meet = importText(square("xMidYMid meet"));
  ASSERT_TRUE(meet.ok()) << meet.message;
  ASSERT_EQ(allPaths(meet.drawing).size(), 2u);
  EXPECT_TRUE(hasPoint(meet.drawing, 47.5, 22.5));
  EXPECT_TRUE(hasPoint(meet.drawing, 52.5, 27.5));
  const ImportResult none = importText(square("none"));
  ASSERT_TRUE(none.ok()) << none.message;
  EXPECT_TRUE(hasPoint(none.drawing, 45, 22.5));
  EXPECT_TRUE(hasPoint(none.drawing, 55, 27.5));
}

TEST(Markers, PolygonVerticesStylePropertyInheritanceAndTransform) {
  // `marker` in a style on a group: every vertex of the polygon, the closing one included (4),
  // each a circle of radius 1 centred on it; the group's transform moves shape and markers.
  const ImportResult r = importText(page(
      "<marker id=\"dot\" markerWidth=\"4\" markerHeight=\"4\" refX=\"2\" refY=\"2\" markerUnits=\"userSpaceOnUse\">"
      "<circle cx=\"2\" cy=\"2\" r=\"1\" fill=\"none\" stroke=\"black\"/></marker>"
      "<g style=\"marker: url(#dot)\"><polygon points=\"10 10 30 10 30 30\" transform=\"translate(5 0)\" "
      "fill=\"none\" stroke=\"black\"/></g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 5u);
  for (const Vec2& centre : {Vec2(15, 10), Vec2(35, 10), Vec2(35, 30)}) {
    EXPECT_TRUE(hasPoint(r.drawing, centre.x() + 1, centre.y(), 1e-3)) << centre.transpose();
    EXPECT_TRUE(hasPoint(r.drawing, centre.x() - 1, centre.y(), 1e-3)) << centre.transpose();
  }
  // The marker element itself (outside defs) is not drawn: no circle at (2, 2).
  EXPECT_FALSE(hasPoint(r.drawing, 3, 2, 1e-3));
}

TEST(Markers, UnsupportedCasesAreWarned) {
  const std::string marker = stick("s", "style=\"overflow: hidden\"");
  // A rect with marker properties: SVG draws markers on path, line, polyline, polygon only.
  const ImportResult rect = importText(page("<defs>" + marker + "</defs><rect width=\"10\" height=\"10\" "
                                            "fill=\"none\" stroke=\"black\" marker-end=\"url(#s)\"/>"));
  ASSERT_TRUE(rect.ok()) << rect.message;
  EXPECT_EQ(allPaths(rect.drawing).size(), 1u);
  EXPECT_TRUE(warned(rect, "markers on <rect> are not drawn")) << joined(rect);
  // A style sheet rule with a descendant selector; a missing marker; explicit overflow clipping.
  const ImportResult css = importText(page("<style>g path { marker-end: url(#s) }</style><defs>" + marker +
                                           "</defs><g><path d=\"M0 0 L10 0\" stroke=\"black\" marker-start=\"url(#s)\"/>"
                                           "<path d=\"M0 5 L10 5\" stroke=\"black\" marker-start=\"url(#nope)\"/></g>"));
  ASSERT_TRUE(css.ok()) << css.message;
  EXPECT_EQ(allPaths(css.drawing).size(), 3u);
  EXPECT_TRUE(warned(css, "markers set in a style sheet for the selector 'g path' are not drawn"))
      << joined(css);
  EXPECT_TRUE(warned(css, "marker #nope not found")) << joined(css);
  EXPECT_TRUE(warned(css, "marker overflow clipping not applied")) << joined(css);
}

// Style sheets (<style>) set markers as attributes do, in CSS order: presentation attribute <
// style-sheet rule (by specificity, then order) < style attribute.
TEST(Markers, StyleSheetMarkersAreDrawnLikeAttributes) {
  const std::string sheet =
      "<style>/* markers */ .arrow { marker-end: url(#s) } path#plain { marker-end: none }\n"
      "line, polyline.tick { marker-start: url(#s) !important }</style>";
  const ImportResult r = importText(page(
      sheet + "<defs>" + stick("s", "") + "</defs>"
      "<path class=\"arrow\" d=\"M10 10 L30 10\" stroke=\"black\"/>"                    // end marker
      "<path id=\"plain\" class=\"arrow\" d=\"M10 20 L30 20\" stroke=\"black\"/>"      // #id beats .class
      "<path class=\"x arrow\" marker-end=\"url(#nope)\" d=\"M10 30 L30 30\" stroke=\"black\"/>"  // rule beats attribute
      "<path class=\"arrow\" style=\"marker-end: none\" d=\"M10 40 L30 40\" stroke=\"black\"/>"  // style wins
      "<line x1=\"50\" y1=\"10\" x2=\"70\" y2=\"10\" stroke=\"black\"/>"              // start marker
      "<polyline points=\"50 30 70 30\" fill=\"none\" stroke=\"black\"/>"));          // no class: none
  ASSERT_TRUE(r.ok()) << r.message;
  // The stick of marker s runs 10 units along +x from the vertex (orient 0, stroke width 1).
  EXPECT_EQ(segmentsFromTo(r.drawing, {30, 10}, {40, 10}), 1);
  EXPECT_EQ(segmentsFromTo(r.drawing, {30, 20}, {40, 20}), 0);
  EXPECT_EQ(segmentsFromTo(r.drawing, {30, 30}, {40, 30}), 1);
  EXPECT_EQ(segmentsFromTo(r.drawing, {30, 40}, {40, 40}), 0);
  EXPECT_EQ(segmentsFromTo(r.drawing, {50, 10}, {60, 10}), 1);
  EXPECT_EQ(segmentsFromTo(r.drawing, {50, 30}, {60, 30}), 0);
  EXPECT_EQ(allPaths(r.drawing).size(), 9u);  // 6 shapes + 3 markers
  EXPECT_FALSE(warned(r, "style sheet")) << joined(r);
  EXPECT_FALSE(warned(r, "marker #nope not found")) << joined(r);
}

TEST(Markers, StyleSheetSelectorsAreParsedAsCss) {
  const MarkerSheet s = parseMarkerSheet(
      u"a{fill:red} @media print { path { marker: url(#m) } } *{marker-mid:url(#m)} "
      u"#i.c1.c2 { marker : url(#m) } g > path { marker-end: url(#m) } path:hover{marker:none}");
  ASSERT_EQ(s.rules.size(), 2u);
  EXPECT_EQ(s.rules[0].specificity, 0);  // * first: lowest specificity
  EXPECT_EQ(s.rules[1].specificity, 120);
  EXPECT_EQ(s.rules[1].id, QStringLiteral("i"));
  EXPECT_EQ(s.rules[1].classes, QStringList({QStringLiteral("c1"), QStringLiteral("c2")}));
  EXPECT_EQ(s.unsupported,
            (std::vector<QString>{QStringLiteral("@media print"), QStringLiteral("g > path"),
                                  QStringLiteral("path:hover")}));
}

}  // namespace
}  // namespace fivebar::svg
