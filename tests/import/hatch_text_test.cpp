// SPDX-License-Identifier: GPL-3.0-or-later
// Hatching what the importer marks as filled: text glyphs (nonzero, with counters as holes), an
// evenodd path with a hole, and a filled-and-stroked shape; checked against an independent
// winding number (angle summation) on the imported rings.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/planning/hatch.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using Rings = std::vector<std::vector<Vec2>>;

int windingByAngles(const Rings& rings, const Vec2& p) {
  double total = 0.0;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i] - p, b = ring[(i + 1) % ring.size()] - p;
      total += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  return static_cast<int>(std::lround(total / (2.0 * std::numbers::pi)));
}

double toBoundary(const Rings& rings, const Vec2& p) {
  double best = 1e300;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], ab = ring[(i + 1) % ring.size()] - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * ab - p).norm());
    }
  return best;
}

// The rings of the filled shapes of a drawing, with their rule.
std::vector<std::pair<Rings, FillRule>> filledShapes(const Drawing& d) {
  std::vector<std::pair<Rings, FillRule>> shapes;
  for (const Polyline& line : test::allPaths(d)) {
    if (line.fill == FillRule::None) continue;
    if (line.fillStart || shapes.empty()) shapes.push_back({{}, line.fill});
    shapes.back().first.push_back(line.points);
  }
  return shapes;
}

// Every hatch point inside its shape (or on its boundary); returns the hatch strokes.
std::size_t checkShapes(const Drawing& d, double spacing, double angle) {
  std::size_t strokes = 0;
  for (const auto& [rings, rule] : filledShapes(d)) {
    const std::vector<Polyline> lines = hatchArea(rings, rule, spacing, angle);
    strokes += lines.size();
    for (const Polyline& l : lines)
      for (std::size_t i = 0; i + 1 < l.points.size(); ++i)
        for (int s = 0; s <= 10; ++s) {
          const Vec2 p = l.points[i] + (l.points[i + 1] - l.points[i]) * (s / 10.0);
          if (toBoundary(rings, p) < 1e-7) continue;
          const int w = windingByAngles(rings, p);
          EXPECT_TRUE(rule == FillRule::EvenOdd ? (w & 1) != 0 : w != 0) << p.transpose();
        }
  }
  return strokes;
}

TEST(HatchImport, TextGlyphsAreHatchedInsideTheirOutlinesWithCountersLeftOpen) {
  const ImportResult r = test::importText(test::page(
      "<text x=\"5\" y=\"40\" font-size=\"30\" font-family=\"DejaVu Sans\" fill=\"black\">BOA</text>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto shapes = filledShapes(r.drawing);
  ASSERT_FALSE(shapes.empty());
  std::size_t rings = 0;
  for (const auto& s : shapes) rings += s.first.size();
  EXPECT_GE(rings, 6u);  // B (3), O (2), A (2)
  EXPECT_GT(checkShapes(r.drawing, 0.4, 0.6), 3u);
  // The counter of the O stays empty: no hatch point near its centre.
  HatchSettings settings;
  settings.spacingMm = 0.4;
  const Drawing& d = r.drawing;
  std::vector<Polyline> hatched;
  for (const Layer& l : d.layers) {
    auto out = applyFill(l.paths, FillMode::Hatch, settings);
    hatched.insert(hatched.end(), out.begin(), out.end());
  }
  EXPECT_GT(hatched.size(), test::allPaths(d).size());
}

TEST(HatchImport, EvenOddHoleAndNonZeroFillFromTheFile) {
  const std::string rings = "M10 10 H40 V40 H10 Z M20 20 H30 V30 H20 Z";  // same direction
  const ImportResult even = test::importText(test::page(
      "<path d=\"" + rings + "\" fill=\"black\" fill-rule=\"evenodd\"/>", 50, 50));
  const ImportResult nonzero = test::importText(test::page("<path d=\"" + rings + "\" fill=\"black\"/>", 50, 50));
  ASSERT_TRUE(even.ok() && nonzero.ok());
  ASSERT_EQ(filledShapes(even.drawing).size(), 1u);
  EXPECT_EQ(filledShapes(even.drawing)[0].second, FillRule::EvenOdd);
  EXPECT_EQ(filledShapes(nonzero.drawing)[0].second, FillRule::NonZero);
  checkShapes(even.drawing, 0.5, 0.3);
  checkShapes(nonzero.drawing, 0.5, 0.3);
  // Filled and stroked: the stroke is kept (not fill-only), the hatch added.
  const ImportResult both = test::importText(test::page(
      "<circle cx=\"25\" cy=\"25\" r=\"10\" fill=\"red\" stroke=\"black\"/>", 50, 50));
  ASSERT_TRUE(both.ok());
  const auto paths = test::allPaths(both.drawing);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].fill, FillRule::NonZero);
  EXPECT_FALSE(paths[0].fillOnly);
  HatchSettings s;
  s.outline = false;
  EXPECT_GT(applyFill(paths, FillMode::Hatch, s).size(), 1u);
  EXPECT_EQ(applyFill(paths, FillMode::None, s).size(), 1u);
  checkShapes(both.drawing, 0.5, 1.0);
}

}  // namespace
}  // namespace fivebar::svg
