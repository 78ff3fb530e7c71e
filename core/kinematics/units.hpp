// Unit conversions. Radians inside the core; degrees only at the edges (CLI, UI, G-code,
// profiles). This is the one tested place where the two meet.
#pragma once

#include <cmath>
#include <numbers>

namespace fivebar {

constexpr double kPi = std::numbers::pi;

constexpr double radFromDeg(double angleDeg) { return angleDeg * (kPi / 180.0); }
constexpr double degFromRad(double angleRad) { return angleRad * (180.0 / kPi); }

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
