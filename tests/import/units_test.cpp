// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/import/svg_units.hpp"

namespace fivebar::svg {
namespace {

double mm(const char* text, double dpi = 96.0) {
  const auto length = parseLength(QString::fromLatin1(text));
  EXPECT_TRUE(length.has_value()) << text;
  return lengthToMm(*length, dpi).value_or(-1.0);
}

TEST(Units, AbsoluteUnitsConvertToMillimetres) {
  EXPECT_DOUBLE_EQ(mm("100mm"), 100.0);
  EXPECT_DOUBLE_EQ(mm("2.5cm"), 25.0);
  EXPECT_DOUBLE_EQ(mm("1in"), 25.4);
  EXPECT_DOUBLE_EQ(mm("72pt"), 25.4);
  EXPECT_DOUBLE_EQ(mm("6pc"), 25.4);
  EXPECT_DOUBLE_EQ(mm(" 1e1 mm "), 10.0);
}

TEST(Units, UnitlessAndPxFollowTheDpiNot90) {
  EXPECT_DOUBLE_EQ(mm("96"), 25.4);
  EXPECT_DOUBLE_EQ(mm("96px"), 25.4);
  EXPECT_DOUBLE_EQ(mm("72", 72.0), 25.4);
  EXPECT_NE(mm("90"), 25.4);  // Qt's 90 dpi would give exactly one inch here
}

TEST(Units, PercentHasNoAbsoluteSizeAndGarbageIsNoLength) {
  const auto percent = parseLength(u"100%");
  ASSERT_TRUE(percent.has_value());
  EXPECT_FALSE(lengthToMm(*percent, 96.0).has_value());
  EXPECT_FALSE(parseLength(u"abc").has_value());
  EXPECT_FALSE(parseLength(u"12furlongs").has_value());
}

TEST(Units, PageFromViewBoxWhenSizeIsPercentOrMissing) {
  RootAttributes root;
  root.hasViewBox = true;
  root.viewBox = QStringLiteral("100 100 300 150");
  root.hasWidth = true;
  root.width = QStringLiteral("100%");
  PageSetup page;
  EXPECT_EQ(computePage(root, 96.0, page), "");
  EXPECT_DOUBLE_EQ(page.widthMm, 300 * 25.4 / 96);
  EXPECT_DOUBLE_EQ(page.heightMm, 150 * 25.4 / 96);
}

TEST(Units, OneSideGivenTheOtherFollowsTheViewBoxAspect) {
  RootAttributes root;
  root.hasViewBox = true;
  root.viewBox = QStringLiteral("0,0,200,100");
  root.hasWidth = true;
  root.width = QStringLiteral("10cm");
  PageSetup page;
  ASSERT_EQ(computePage(root, 96.0, page), "");
  EXPECT_DOUBLE_EQ(page.widthMm, 100.0);
  EXPECT_DOUBLE_EQ(page.heightMm, 50.0);
}

TEST(Units, PreserveAspectRatioPlacesTheViewBox) {
  const QRectF vb(0, 0, 100, 100);
  const QRectF port(0, 0, 200, 100);
  EXPECT_EQ(placeViewBox(vb, port, parsePreserveAspectRatio(u"")), QRectF(50, 0, 100, 100));
  EXPECT_EQ(placeViewBox(vb, port, parsePreserveAspectRatio(u"xMinYMin meet")), QRectF(0, 0, 100, 100));
  EXPECT_EQ(placeViewBox(vb, port, parsePreserveAspectRatio(u"xMaxYMax")), QRectF(100, 0, 100, 100));
  EXPECT_EQ(placeViewBox(vb, port, parsePreserveAspectRatio(u"none")), port);
  EXPECT_EQ(placeViewBox(vb, port, parsePreserveAspectRatio(u"xMidYMin slice")), QRectF(0, 0, 200, 200));
}

TEST(Units, ZeroOrNegativeSizeIsRefusedWithTheAttribute) {
  RootAttributes root;
  root.hasWidth = true;
  root.width = QStringLiteral("0");
  root.hasHeight = true;
  root.height = QStringLiteral("10");
  PageSetup page;
  const std::string error = computePage(root, 96.0, page).text();
  EXPECT_NE(error.find("width=\"0\""), std::string::npos) << error;
  root.width = QStringLiteral("10");
  root.hasViewBox = true;
  root.viewBox = QStringLiteral("0 0 -5 10");
  EXPECT_NE(computePage(root, 96.0, page).text().find("viewBox"), std::string::npos);
}

}  // namespace
}  // namespace fivebar::svg
