// SPDX-License-Identifier: GPL-3.0-or-later
// Dashed strokes drawn as SVG draws them (issue 29): each dash a polyline (pen up in between),
// dasharray and dashoffset in the element's user units along the path, odd lists repeated, the
// pattern restarting per subpath and running over a closed shape's closing edge; the pen width
// (set here or inherited) changes nothing; DashMode::Solid draws the stroke whole, in process and
// through the worker. Expected dashes are worked out by hand from the pattern.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include <utility>

#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::allPaths;
using test::importText;
using test::page;

using Span = std::pair<double, double>;  // x from, x to (page mm) of a horizontal dash

// The horizontal dashes drawn, left to right, as x spans.
std::vector<Span> spans(const ImportResult& r) {
  std::vector<Span> out;
  for (const Polyline& line : allPaths(r.drawing)) {
    EXPECT_FALSE(line.closed);
    out.emplace_back(line.points.front().x(), line.points.back().x());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expectSpans(const ImportResult& r, const std::vector<Span>& expected, const std::string& what) {
  ASSERT_TRUE(r.ok()) << what << ": " << r.message;
  const std::vector<Span> got = spans(r);
  ASSERT_EQ(got.size(), expected.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].first, expected[i].first, 1e-9) << what << " dash " << i;
    EXPECT_NEAR(got[i].second, expected[i].second, 1e-9) << what << " dash " << i;
  }
}

std::string line(const std::string& attributes) {
  return page("<path d=\"M10 10 L60 10\" fill=\"none\" stroke=\"black\" " + attributes + "/>");
}

TEST(Dashes, DasharrayAndOffsetInUserUnitsAlongThePath) {
  const std::vector<Span> tenFive = {{10, 20}, {25, 35}, {40, 50}, {55, 60}};
  expectSpans(importText(line("stroke-dasharray=\"10 5\"")), tenFive, "10 5");
  expectSpans(importText(line("stroke-dasharray=\"10,5\" stroke-dashoffset=\"3\"")),
              {{10, 17}, {22, 32}, {37, 47}, {52, 60}}, "offset 3");
  expectSpans(importText(line("stroke-dasharray=\"10 5\" stroke-dashoffset=\"-5\"")),
              {{15, 25}, {30, 40}, {45, 55}}, "offset -5");
  expectSpans(importText(line("stroke-dasharray=\"10\"")), {{10, 20}, {30, 40}, {50, 60}}, "odd list");
  expectSpans(importText(line("style=\"stroke-dasharray:10 5\"")), tenFive, "style");
  // The pen width is no factor (Qt keeps the pattern in units of it).
  expectSpans(importText(line("stroke-width=\"2\" stroke-dasharray=\"10 5\"")), tenFive, "width 2");
  expectSpans(importText(line("stroke-width=\"1mm\" stroke-dasharray=\"10 5\"")), tenFive, "width 1mm");
  expectSpans(importText(line("stroke-width=\"2%\" stroke-dasharray=\"10 5\"")), tenFive, "width 2%");
  expectSpans(importText(page("<g stroke-width=\"4\"><path d=\"M10 10 L60 10\" fill=\"none\" stroke=\"black\" "
                              "stroke-dasharray=\"10 5\"/></g>")),
              tenFive, "inherited width");
  expectSpans(importText(page("<g stroke-dasharray=\"10 5\"><path d=\"M10 10 L60 10\" fill=\"none\" "
                              "stroke=\"black\" stroke-width=\"3\"/></g>")),
              tenFive, "inherited dasharray");
  // Under scale(2) the pattern is in the path's own units: 5 2.5 there is 10 5 on the page.
  expectSpans(importText(page("<g transform=\"scale(2)\"><path d=\"M5 5 L30 5\" fill=\"none\" stroke=\"black\" "
                              "stroke-dasharray=\"5 2.5\"/></g>")),
              tenFive, "scaled");
  // "none" and all-zero patterns are solid.
  expectSpans(importText(line("stroke-dasharray=\"none\"")), {{10, 60}}, "none");
  expectSpans(importText(line("stroke-dasharray=\"0 0\"")), {{10, 60}}, "zeros");
}

TEST(Dashes, PatternRestartsAtEachSubpathAndBendsAroundCorners) {
  expectSpans(importText(page("<path d=\"M10 10 L22 10 M30 10 L42 10\" fill=\"none\" stroke=\"black\" "
                              "stroke-dasharray=\"5 3\"/>")),
              {{10, 15}, {18, 22}, {30, 35}, {38, 42}}, "two subpaths");
  // An L: 10 along x, then down; a 12-long dash takes the corner with it.
  const ImportResult r = importText(page("<path d=\"M10 10 L20 10 L20 30\" fill=\"none\" stroke=\"black\" "
                                         "stroke-dasharray=\"12 4\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 2u);  // [0, 12] and [16, 28] along the 30-long path
  const double h = r.drawing.heightMm;
  ASSERT_EQ(p[0].points.size(), 3u);
  EXPECT_NEAR((p[0].points[1] - Vec2(20, h - 10)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((p[0].points[2] - Vec2(20, h - 12)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((p[1].points.front() - Vec2(20, h - 16)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((p[1].points.back() - Vec2(20, h - 28)).norm(), 0.0, 1e-9);
}

double length(const Polyline& l) {
  double s = 0.0;
  for (std::size_t i = 1; i < l.points.size(); ++i) s += (l.points[i] - l.points[i - 1]).norm();
  return s;
}

TEST(Dashes, AClosedShapeIsDashedOverItsClosingEdgeAndTheSeamIsOneDash) {
  // A 40 x 10 rect: perimeter 100 from (10, 10) clockwise. "20 5" offset 10: on 0-10, off 10-15,
  // on 15-35, 40-60, 65-85, 90-100 and on over the start: 90-110 is one dash.
  const ImportResult r = importText(page("<rect x=\"10\" y=\"10\" width=\"40\" height=\"10\" fill=\"none\" "
                                         "stroke=\"black\" stroke-dasharray=\"20 5\" stroke-dashoffset=\"10\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 4u);
  double total = 0.0;
  for (const Polyline& l : p) {
    EXPECT_NEAR(length(l), 20.0, 1e-9);
    total += length(l);
  }
  EXPECT_NEAR(total, 80.0, 1e-9);
}

TEST(Dashes, SolidModeDrawsTheStrokeWholeInProcessAndThroughTheWorker) {
  const std::string doc = line("stroke-dasharray=\"10 5\"");
  ImportOptions solid;
  solid.dashes = DashMode::Solid;
  expectSpans(importText(doc, solid), {{10, 60}}, "solid");
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString path = dir.filePath(QStringLiteral("dashed.svg"));
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(QByteArray::fromStdString(doc));
  file.close();
  expectSpans(importSvgFile(path, solid), {{10, 60}}, "solid, worker");
  expectSpans(importSvgFile(path), {{10, 20}, {25, 35}, {40, 50}, {55, 60}}, "dashed, worker");
}

TEST(Dashes, PatternLengthsInUnits) {
  // A px page (no viewBox): 0.5in = 48 px, 0.25in = 24 px; dashes at 0-48, 72-120, 144-192 px.
  const ImportResult r = importText(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200px\" height=\"50px\"><path d=\"M0 10 L200 10\" "
      "stroke=\"black\" stroke-dasharray=\"0.5in 0.25in\"/></svg>");
  const double mm = 25.4 / 96.0;
  expectSpans(r, {{0, 48 * mm}, {72 * mm, 120 * mm}, {144 * mm, 192 * mm}}, "inches");
}

}  // namespace
}  // namespace fivebar::svg
