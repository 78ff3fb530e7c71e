// SPDX-License-Identifier: GPL-3.0-or-later
// Every length in its unit (issue 29): the resolver unit by unit against hand-computed user
// units (CSS: 96 px per inch), then true sizes on the page through the whole import: a rect sized
// in each unit in a document whose user unit is one CSS px (no viewBox), percentages on the axis
// each attribute belongs to, em/ex from the element's font size, nested viewports.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/import/svg_lengths.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::allPaths;
using test::importText;
using test::joined;

constexpr double kMmPerPx = 25.4 / 96.0;  // CSS

double user(const char* text, LengthAxis axis = LengthAxis::Width, double font = 16.0,
            UserViewport viewport = {200.0, 100.0}) {
  return resolveLength(QString::fromLatin1(text), axis, LengthContext{viewport, font, 96.0}).value_or(-1.0);
}

TEST(Lengths, EachCssUnitInUserUnitsAt96PxPerInch) {
  EXPECT_DOUBLE_EQ(user("1in"), 96.0);
  EXPECT_DOUBLE_EQ(user("1cm"), 96.0 / 2.54);
  EXPECT_DOUBLE_EQ(user("1mm"), 96.0 / 25.4);
  EXPECT_DOUBLE_EQ(user("1Q"), 96.0 / 101.6);
  EXPECT_DOUBLE_EQ(user("1pt"), 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(user("1pc"), 16.0);
  EXPECT_DOUBLE_EQ(user("7px"), 7.0);
  EXPECT_DOUBLE_EQ(user("7"), 7.0);
  EXPECT_DOUBLE_EQ(user("-2.5e1mm"), -25.0 * 96.0 / 25.4);
  // em and ex follow the element's font size, not a fixed 16 px.
  EXPECT_DOUBLE_EQ(user("2em", LengthAxis::Width, 20.0), 40.0);
  EXPECT_DOUBLE_EQ(user("2ex", LengthAxis::Width, 20.0), 20.0);
  EXPECT_FALSE(resolveLength(u"3furlongs", LengthAxis::Width, {}).has_value());
}

TEST(Lengths, PercentagesUseTheAxisOfTheAttribute) {
  // A 200 x 100 viewport: width 200, height 100, normalised diagonal sqrt((200^2 + 100^2) / 2).
  EXPECT_DOUBLE_EQ(user("10%", LengthAxis::Width), 20.0);
  EXPECT_DOUBLE_EQ(user("10%", LengthAxis::Height), 10.0);
  EXPECT_DOUBLE_EQ(user("10%", LengthAxis::Diagonal), 0.1 * std::sqrt(25000.0));
  EXPECT_FALSE(resolveLength(u"10%", LengthAxis::Width, LengthContext{{0.0, 0.0}, 16.0, 96.0}).has_value());
  EXPECT_EQ(lengthAttributeAxis(u"line", u"x2"), LengthAxis::Width);
  EXPECT_EQ(lengthAttributeAxis(u"rect", u"ry"), LengthAxis::Height);
  EXPECT_EQ(lengthAttributeAxis(u"circle", u"r"), LengthAxis::Diagonal);
  EXPECT_FALSE(lengthAttributeAxis(u"path", u"x").has_value());
}

struct Box {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -std::numeric_limits<double>::infinity(), maxY = maxX;
  double width() const { return maxX - minX; }
  double height() const { return maxY - minY; }
};

// Bounding box of every point in the page frame (mm, y down).
Box pageBox(const Drawing& d) {
  Box b;
  for (const Polyline& line : allPaths(d))
    for (const Vec2& p : line.points) {
      b.minX = std::min(b.minX, p.x());
      b.maxX = std::max(b.maxX, p.x());
      b.minY = std::min(b.minY, d.heightMm - p.y());
      b.maxY = std::max(b.maxY, d.heightMm - p.y());
    }
  return b;
}

// A 300 mm square page without a viewBox: one user unit is one CSS px (25.4 / 96 mm).
std::string pxPage(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"300mm\" height=\"300mm\">" + body + "</svg>";
}

struct UnitCase {
  const char* length;
  double mm;  // worked out by hand
};

TEST(Lengths, ARectSizedInEachUnitIsItsTrueSizeOnThePage) {
  const UnitCase cases[] = {{"2in", 50.8},   {"5cm", 50.0},       {"40mm", 40.0},  {"100Q", 25.0},
                            {"72pt", 25.4},  {"6pc", 25.4},       {"96px", 25.4},  {"96", 25.4},
                            {"1.5in", 38.1}, {"144pt", 50.8}};
  for (const UnitCase& c : cases) {
    const std::string l = c.length;
    const ImportResult r = importText(pxPage("<rect x=\"" + l + "\" y=\"" + l + "\" width=\"" + l +
                                             "\" height=\"" + l + "\" fill=\"none\" stroke=\"black\"/>"));
    ASSERT_TRUE(r.ok()) << c.length << ": " << r.message;
    const Box b = pageBox(r.drawing);
    EXPECT_NEAR(b.minX, c.mm, 1e-9) << c.length;
    EXPECT_NEAR(b.minY, c.mm, 1e-9) << c.length;
    EXPECT_NEAR(b.width(), c.mm, 1e-9) << c.length;
    EXPECT_NEAR(b.height(), c.mm, 1e-9) << c.length;
  }
}

TEST(Lengths, EmAndExFollowTheFontSizeOfTheElementAndItsAncestors) {
  // font-size 20 px (attribute) and 10 mm (style, on a nested group): 1em = 20 px, then 10 mm.
  const ImportResult r = importText(pxPage(
      "<g font-size=\"20\"><rect x=\"1em\" y=\"2ex\" width=\"8em\" height=\"4ex\" fill=\"none\" stroke=\"black\"/>"
      "<g style=\"font-size:10mm\"><rect x=\"10em\" y=\"1em\" width=\"2em\" height=\"2ex\" fill=\"none\" "
      "stroke=\"red\"/></g></g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.drawing.layers.size(), 2u);
  Drawing first = r.drawing, second = r.drawing;
  first.layers.resize(1);
  second.layers.erase(second.layers.begin());
  const Box a = pageBox(first);
  EXPECT_NEAR(a.minX, 20 * kMmPerPx, 1e-9);
  EXPECT_NEAR(a.minY, 20 * kMmPerPx, 1e-9);
  EXPECT_NEAR(a.width(), 160 * kMmPerPx, 1e-9);
  EXPECT_NEAR(a.height(), 40 * kMmPerPx, 1e-9);
  const Box b = pageBox(second);
  EXPECT_NEAR(b.minX, 100.0, 1e-9);
  EXPECT_NEAR(b.minY, 10.0, 1e-9);
  EXPECT_NEAR(b.width(), 20.0, 1e-9);
  EXPECT_NEAR(b.height(), 10.0, 1e-9);
}

// A 200 x 100 viewBox on a 200 mm x 100 mm page: one user unit is 1 mm.
std::string mmPage(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"100mm\" viewBox=\"0 0 200 100\">" +
         body + "</svg>";
}

TEST(Lengths, PercentagesOnShapesTakeTheRightAxis) {
  const ImportResult rect = importText(mmPage(
      "<rect x=\"10%\" y=\"10%\" width=\"80%\" height=\"80%\" fill=\"none\" stroke=\"black\"/>"));
  ASSERT_TRUE(rect.ok()) << rect.message;
  Box b = pageBox(rect.drawing);
  EXPECT_NEAR(b.minX, 20.0, 1e-9);
  EXPECT_NEAR(b.minY, 10.0, 1e-9);
  EXPECT_NEAR(b.width(), 160.0, 1e-9);
  EXPECT_NEAR(b.height(), 80.0, 1e-9);
  const ImportResult line = importText(mmPage("<line x1=\"10%\" y1=\"50%\" x2=\"90%\" y2=\"50%\" stroke=\"black\"/>"));
  ASSERT_TRUE(line.ok()) << line.message;
  b = pageBox(line.drawing);
  EXPECT_NEAR(b.minX, 20.0, 1e-9);
  EXPECT_NEAR(b.maxX, 180.0, 1e-9);
  EXPECT_NEAR(b.minY, 50.0, 1e-9);
  const ImportResult ellipse = importText(mmPage(
      "<ellipse cx=\"50%\" cy=\"50%\" rx=\"20%\" ry=\"20%\" fill=\"none\" stroke=\"black\"/>"));
  ASSERT_TRUE(ellipse.ok()) << ellipse.message;
  b = pageBox(ellipse.drawing);
  EXPECT_NEAR(b.width(), 80.0, 0.05);   // 2 x 20 % of 200
  EXPECT_NEAR(b.height(), 40.0, 0.05);  // 2 x 20 % of 100
  EXPECT_NEAR(0.5 * (b.minX + b.maxX), 100.0, 0.05);
  const ImportResult circle = importText(mmPage("<circle cx=\"100\" cy=\"50\" r=\"10%\" fill=\"none\" stroke=\"black\"/>"));
  ASSERT_TRUE(circle.ok()) << circle.message;
  b = pageBox(circle.drawing);
  EXPECT_NEAR(b.width(), 2 * 0.1 * std::sqrt(25000.0), 0.05);
}

TEST(Lengths, MillimetresInAViewBoxAreCssMillimetresOfUserSpace) {
  // resvg shapes/rect/mm-values.svg: x="5mm" is 5 * 96 / 25.4 = 18.9 user units (here: mm).
  const ImportResult r = importText(mmPage("<rect x=\"5mm\" y=\"5mm\" width=\"44mm\" height=\"20mm\" rx=\"6mm\" "
                                           "fill=\"none\" stroke=\"black\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const Box b = pageBox(r.drawing);
  const double u = 96.0 / 25.4;
  EXPECT_NEAR(b.minX, 5 * u, 1e-6);
  EXPECT_NEAR(b.minY, 5 * u, 1e-6);
  EXPECT_NEAR(b.width(), 44 * u, 1e-6);
  EXPECT_NEAR(b.height(), 20 * u, 1e-6);
}

TEST(Lengths, PercentagesInsideANestedSvgAreOfItsViewport) {
  // The nested viewport is 100 x 40 user units: 50 % of it is 50 x 20 (not 100 x 50 of the root).
  const ImportResult r = importText(mmPage(
      "<svg x=\"10\" y=\"10\" width=\"100\" height=\"40\"><rect width=\"50%\" height=\"50%\" fill=\"none\" "
      "stroke=\"black\"/></svg>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const Box b = pageBox(r.drawing);
  EXPECT_NEAR(b.minX, 10.0, 1e-9);
  EXPECT_NEAR(b.minY, 10.0, 1e-9);
  EXPECT_NEAR(b.width(), 50.0, 1e-9);
  EXPECT_NEAR(b.height(), 20.0, 1e-9);
}

TEST(Lengths, AUseOfAnSvgGivesItTheUsesSize) {
  // A 10 x 10 viewBox in a 40 x 80 viewport at (20, 10), meet, centred: scale 4, 40 x 40 at
  // (20, 30). At its own size (100 % of the root: 200 x 100) it would be 100 x 100 at (50, 0).
  const ImportResult r = importText(mmPage(
      "<defs><svg id=\"s\" viewBox=\"0 0 10 10\"><rect width=\"10\" height=\"10\" fill=\"none\" "
      "stroke=\"black\"/></svg></defs><use href=\"#s\" x=\"20\" y=\"10\" width=\"40\" height=\"80\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const Box b = pageBox(r.drawing);
  EXPECT_NEAR(b.minX, 20.0, 1e-9);
  EXPECT_NEAR(b.minY, 30.0, 1e-9);
  EXPECT_NEAR(b.width(), 40.0, 1e-9);
  EXPECT_NEAR(b.height(), 40.0, 1e-9);
}

TEST(Lengths, UseAndMarkerLengthsInUnits) {
  const ImportResult use = importText(mmPage(
      "<defs><rect id=\"r\" width=\"10\" height=\"10\" fill=\"none\" stroke=\"black\"/></defs>"
      "<use href=\"#r\" x=\"1in\" y=\"10%\"/>"));
  ASSERT_TRUE(use.ok()) << use.message;
  const Box b = pageBox(use.drawing);
  EXPECT_NEAR(b.minX, 96.0, 1e-9);
  EXPECT_NEAR(b.minY, 10.0, 1e-9);
  // A marker 1 cm wide (userSpaceOnUse) maps its 0..10 viewBox onto 96 / 2.54 user units.
  const ImportResult marker = importText(mmPage(
      "<marker id=\"m\" viewBox=\"0 0 10 10\" markerWidth=\"1cm\" markerHeight=\"1cm\" markerUnits=\"userSpaceOnUse\">"
      "<rect width=\"10\" height=\"10\" fill=\"none\" stroke=\"red\"/></marker>"
      "<path d=\"M20 20 L150 20\" stroke=\"black\" marker-end=\"url(#m)\"/>"));
  ASSERT_TRUE(marker.ok()) << marker.message;
  Drawing markerOnly = marker.drawing;
  std::erase_if(markerOnly.layers, [](const Layer& l) { return l.rgb != 0xFF0000u; });
  ASSERT_EQ(markerOnly.layers.size(), 1u) << joined(marker);
  const Box m = pageBox(markerOnly);
  EXPECT_NEAR(m.width(), 96.0 / 2.54, 1e-6);
  EXPECT_NEAR(m.minX, 150.0, 1e-6);
  // markerUnits="strokeWidth": a stroke-width of 1mm (96 / 25.4 user units) scales a 1 x 1 marker.
  const ImportResult stroke = importText(mmPage(
      "<marker id=\"m\" viewBox=\"0 0 1 1\" markerWidth=\"1\" markerHeight=\"1\">"
      "<rect width=\"1\" height=\"1\" fill=\"none\" stroke=\"red\"/></marker>"
      "<path d=\"M20 20 L150 20\" stroke=\"black\" stroke-width=\"1mm\" marker-end=\"url(#m)\"/>"));
  ASSERT_TRUE(stroke.ok()) << stroke.message;
  Drawing strokeMarker = stroke.drawing;
  std::erase_if(strokeMarker.layers, [](const Layer& l) { return l.rgb != 0xFF0000u; });
  ASSERT_EQ(strokeMarker.layers.size(), 1u) << joined(stroke);
  EXPECT_NEAR(pageBox(strokeMarker).width(), 96.0 / 25.4, 1e-6);
}

}  // namespace
}  // namespace fivebar::svg
