// SPDX-License-Identifier: GPL-3.0-or-later
// Unit conversions (core/kinematics/units.hpp): known values and round trips.
#include <gtest/gtest.h>

#include <random>

#include "core/kinematics/units.hpp"

using namespace fivebar;

TEST(Units, AnglesKnownValues) {
  EXPECT_DOUBLE_EQ(radFromDeg(180.0), kPi);
  EXPECT_DOUBLE_EQ(radFromDeg(90.0), kPi / 2.0);
  EXPECT_DOUBLE_EQ(degFromRad(kPi / 4.0), 45.0);
  EXPECT_DOUBLE_EQ(degFromRad(1.0), 57.29577951308232);
  EXPECT_DOUBLE_EQ(radFromDeg(-15.0), -0.2617993877991494);
}

TEST(Units, RatesKnownValues) {
  // GRBL $110 in deg/min: 1 rad/s = 3437.746770784939 deg/min.
  EXPECT_DOUBLE_EQ(degPerMinFromRadPerS(1.0), 3437.746770784939);
  EXPECT_DOUBLE_EQ(radPerSFromDegPerMin(21600.0), 2.0 * kPi);  // one turn per second
  EXPECT_DOUBLE_EQ(degPerS2FromRadPerS2(kPi), 180.0);
  EXPECT_DOUBLE_EQ(radPerS2FromDegPerS2(3000.0), 3000.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(mmPerMinFromMmPerS(50.0), 3000.0);
  EXPECT_DOUBLE_EQ(mmPerSFromMmPerMin(600.0), 10.0);
}

TEST(Units, RoundTripsAreExactToRounding) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> value(-1e4, 1e4);
  for (int i = 0; i < 1000; ++i) {
    const double v = value(rng);
    EXPECT_NEAR(degFromRad(radFromDeg(v)), v, 1e-12 * std::abs(v) + 1e-15);
    EXPECT_NEAR(degPerMinFromRadPerS(radPerSFromDegPerMin(v)), v, 1e-12 * std::abs(v) + 1e-15);
    EXPECT_NEAR(radPerSFromDegPerMin(degPerMinFromRadPerS(v)), v, 1e-12 * std::abs(v) + 1e-15);
    EXPECT_NEAR(degPerS2FromRadPerS2(radPerS2FromDegPerS2(v)), v, 1e-12 * std::abs(v) + 1e-15);
    EXPECT_NEAR(mmPerSFromMmPerMin(mmPerMinFromMmPerS(v)), v, 1e-12 * std::abs(v) + 1e-15);
    // Rounding for files: the 1e-9 grid, never further than half a step.
    EXPECT_NEAR(roundForFile(v), v, 0.5e-9 + 1e-12 * std::abs(v));
  }
}

TEST(Units, RoundForFileRemovesConversionNoise) {
  EXPECT_EQ(roundForFile(degFromRad(0.2617993877991494)), 15.0);
  EXPECT_EQ(roundForFile(14.999999999999998), 15.0);
  EXPECT_EQ(roundForFile(-0.1234567891234), -0.123456789);
}

TEST(Units, NormalizeKeepsTheConventionRange) {
  EXPECT_DOUBLE_EQ(normalizeDeg(180.0), 180.0);
  EXPECT_DOUBLE_EQ(normalizeDeg(-180.0), 180.0);
  EXPECT_DOUBLE_EQ(normalizeDeg(370.0), 10.0);
  EXPECT_DOUBLE_EQ(normalizeRad(-kPi), kPi);
  EXPECT_NEAR(unwrapNear(0.1, 2.0 * kPi), 2.0 * kPi + 0.1, 1e-12);
}
