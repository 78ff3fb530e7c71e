// SPDX-License-Identifier: GPL-3.0-or-later
// In-process import of small hand-written documents: units, frame, tolerance, structure.
#include <gtest/gtest.h>

#include <chrono>

#include <atomic>
#include <cmath>
#include <numbers>

#include "geometry_support.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::allPaths;
using test::importText;
using test::page;

constexpr double kExact = 1e-9;  // mm; pure affine arithmetic
const char* kStroke = " stroke=\"black\" fill=\"none\"";

std::string svgWithSize(const std::string& size, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" " + size + ">" + body + "</svg>";
}

TEST(ImportUnits, A100MmWideFileIs100MmWhateverTheUnit) {
  for (const char* size : {"width=\"100mm\" height=\"40mm\"", "width=\"10cm\" height=\"4cm\"",
                           "width=\"283.46456692913387pt\" height=\"113.38582677165354pt\"",
                           "width=\"377.95275590551176\" height=\"151.18110236220471\""}) {
    const ImportResult r = importText(svgWithSize(std::string(size) + " viewBox=\"0 0 1000 400\"",
                                                  std::string("<path d=\"M0 0 L1000 400\"") + kStroke + "/>"));
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.drawing.widthMm, 100.0, 1e-6) << size;
    EXPECT_NEAR(r.drawing.heightMm, 40.0, 1e-6) << size;
    const auto paths = allPaths(r.drawing);
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_NEAR((paths[0].points.back() - Vec2(100, 0)).norm(), 0.0, 1e-6) << size;
  }
}

TEST(ImportUnits, WithoutViewBoxUserUnitsArePxAt96DpiOrTheGivenDpi) {
  const std::string doc = svgWithSize("width=\"100mm\" height=\"50mm\"",
                                      std::string("<path d=\"M0 10 L96 10\"") + kStroke + "/>");
  const ImportResult r = importText(doc);
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].points[1].x() - p[0].points[0].x(), 25.4, 1e-9);  // 96 px = 1 inch
  ImportOptions at72;
  at72.dpi = 72.0;
  const ImportResult r72 = importText(svgWithSize("width=\"720\" height=\"72\"",
                                                  std::string("<path d=\"M0 0 L72 0\"") + kStroke + "/>"),
                                      at72);
  ASSERT_TRUE(r72.ok()) << r72.message;
  EXPECT_NEAR(r72.drawing.widthMm, 254.0, 1e-9);
  EXPECT_NEAR(allPaths(r72.drawing)[0].points[1].x(), 25.4, 1e-9);
}

