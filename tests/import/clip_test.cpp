// SPDX-License-Identifier: GPL-3.0-or-later
// Clip paths applied to the plotted lines (issue 29). The geometry (clip.hpp) against an
// independent inside test (winding number by angle summation) on seeded random polylines: every
// kept point inside, every input point inside the region covered by a kept piece. Then through the
// importer: a rect clip on a group, clip-rule evenodd, clipPathUnits="objectBoundingBox", a clip
// path clipped by another (intersection), nested clipped groups, a transformed element, a fill-only
// shape clipped as an area; expected pieces worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/import/clip.hpp"
#include "geometry_support.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::allPaths;
using test::importText;
using test::joined;
using test::page;

std::uint32_t seed() {
  const char* s = std::getenv("FIVEBAR_TEST_SEED");
  return s ? static_cast<std::uint32_t>(std::strtoul(s, nullptr, 10)) : 20261122u;
}

// Winding number by angle summation (independent of clip.cpp's crossing count).
int windingBySum(const Vec2& p, const std::vector<Vec2>& ring) {
  double sum = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i] - p, b = ring[(i + 1) % ring.size()] - p;
    sum += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  return static_cast<int>(std::lround(sum / (2 * std::numbers::pi)));
}

double distanceToRing(const Vec2& p, const std::vector<Vec2>& ring) { return test::distanceToPolyline(p, ring, true); }

TEST(Clip, PiecesLieInsideAndCoverWhatIsInsideRandomLinesAgainstAStar) {
  std::mt19937 rng(seed());
  std::uniform_real_distribution<double> coord(-60.0, 60.0);
  // A self-intersecting five-pointed star: nonzero fills its centre, evenodd leaves it empty.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double a = std::numbers::pi / 2 + k * 4 * std::numbers::pi / 5;
    star.emplace_back(50 * std::cos(a), 50 * std::sin(a));
  }
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    const std::vector<ClipShape> clip{{{star}, rule}};
    auto inside = [&](const Vec2& p) {
      const int w = windingBySum(p, star);
      return rule == FillRule::EvenOdd ? w % 2 != 0 : w != 0;
    };
    for (int trial = 0; trial < 40; ++trial) {
      Polyline line;
      for (int i = 0; i < 6; ++i) line.points.emplace_back(coord(rng), coord(rng));
      line.closed = trial % 2 == 0;
      const std::vector<Polyline> kept = clipLines(std::vector<Polyline>{line}, clip);
      for (const Polyline& piece : kept)
        for (std::size_t i = 0; i + 1 < piece.points.size(); ++i)
          for (double t : {0.1, 0.5, 0.9}) {
            const Vec2 p = piece.points[i] + t * (piece.points[i + 1] - piece.points[i]);
            EXPECT_TRUE(inside(p) || distanceToRing(p, star) < 1e-6) << "seed " << seed() << " trial " << trial;
          }
      // Every point of the input well inside is on a kept piece; well outside, on none.
      const std::size_t n = line.points.size();
      for (std::size_t i = 0; i < (line.closed ? n : n - 1); ++i)
        for (int k = 0; k < 20; ++k) {
          const Vec2 p = line.points[i] + (k + 0.5) / 20.0 * (line.points[(i + 1) % n] - line.points[i]);
          if (distanceToRing(p, star) < 1e-3) continue;
          double best = 1e300;
          for (const Polyline& piece : kept) best = std::min(best, test::distanceToPolyline(p, piece.points, piece.closed));
          if (inside(p)) EXPECT_LT(best, 1e-9) << "seed " << seed() << " trial " << trial;
          else EXPECT_GT(best, 1e-6) << "seed " << seed() << " trial " << trial;
        }
    }
  }
}

// Total drawn length.
double drawn(const ImportResult& r) {
  double s = 0.0;
  for (const Polyline& l : allPaths(r.drawing)) {
    for (std::size_t i = 1; i < l.points.size(); ++i) s += (l.points[i] - l.points[i - 1]).norm();
    if (l.closed) s += (l.points.front() - l.points.back()).norm();
  }
  return s;
}

const char* kClip = "<clipPath id=\"c\"><rect x=\"20\" y=\"10\" width=\"30\" height=\"20\"/></clipPath>";

TEST(Clip, AGroupIsCutToItsClipPathWhereverTheClipPathStands) {
  // A horizontal line across the page at y = 20: only x in [20, 50] is inside the rect.
  for (const std::string& body :
       {std::string(kClip) + "<g clip-path=\"url(#c)\"><path d=\"M0 20 L100 20\" stroke=\"black\"/></g>",
        "<g style=\"clip-path: url(#c)\"><path d=\"M0 20 L100 20\" stroke=\"black\"/></g><defs>" + std::string(kClip) +
            "</defs>"}) {
    const ImportResult r = importText(page(body));
    ASSERT_TRUE(r.ok()) << r.message;
    const auto p = allPaths(r.drawing);
    ASSERT_EQ(p.size(), 1u) << joined(r);
    EXPECT_NEAR(std::min(p[0].points.front().x(), p[0].points.back().x()), 20.0, 1e-9);
    EXPECT_NEAR(std::max(p[0].points.front().x(), p[0].points.back().x()), 50.0, 1e-9);
    EXPECT_FALSE(test::warned(r, "clip-path")) << joined(r);
  }
}

