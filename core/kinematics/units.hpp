// SPDX-License-Identifier: GPL-3.0-or-later
// Unit conversions. Radians inside the core; degrees only at the edges (CLI, UI, G-code,
// profiles). This is the one tested place where the two meet.
#pragma once

#include <cmath>
#include <numbers>

namespace fivebar {

constexpr double kPi = std::numbers::pi;

constexpr double radFromDeg(double angleDeg) { return angleDeg * (kPi / 180.0); }
constexpr double degFromRad(double angleRad) { return angleRad * (180.0 / kPi); }

// Rates. GRBL stores joint speeds in deg/min ($110/$111) and accelerations in deg/s^2
// ($120/$121); feeds in G-code are mm/min. The core uses rad/s, rad/s^2 and mm/s.
constexpr double kSecondsPerMinute = 60.0;
constexpr double degPerMinFromRadPerS(double speedRadPerS) {
  return degFromRad(speedRadPerS) * kSecondsPerMinute;
}
constexpr double radPerSFromDegPerMin(double speedDegPerMin) {
  return radFromDeg(speedDegPerMin / kSecondsPerMinute);
}
constexpr double degPerS2FromRadPerS2(double accelRadPerS2) { return degFromRad(accelRadPerS2); }
constexpr double radPerS2FromDegPerS2(double accelDegPerS2) { return radFromDeg(accelDegPerS2); }
constexpr double mmPerMinFromMmPerS(double speedMmPerS) { return speedMmPerS * kSecondsPerMinute; }
constexpr double mmPerSFromMmPerMin(double speedMmPerMin) { return speedMmPerMin / kSecondsPerMinute; }

// A value rounded to 1e-9 of its unit, for files: 15 deg must not print as 14.999999999999998.
inline double roundForFile(double value) { return std::round(value * 1e9) / 1e9; }

// Wraps an angle in degrees into (-180, 180], as conventions.md requires for single poses.
inline double normalizeDeg(double angleDeg) {
  double r = std::fmod(angleDeg, 360.0);
  if (r <= -180.0) r += 360.0;
  if (r > 180.0) r -= 360.0;
  return r;
}

// Wraps an angle in radians into (-pi, pi].
inline double normalizeRad(double angleRad) {
  double r = std::fmod(angleRad, 2.0 * kPi);
  if (r <= -kPi) r += 2.0 * kPi;
  if (r > kPi) r -= 2.0 * kPi;
  return r;
}

// The representative of `angleRad` (mod 2 pi) closest to `referenceRad`: used to keep motion
// continuous (unwrapped) from one target to the next.
inline double unwrapNear(double angleRad, double referenceRad) {
  return referenceRad + normalizeRad(angleRad - referenceRad);
}

}  // namespace fivebar
