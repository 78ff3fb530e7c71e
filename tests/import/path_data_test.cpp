// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <random>

#include "../core/test_support.hpp"
#include "core/import/path_data.hpp"

namespace fivebar::svg {
namespace {

void expectCommand(const PathCommand& c, char op, std::initializer_list<double> v) {
  EXPECT_EQ(c.op, op);
  int i = 0;
  for (double x : v) EXPECT_DOUBLE_EQ(c.v[i++], x) << op << " value " << i - 1;
}

TEST(PathData, RelativeAndShorthandCommandsBecomeAbsolute) {
  const ParsedPath p = parsePathData(u"m10 10 h5 v5 l-5 0 z m1 1 2 2");
  ASSERT_FALSE(p.error);
  ASSERT_EQ(p.commands.size(), 7u);
  expectCommand(p.commands[0], 'M', {10, 10});
  expectCommand(p.commands[1], 'L', {15, 10});
  expectCommand(p.commands[2], 'L', {15, 15});
  expectCommand(p.commands[3], 'L', {10, 15});
  EXPECT_EQ(p.commands[4].op, 'Z');
  expectCommand(p.commands[5], 'M', {11, 11});  // relative to the closed subpath's start
  expectCommand(p.commands[6], 'L', {13, 13});  // implicit lineto after a moveto
}

TEST(PathData, SmoothCurvesReflectThePreviousControlPoint) {
  const ParsedPath c = parsePathData(u"M0 0 C1 1 2 1 3 0 S5 -1 6 0");
  ASSERT_EQ(c.commands.size(), 3u);
  expectCommand(c.commands[2], 'C', {4, -1, 5, -1, 6, 0});
  const ParsedPath q = parsePathData(u"M0 0 Q1 1 2 0 T4 0");
  ASSERT_EQ(q.commands.size(), 3u);
  expectCommand(q.commands[2], 'Q', {3, -1, 4, 0});
}

TEST(PathData, CompactArcFlagsAndNumbers) {
  const ParsedPath p = parsePathData(u"M0,0a5 5 0 0110 0.5.5.5 0 1 0 1 1");
  ASSERT_FALSE(p.error);
  ASSERT_EQ(p.commands.size(), 3u);
  expectCommand(p.commands[1], 'A', {5, 5, 0, 0, 1, 10, 0.5});
  expectCommand(p.commands[2], 'A', {0.5, 0.5, 0, 1, 0, 11, 1.5});  // implicit repeat, relative
  const ParsedPath q = parsePathData(u"M0 0 L1");
  EXPECT_TRUE(q.error);
  EXPECT_EQ(q.commands.size(), 1u);
}

// End points of the drawing commands (closepath resolved to the subpath start).
std::vector<std::pair<double, double>> drawnEnds(const std::vector<PathCommand>& commands) {
  std::vector<std::pair<double, double>> out;
  double sx = 0, sy = 0;
  for (const PathCommand& c : commands) {
    switch (c.op) {
      case 'M': sx = c.v[0]; sy = c.v[1]; break;
      case 'Z': out.emplace_back(sx, sy); break;
      case 'C': out.emplace_back(c.v[4], c.v[5]); break;
      case 'Q': out.emplace_back(c.v[2], c.v[3]); break;
      case 'A': out.emplace_back(c.v[5], c.v[6]); break;
      default: out.emplace_back(c.v[0], c.v[1]); break;
    }
  }
  return out;
}

TEST(PathData, SplittingKeepsEveryDrawnPointAndTheElementBudget) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  std::uniform_int_distribution<int> pick(0, 9);
  std::string d = "m1 1";
  for (int i = 0; i < 3000; ++i) {
    const int k = pick(rng);
    auto n = [&] { return std::to_string(coord(rng)); };
    if (k < 4) d += " l" + n() + " " + n();
    else if (k < 6) d += " c" + n() + " " + n() + " " + n() + " " + n() + " " + n() + " " + n();
    else if (k == 6) d += " s" + n() + " " + n() + " " + n() + " " + n();
    else if (k == 7) d += " a10 20 30 1 0 " + n() + " " + n();
    else if (k == 8) d += " z";
    else d += " M" + n() + " " + n();
  }
  const ParsedPath original = parsePathData(QString::fromStdString(d));
  ASSERT_FALSE(original.error);
  constexpr int kBudget = 200;
  const std::vector<QString> parts = splitPathData(original.commands, kBudget);
  ASSERT_GT(parts.size(), 10u);
  std::vector<PathCommand> joined;
  for (const QString& part : parts) {
    const ParsedPath p = parsePathData(part);
    ASSERT_FALSE(p.error) << part.left(80).toStdString();
    int elements = 0;
    for (const PathCommand& c : p.commands) elements += qtElementEstimate(c);
    EXPECT_LE(elements, kBudget);
    joined.insert(joined.end(), p.commands.begin(), p.commands.end());
  }
  EXPECT_EQ(drawnEnds(joined), drawnEnds(original.commands));
}

// Found by fuzz/path_data_fuzz.cpp (fuzz/regressions/path_data): an arc whose end point is near
// the largest double overflowed its centre to NaN, and the NaN sweep was converted to a piece
// count (undefined behaviour). Such an arc is its chord now.
TEST(PathData, AnArcWhoseCentreOverflowsIsItsChord) {
  const ParsedPath p = parsePathData(u"M0 4a25 25 1 0 0 5 0 01e301e308");
  ASSERT_FALSE(p.commands.empty());
  const std::vector<PathCommand> cubics = arcsAsCubics(p.commands);
  for (const PathCommand& c : cubics) EXPECT_NE(c.op, 'A');
  std::vector<PathCommand> out;
  PathCommand arc{'A', {25.0, 25.0, 0.0, 0.0, 1.0, 1e301, 1e308}};
  appendArcAsCubics(0.0, 4.0, arc, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].op, 'L');
  EXPECT_EQ(out[0].v[1], 1e308);
}