TEST(ImportFrame, SvgYDownBecomesWorkYUpWithOriginBottomLeft) {
  const ImportResult r = importText(page(std::string("<path d=\"M10 5 L30 45\"") + kStroke + "/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR((p[0].points[0] - Vec2(10, 45)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[0].points[1] - Vec2(30, 5)).norm(), 0.0, kExact);
}

TEST(ImportFrame, ForcedWidthScalesUniformly) {
  ImportOptions o;
  o.forcedWidthMm = 200.0;
  const ImportResult r = importText(page(std::string("<path d=\"M0 0 L100 50\"") + kStroke + "/>", 100, 50), o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(r.drawing.widthMm, 200.0);
  EXPECT_DOUBLE_EQ(r.drawing.heightMm, 100.0);
  EXPECT_NEAR((allPaths(r.drawing)[0].points[1] - Vec2(200, 0)).norm(), 0.0, kExact);
}

// Largest distance from the analytic ellipse (centre, u, v in work mm) to the polyline.
double worstGap(const Polyline& line, const Vec2& centre, const Vec2& u, const Vec2& v) {
  double worst = 0.0;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * std::numbers::pi * i / 3600.0;
    worst = std::max(worst, test::distanceToPolyline(centre + u * std::cos(t) + v * std::sin(t),
                                                     line.points, line.closed));
  }
  return worst;
}

TEST(ImportTolerance, CircleAndRotatedEllipseStayWithinTheChordTolerance) {
  for (double tolerance : {0.05, 0.005}) {
    ImportOptions o;
    o.toleranceMm = tolerance;
    const ImportResult r = importText(
        page(std::string("<circle cx=\"50\" cy=\"25\" r=\"20\"") + kStroke + "/>"
             "<ellipse cx=\"50\" cy=\"25\" rx=\"30\" ry=\"10\" transform=\"rotate(30 50 25)\"" + kStroke + "/>"),
        o);
    ASSERT_TRUE(r.ok()) << r.message;
    const auto p = allPaths(r.drawing);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(p[0].closed && p[1].closed);
    const Vec2 centre(50, 25);  // (50, 50 - 25) in the work frame
    EXPECT_LE(worstGap(p[0], centre, {20, 0}, {0, 20}), tolerance);
    for (const Vec2& q : p[0].points) EXPECT_NEAR((q - centre).norm(), 20.0, 1e-9);
    // rotate(30) in y-down is clockwise-on-screen; in y-up the axis is at -30 degrees.
    const double a = -std::numbers::pi / 6;
    EXPECT_LE(worstGap(p[1], centre, 30 * Vec2(std::cos(a), std::sin(a)),
                       10 * Vec2(-std::sin(a), std::cos(a))), tolerance);
    EXPECT_GT(p[0].points.size(), 20u);
  }
}

TEST(ImportTolerance, ArcPathIsWithinTolerancePlusQtsArcApproximation) {
  // Qt turns arcs into cubics (error ~2.7e-4 r); the flattening adds at most the tolerance.
  const double tolerance = 0.05, r = 20.0;
  ImportOptions o;
  o.toleranceMm = tolerance;
  const ImportResult res = importText(
      page(std::string("<path d=\"M30,25 A20,20 0 1,0 70,25 A20,20 0 1,0 30,25 Z\"") + kStroke + "/>"), o);
  ASSERT_TRUE(res.ok()) << res.message;
  const auto p = allPaths(res.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_LE(worstGap(p[0], {50, 25}, {r, 0}, {0, r}), tolerance + 3e-4 * r);
}

// Straight lines are their own geometry (no flattening error to pay for); curves are marked.
TEST(ImportTolerance, CurvesAreMarkedFlattenedStraightLinesAreNot) {
  const std::string shapes =
      "<path d=\"M0 0 L10 0 L10 10 M20 0 C25 5 30 5 35 0 L40 0\" fill=\"none\" stroke=\"#000\"/>"
      "<polyline points=\"0 20 10 20 10 30\" fill=\"none\" stroke=\"#000\"/>"
      "<line x1=\"0\" y1=\"40\" x2=\"10\" y2=\"40\" stroke=\"#000\"/>";
  for (const std::string& extra : {std::string(), std::string("<circle cx=\"60\" cy=\"20\" r=\"5\" "
                                                             "fill=\"none\" stroke=\"#000\"/>")}) {
    // Without the circle the direct reader reads the file, with it the general path.
    const ImportResult r = importText(page(shapes + extra));
    ASSERT_TRUE(r.ok()) << r.message;
    const std::vector<Polyline> paths = allPaths(r.drawing);
    ASSERT_EQ(paths.size(), extra.empty() ? 4u : 5u);
    EXPECT_FALSE(paths[0].flattened);  // M0 0 L10 0 L10 10
    EXPECT_TRUE(paths[1].flattened);   // the subpath with a cubic
    EXPECT_FALSE(paths[2].flattened);  // polyline
    EXPECT_FALSE(paths[3].flattened);  // line
    if (!extra.empty()) {
      EXPECT_TRUE(paths[4].flattened);  // circle
    }
  }
}

// The points budget stops the import as soon as it is passed (the direct reader and the general
// path alike), naming the budget.
TEST(ImportHostile, ThePointsBudgetStopsTheImportEarly) {
  std::string many;
  for (int i = 0; i < 400; ++i)
    many += "<path d=\"M0 " + std::to_string(i % 50) + " L100 " + std::to_string(i % 50) +
            "\" stroke=\"#000\"/>";
  ImportOptions o;
  o.maxPoints = 500;
  for (const std::string& extra : {std::string(), std::string("<rect width=\"5\" height=\"5\" stroke=\"#000\"/>")}) {
    const ImportResult stopped = importText(page(many + extra), o);
    EXPECT_EQ(stopped.status, ImportStatus::TooManyPoints);
    EXPECT_NE(stopped.message.text().find("more than 500 points after flattening (the points budget)"),
              std::string::npos) << stopped.message;
    o.maxPoints = 900;  // 800 points + the rectangle's 4
    EXPECT_TRUE(importText(page(many + extra), o).ok());
    o.maxPoints = 500;
  }
}

// Found by fuzz/svg_import_fuzz.cpp (fuzz/regressions/svg_import): one cubic whose control point
// lies 1e13 units away needs ~1e7 points within the tolerance; the curve was flattened whole
// before the budget was looked at (seconds, and gigabytes for a larger number). The budget now
// stops the curve itself, in the direct reader, the general path and a clip path alike.
TEST(ImportHostile, TheBudgetStopsInsideOneHugeCurve) {
  const std::string curve = "<path d=\"M0 0 C 10 10, 98264869374483 20, 100 100\" stroke=\"#000\"/>";
  const std::string clipped = "<clipPath id=\"c\"><path d=\"M0 0 C 10 10, 98264869374483 20, 100 100\"/></clipPath>"
                              "<path d=\"M0 0 L50 50\" stroke=\"#000\" clip-path=\"url(#c)\"/>";
  ImportOptions o;
  o.maxPoints = 10'000;
  for (const std::string& body : {curve, clipped, curve + "<g opacity=\"0.5\">" + curve + "</g>"}) {
    const auto started = std::chrono::steady_clock::now();
    const ImportResult stopped = importText(page(body), o);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(stopped.status, ImportStatus::TooManyPoints) << body << ": " << stopped.message;
    EXPECT_LT(seconds, 1.0) << body;
  }
}

TEST(ImportStructure, EachSubpathIsItsOwnPolylineWithTheClosedFlag) {
  const ImportResult r = importText(page(std::string("<path d=\"M10 10 L20 10 M30 10 L40 10 L35 20 Z\"") + kStroke + "/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_FALSE(p[0].closed);
  EXPECT_EQ(p[0].points.size(), 2u);
  EXPECT_TRUE(p[1].closed);
  EXPECT_EQ(p[1].points.size(), 3u);  // the closing point is implied, not repeated
}

TEST(ImportStructure, NestedTransformsUseAndHrefAreApplied) {
  const ImportResult r = importText(page(
      "<defs><path id=\"p\" d=\"M0 0 L10 0\"/></defs>"
      "<g transform=\"translate(10,5)\"><g transform=\"scale(2)\">"
      "<rect x=\"1\" y=\"1\" width=\"2\" height=\"3\"" + std::string(kStroke) + "/></g></g>"
      "<use xlink:href=\"#p\" x=\"5\" y=\"40\" stroke=\"#0000ff\"/>"
      "<use href=\"#p\" x=\"50\" y=\"40\" stroke=\"#00ff00\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 3u);
  ASSERT_EQ(p[0].points.size(), 4u);
  EXPECT_NEAR((p[0].points[0] - Vec2(12, 50 - 7)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[0].points[2] - Vec2(16, 50 - 13)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[1].points[0] - Vec2(5, 10)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[1].points[1] - Vec2(15, 10)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[2].points[1] - Vec2(60, 10)).norm(), 0.0, kExact);
}

TEST(ImportStructure, NestedSvgMapsItsViewBox) {
  const ImportResult r = importText(page(
      "<svg x=\"10\" y=\"10\" width=\"20\" height=\"20\" viewBox=\"0 0 10 10\">"
      "<path d=\"M0 0 L10 10\"" + std::string(kStroke) + "/></svg>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR((p[0].points[0] - Vec2(10, 40)).norm(), 0.0, kExact);
  EXPECT_NEAR((p[0].points[1] - Vec2(30, 20)).norm(), 0.0, kExact);
}

TEST(ImportStructure, DisplayNoneHiddenAndTransparentAreSkipped) {
  const ImportResult r = importText(page(
      "<path d=\"M0 0 L1 1\" display=\"none\"" + std::string(kStroke) + "/>"
      "<g style=\"display:none\"><path d=\"M0 0 L2 2\"" + kStroke + "/></g>"
      "<path d=\"M0 0 L3 3\" visibility=\"hidden\"" + kStroke + "/>"
      "<path d=\"M0 0 L4 4\" stroke-opacity=\"0\" stroke=\"black\" fill=\"none\"/>"
      "<path d=\"M5 5 L6 6\"" + kStroke + "/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR((p[0].points[0] - Vec2(5, 45)).norm(), 0.0, kExact);
}

TEST(ImportStructure, FillOnlyShapesAreOutlinedOrSkippedAndFilledStrokedOnce) {
  const std::string doc = page(
      "<rect x=\"1\" y=\"1\" width=\"5\" height=\"5\" fill=\"#ff0000\"/>"
      "<rect x=\"10\" y=\"1\" width=\"5\" height=\"5\" fill=\"#ff0000\" stroke=\"#0000ff\"/>");
  const ImportResult outlined = importText(doc);
  ASSERT_TRUE(outlined.ok()) << outlined.message;
  ASSERT_EQ(test::pathCount(outlined.drawing), 2u);
  ASSERT_EQ(outlined.drawing.layers.size(), 2u);
  EXPECT_EQ(outlined.drawing.layers[0].rgb, 0xff0000u);
  EXPECT_EQ(outlined.drawing.layers[1].rgb, 0x0000ffu);
  ImportOptions strokesOnly;
  strokesOnly.outlineFills = false;
  const ImportResult skipped = importText(doc, strokesOnly);
  ASSERT_TRUE(skipped.ok()) << skipped.message;
  ASSERT_EQ(test::pathCount(skipped.drawing), 1u);
  EXPECT_EQ(skipped.drawing.layers[0].rgb, 0x0000ffu);
}

TEST(ImportStructure, StyleSheetsCannotTurnLayerMarkersIntoLines) {
  const ImportResult r = importText(page(
      "<style>line { stroke-width: 3px; stroke: #ff0000 } * { opacity: 1 }</style>"
      "<g id=\"a\"><path d=\"M1 1 L2 2\"" + std::string(kStroke) + "/></g>"
      "<g id=\"b\"><line x1=\"5\" y1=\"5\" x2=\"9\" y2=\"5\"/></g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.drawing.layers.size(), 2u);
  EXPECT_EQ(r.drawing.layers[0].id, "a");
  EXPECT_EQ(r.drawing.layers[0].paths.size(), 1u);
  ASSERT_EQ(r.drawing.layers[1].paths.size(), 1u);  // the document's own line, styled red
  EXPECT_EQ(r.drawing.layers[1].rgb, 0xff0000u);
  EXPECT_NEAR((r.drawing.layers[1].paths[0].points[0] - Vec2(5, 45)).norm(), 0.0, kExact);
}

TEST(ImportStructure, TextBecomesOutlines) {
  const ImportResult r = importText(page("<text x=\"10\" y=\"30\" font-size=\"10\" font-family=\"DejaVu Sans\">Hi</text>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_GE(p.size(), 2u);  // at least the H and the i
  for (const Polyline& line : p)
    for (const Vec2& q : line.points) {
      EXPECT_GT(q.x(), 9.0);
      EXPECT_LT(q.x(), 30.0);
      EXPECT_GT(q.y(), 50 - 31.0);  // glyphs sit on the baseline y = 30 (svg)
      EXPECT_LT(q.y(), 50 - 19.0);
    }
}

TEST(ImportHostile, PathWithMoreThan32767ElementsImportsWhole) {
  constexpr int kSegments = 40000;
  std::string d = "M0 0";
  for (int i = 1; i <= kSegments; ++i) d += " L" + std::to_string(i * 0.002) + (i % 2 ? " 1" : " 0");
  const ImportResult r = importText(page("<path d=\"" + d + "\"" + std::string(kStroke) + "/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  std::size_t points = 0;
  const auto p = allPaths(r.drawing);
  for (const Polyline& line : p) points += line.points.size();
  // Split parts restart at the previous part's last point: one repeated point per extra part.
  EXPECT_EQ(points, kSegments + 1 + (p.size() - 1));
  EXPECT_GE(p.size(), 2u);
  EXPECT_NEAR((p.back().points.back() - Vec2(kSegments * 0.002, 50.0)).norm(), 0.0, 1e-9);
  bool warned = false;
  for (const fivebar::Message& w : r.warnings) warned = warned || w.text().find("split") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(ImportHostile, NaNAndOverflowAreRefusedWithElementAndLine) {
  const ImportResult nan = importText(page("\n<path id=\"bad\" d=\"M0 0 L NaN 5\"/>"));
  EXPECT_EQ(nan.status, ImportStatus::InvalidNumber);
  EXPECT_NE(nan.message.text().find("test.svg"), std::string::npos) << nan.message;
  EXPECT_NE(nan.message.text().find("line 2"), std::string::npos) << nan.message;
  EXPECT_NE(nan.message.text().find("<path id=\"bad\">"), std::string::npos) << nan.message;
  EXPECT_NE(nan.message.text().find("NaN"), std::string::npos) << nan.message;
  const ImportResult inf = importText(page("<circle cx=\"1e999\" cy=\"1\" r=\"1\"/>"));
  EXPECT_EQ(inf.status, ImportStatus::InvalidNumber);
  EXPECT_NE(inf.message.text().find("attribute cx"), std::string::npos) << inf.message;
}

TEST(ImportHostile, AbsurdCoordinatesAreRefused) {
  const ImportResult r = importText(page(std::string("<path d=\"M0 0 L3e9 0\"") + kStroke + "/>"));
  EXPECT_EQ(r.status, ImportStatus::AbsurdCoordinates);
  EXPECT_NE(r.message.text().find("beyond"), std::string::npos) << r.message;
}

TEST(ImportErrors, MalformedXmlWrongRootAndBadOptionsNameTheProblem) {
  const ImportResult xml = importText("<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path></svg>");
  EXPECT_EQ(xml.status, ImportStatus::MalformedXml);
  EXPECT_NE(xml.message.text().find("line 2"), std::string::npos) << xml.message;
  const ImportResult root = importText("<html><body/></html>");
  EXPECT_EQ(root.status, ImportStatus::InvalidDocument);
  EXPECT_NE(root.message.text().find("not <svg>"), std::string::npos) << root.message;
  ImportOptions bad;
  bad.toleranceMm = 0.0;
  const ImportResult options = importText(page(""), bad);
  EXPECT_EQ(options.status, ImportStatus::InvalidOptions);
  EXPECT_NE(options.message.text().find("toleranceMm"), std::string::npos) << options.message;
}

TEST(ImportProgress, ReportsRisingFractionsToOneAndHonoursCancel) {
  std::string body;
  for (int i = 0; i < 3000; ++i) body += "<path d=\"M0 0 L" + std::to_string(i % 100) + " 5\"" + kStroke + "/>";
  std::vector<double> seen;
  const ImportResult r = svg::importSvgData(QByteArray::fromStdString(page(body)), QStringLiteral("p.svg"),
                                            {}, [&](double f) { seen.push_back(f); });
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(seen.size(), 3u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  std::atomic<bool> cancel{true};
  ImportOptions o;
  o.cancel = &cancel;
  const ImportResult c = svg::importSvgData(QByteArray::fromStdString(page(body)), QStringLiteral("p.svg"), o);
  EXPECT_EQ(c.status, ImportStatus::Cancelled);
}

}  // namespace
}  // namespace fivebar::svg
