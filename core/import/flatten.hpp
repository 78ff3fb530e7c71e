// SPDX-License-Identifier: GPL-3.0-or-later
// Tolerance-bounded flattening of curves into polyline points (no Qt). Coordinates and the
// tolerance share one unit (mm in practice). Guarantee: every point of the true curve lies
// within toleranceMm of the emitted polyline.
#pragma once

#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar::svg {

// Appends the points after p0 of cubic Bezier (p0, c1, c2, p3), ending exactly at p3. Adaptive
// de Casteljau subdivision at t = 1/2 until the Hain/Willcocks flatness bound
//   max |B(t) - L(t)| <= 1/4 sqrt(max(ux^2, vx^2) + max(uy^2, vy^2)),
//   u = 3 c1 - 2 p0 - p3, v = 3 c2 - p0 - 2 p3,
// is within the tolerance (L = the chord parametrised linearly). Depth is capped at 30.
// maxPoints > 0: appends at most that many points and returns false when the curve needed more
// (a control point 1e13 mm away needs ~1e7 points: the caller's points budget stops it there,
// not after gigabytes). Returns true when the whole curve was appended.
bool flattenCubic(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3,
                  double toleranceMm, std::vector<Vec2>& out, std::size_t maxPoints = 0);

// Bound (same unit as the points) of the distance between a cubic and the elliptical arc it
// stands for, when it is one piece of our arc conversion (path_data.hpp appendArcAsCubics: any
// affine image of the standard cubic of a circular arc of sweep <= kArcPieceMaxRad); 0 for any
// other cubic, whose points are its geometry. Such a piece satisfies p3 - p0 = rho (c1 - p0 +
// p3 - c2), rho = 3 / (2 (1 - tan^2(sweep / 4))), which gives the sweep; the circle's radial error
// e(sweep) <= 1.82e-5 sweep^6 is then scaled by the largest radius of the ellipse over the piece,
// <= |w| / (2 k sin(sweep / 2)) + |p3 - p0| / 2 (w = c1 - p0 - (p3 - c2), k = 4/3 tan(sweep / 4)).
double arcPieceErrorBound(const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3);

// Points of the closed ellipse centre + u cos t + v sin t (u, v: conjugate semi-axes after any
// affine map), starting at t = 0, without repeating the first point. The step h satisfies
// h^2 / 8 * max|P''| <= tolerance (linear interpolation error bound), max|P''| = the largest
// singular value of [u v].
void flattenEllipse(const Vec2& centre, const Vec2& u, const Vec2& v, double toleranceMm,
                    std::vector<Vec2>& out);

}  // namespace fivebar::svg
