// SPDX-License-Identifier: GPL-3.0-or-later
#include "flatten.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fivebar::svg {
namespace {

constexpr int kMaxDepth = 30;       // 2^30 pieces: far beyond any sane curve
constexpr int kMaxEllipseSteps = 1 << 20;

struct Cubic {
  Vec2 p0, c1, c2, p3;
  int depth = 0;
};

// bound2Limit = 16 tolerance^2: the Hain/Willcocks bound squared, times 16.
bool flatEnough(const Cubic& c, double bound2Limit) {
  const Vec2 u = 3.0 * c.c1 - 2.0 * c.p0 - c.p3;
  const Vec2 v = 3.0 * c.c2 - c.p0 - 2.0 * c.p3;
  const double bound2 = std::max(u.x() * u.x(), v.x() * v.x()) +
                        std::max(u.y() * u.y(), v.y() * v.y());
  return bound2 <= bound2Limit;
}

}  // namespace

bool flattenCubic(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3,
                  double toleranceMm, std::vector<Vec2>& out, std::size_t maxPoints) {
  // Depth-first: keep splitting the current piece, its right half waiting on an explicit stack,
  // so that pieces come out in order.
  const double limit = 16.0 * toleranceMm * toleranceMm;
  Cubic stack[kMaxDepth + 2];
  int top = 0;
  Cubic c{p0, c1, c2, p3, 0};
  std::size_t appended = 0;
  for (;;) {
    if (c.depth >= kMaxDepth || flatEnough(c, limit)) {
      if (maxPoints > 0 && appended == maxPoints) return false;
      out.push_back(c.p3);
      ++appended;
      if (top == 0) return true;
      c = stack[--top];
      continue;
    }
    const Vec2 ab = 0.5 * (c.p0 + c.c1);
    const Vec2 bc = 0.5 * (c.c1 + c.c2);
    const Vec2 cd = 0.5 * (c.c2 + c.p3);
    const Vec2 abc = 0.5 * (ab + bc);
    const Vec2 bcd = 0.5 * (bc + cd);
    const Vec2 mid = 0.5 * (abc + bcd);
    stack[top++] = Cubic{mid, bcd, cd, c.p3, c.depth + 1};
    c = Cubic{c.p0, ab, abc, mid, c.depth + 1};
  }
}

double arcPieceErrorBound(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3) {
  constexpr double kMaxSweepRad = 0.19634954084936207 * (1.0 + 1e-6);  // kArcPieceMaxRad
  const Vec2 sum = (c1 - p0) + (p3 - c2);
  const Vec2 chord = p3 - p0;
  const double sum2 = sum.squaredNorm();
  if (!(sum2 > 0.0)) return 0.0;
  const double rho = chord.dot(sum) / sum2;
  if (!(rho > 1.5) || (chord - rho * sum).norm() > 1e-9 * (chord.norm() + std::sqrt(sum2)))
    return 0.0;
  const double sweep = 4.0 * std::atan(std::sqrt(1.0 - 1.5 / rho));
  if (sweep > kMaxSweepRad) return 0.0;  // not one of ours: the cubic is the geometry
  const double k = 4.0 / 3.0 * std::tan(sweep / 4.0);
  const double halfSin = std::sin(sweep / 2.0);
  if (!(k > 0.0) || !(halfSin > 0.0)) return 0.0;
  const Vec2 w = (c1 - p0) - (p3 - c2);
  const double radiusBound = w.norm() / (2.0 * k * halfSin) + 0.5 * chord.norm();
  return 1.82e-5 * std::pow(sweep, 6) * radiusBound;
}

void flattenEllipse(const Vec2& centre, const Vec2& u, const Vec2& v, double toleranceMm,
                    std::vector<Vec2>& out) {
  // Largest singular value of the 2x2 matrix [u v].
  const double a = u.squaredNorm() + v.squaredNorm();
  const double det = cross(u, v);
  const double sigmaMax = std::sqrt(0.5 * (a + std::sqrt(std::max(0.0, a * a - 4.0 * det * det))));
  const double twoPi = 2.0 * std::numbers::pi;
  int steps = 4;
  if (sigmaMax > 0.0) {
    const double h = std::sqrt(8.0 * toleranceMm / sigmaMax);
    steps = std::clamp(static_cast<int>(std::ceil(twoPi / h)), 4, kMaxEllipseSteps);
  }
  out.reserve(out.size() + static_cast<std::size_t>(steps));
  for (int i = 0; i < steps; ++i) {
    const double t = twoPi * i / steps;
    out.push_back(centre + u * std::cos(t) + v * std::sin(t));
  }
}

}  // namespace fivebar::svg