// Found by fuzz/path_data_fuzz.cpp: finite numbers whose absolute form overflows (a shorthand's
// reflected control point 2 x 1e308) gave inf and nan, which the long-path split then wrote as
// text that is no path data. The parse stops there, as at an unparsable number.
TEST(PathData, AnAbsoluteFormThatOverflowsIsBadData) {
  const QString d = QStringLiteral("M1e308 0 Q 1e308 15 1e308 16 T 1e308 17");
  const ParsedPath p = parsePathData(d);
  EXPECT_TRUE(p.error);
  ASSERT_EQ(p.commands.size(), 2u);
  EXPECT_EQ(p.errorOffset, d.indexOf(u'T') + 1);
  EXPECT_TRUE(parsePathData(u"m1e308 0 l1e308 0").error);
}

// Found by fuzz/path_data_fuzz.cpp (fuzz/regressions/path_data/long-number.txt): a number of more
// than 63 characters with an exponent wrote past the scanner's 64-character buffer, and a long
// number was cut in two (its 64th digit on read as the next number).
TEST(PathData, ANumberOfAnyLengthIsOneNumber) {
  const std::string digits(120, '9');
  const QString d = QString::fromStdString("M0.5" + digits + "E-1 2 L3 4");
  const ParsedPath p = parsePathData(d);
  ASSERT_FALSE(p.error) << p.errorOffset;
  ASSERT_EQ(p.commands.size(), 2u);
  EXPECT_DOUBLE_EQ(p.commands[0].v[0], 0.06);
  EXPECT_DOUBLE_EQ(p.commands[0].v[1], 2.0);
  const QString exponent = QString::fromStdString("M1" + std::string(70, '0') + "e-70 " + "+1.5e+1L0 0");
  const ParsedPath q = parsePathData(exponent);
  ASSERT_FALSE(q.error);
  EXPECT_DOUBLE_EQ(q.commands[0].v[0], 1.0);
  EXPECT_DOUBLE_EQ(q.commands[0].v[1], 15.0);
}

}  // namespace
}  // namespace fivebar::svg