TEST(Clip, ClipRuleUnitsTransformsAndIntersections) {
  const std::string line = "<path d=\"M0 20 L100 20\" stroke=\"black\"";
  // evenodd: a rect with a hole 30..40 drawn inside it -> [20, 30] and [40, 50].
  const ImportResult evenodd = importText(page(
      "<clipPath id=\"c\"><path clip-rule=\"evenodd\" d=\"M20 10 h30 v20 h-30 Z M30 15 h10 v10 h-10 Z\"/></clipPath>" +
      line + " clip-path=\"url(#c)\"/>"));
  ASSERT_TRUE(evenodd.ok()) << evenodd.message;
  EXPECT_EQ(allPaths(evenodd.drawing).size(), 2u);
  EXPECT_NEAR(drawn(evenodd), 20.0, 1e-9);
  // objectBoundingBox: fractions of the clipped element's bounding box.
  const ImportResult box = importText(page(
      "<clipPath id=\"b\" clipPathUnits=\"objectBoundingBox\"><rect x=\"0.25\" y=\"0\" width=\"0.5\" height=\"1\"/></clipPath>"
      "<rect x=\"10\" y=\"10\" width=\"40\" height=\"20\" fill=\"none\" stroke=\"black\" clip-path=\"url(#b)\"/>"));
  ASSERT_TRUE(box.ok()) << box.message;
  // The middle half of the 40 x 20 rect's box is x 20..40 over its full height: 20 mm of the top
  // and 20 mm of the bottom edge are drawn, the left and right sides (x 10, x 50) are outside.
  EXPECT_NEAR(drawn(box), 40.0, 1e-6);
  // A clip path clipped by another: [20, 50] and [35, 80] intersect in [35, 50].
  const ImportResult chain = importText(page(
      "<clipPath id=\"d\"><rect x=\"35\" y=\"0\" width=\"45\" height=\"50\"/></clipPath>"
      "<clipPath id=\"c\" clip-path=\"url(#d)\"><rect x=\"20\" y=\"10\" width=\"30\" height=\"20\"/></clipPath>" +
      line + " clip-path=\"url(#c)\"/>"));
  ASSERT_TRUE(chain.ok()) << chain.message;
  EXPECT_NEAR(drawn(chain), 15.0, 1e-9);
  // Nested clipped groups intersect too.
  const ImportResult nested = importText(page(
      std::string(kClip) + "<clipPath id=\"d\"><rect x=\"35\" y=\"0\" width=\"45\" height=\"50\"/></clipPath>"
      "<g clip-path=\"url(#d)\"><g clip-path=\"url(#c)\">" + line + "/></g></g>"));
  ASSERT_TRUE(nested.ok()) << nested.message;
  EXPECT_NEAR(drawn(nested), 15.0, 1e-9);
  // userSpaceOnUse is the element's own space, its transform included: translate(10) moves both.
  const ImportResult moved = importText(page(std::string(kClip) + line + " transform=\"translate(10 0)\" clip-path=\"url(#c)\"/>"));
  ASSERT_TRUE(moved.ok()) << moved.message;
  const auto p = allPaths(moved.drawing);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(std::min(p[0].points.front().x(), p[0].points.back().x()), 30.0, 1e-9);
  EXPECT_NEAR(drawn(moved), 30.0, 1e-9);
}

TEST(Clip, AFillOnlyShapeIsClippedAsAnAreaAndKeepsAClosedOutline) {
  // A filled 40 x 40 square at (0, 0) under the rect clip (20..50 x 10..30): a 20 x 20 square.
  const ImportResult r = importText(page(std::string(kClip) +
                                         "<rect x=\"0\" y=\"0\" width=\"40\" height=\"40\" fill=\"black\" clip-path=\"url(#c)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto p = allPaths(r.drawing);
  ASSERT_EQ(p.size(), 1u) << joined(r);
  EXPECT_TRUE(p[0].closed);
  EXPECT_TRUE(p[0].fillOnly && p[0].fillStart);
  EXPECT_NEAR(drawn(r), 80.0, 1e-6);
  // A clip region with nothing in it hides everything; an unknown clip is warned about.
  const ImportResult empty = importText(page(
      "<clipPath id=\"e\"/><path d=\"M0 20 L100 20\" stroke=\"black\" clip-path=\"url(#e)\"/>"
      "<path d=\"M0 40 L100 40\" stroke=\"red\"/>"));
  ASSERT_TRUE(empty.ok()) << empty.message;
  EXPECT_EQ(allPaths(empty.drawing).size(), 1u);
  // A clip-path in a style sheet is not applied, and says so.
  const ImportResult sheet = importText(page(std::string(kClip) + "<style>.c { clip-path: url(#c) }</style>"
                                             "<path class=\"c\" d=\"M0 20 L100 20\" stroke=\"black\"/>"));
  ASSERT_TRUE(sheet.ok()) << sheet.message;
  EXPECT_TRUE(test::warned(sheet, "clip-path set in a style sheet is not applied")) << joined(sheet);
}

}  // namespace
}  // namespace fivebar::svg
