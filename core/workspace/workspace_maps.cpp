// SPDX-License-Identifier: GPL-3.0-or-later
// Workspace maps: per-point evaluation and the multi-threaded grid fill. Derivation of the
// per-arm quantities: docs/kinematics.md (law of cosines at the motor and at the elbow).
// Each cell computes each arm's chord and elbow angle once and derives all four working modes
// from +-alpha, without trigonometry per mode except one atan2 for the transmission angle.
#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Below this |det A| / (b1 b2) the Cartesian Jacobian is treated as singular.
constexpr double kSingularSin = 1e-12;
// A target closer than this to a motor axis has no chord direction (as in inverseArm*).
constexpr double kAxisDistanceMm = 1e-12;

// Mode-independent data of one arm at one point.
struct ArmAtPoint {
  bool inAnnulus = false;
  double slackMm = 0.0;       // distance inside the annulus |a-b| <= d <= a+b (< 0 outside)
  double cosC = 1.0, sinC = 0.0;  // chord direction M->P
  double cosA = 1.0, sinA = 0.0;  // elbow angle alpha at the motor (law of cosines)
  double typeIMarginRad = 0.0;    // min(gamma, pi - gamma), gamma the interior angle at the elbow
};

ArmAtPoint solveArm(double a, double b, double dx, double dy) {
  ArmAtPoint arm;
  const double d = std::sqrt(dx * dx + dy * dy);
  arm.slackMm = std::min(a + b - d, d - std::abs(a - b));
  arm.inAnnulus = arm.slackMm >= -kReachToleranceMm && d >= kAxisDistanceMm;
  if (!arm.inAnnulus) return arm;
  arm.cosC = dx / d;
  arm.sinC = dy / d;
  arm.cosA = std::clamp((a * a + d * d - b * b) / (2.0 * a * d), -1.0, 1.0);
  arm.sinA = std::sqrt(std::max(0.0, 1.0 - arm.cosA * arm.cosA));
  const double cosG = std::clamp((a * a + b * b - d * d) / (2.0 * a * b), -1.0, 1.0);
  arm.typeIMarginRad = 0.5 * kPi - std::abs(std::asin(cosG));
  return arm;
}

// The excluded arc of one motor's joint limits, tested on (cos theta, sin theta) without
// trigonometry: theta (mod one turn) lies outside [lo, hi] iff its angular distance to the
// excluded arc's centre is below the arc's half width h, i.e. cos(theta - centre) > cos h.
struct LimitArc {
  bool limited = false;  // false when the limits span a full turn or more
  double cosCentre = 1.0, sinCentre = 0.0, cosHalf = -1.0, slackScale = 1.0;

  LimitArc(double lo, double hi) {
    const double excluded = 2.0 * kPi - (hi - lo);
    limited = excluded > 0.0;
    if (!limited) return;
    const double centre = hi + 0.5 * excluded, half = 0.5 * excluded;
    cosCentre = std::cos(centre);
    sinCentre = std::sin(centre);
    cosHalf = std::cos(half);
    // 1 / sin h turns the cosine difference into an angle, exact to first order at the limit.
    slackScale = 1.0 / std::max(std::sin(half), 0.1);
  }
  // > 0 inside the limits (approximately the angle to the nearest limit, rad), < 0 beyond.
  double slackRad(double cosTheta, double sinTheta) const {
    if (!limited) return std::numeric_limits<double>::infinity();
    return (cosHalf - (cosTheta * cosCentre + sinTheta * sinCentre)) * slackScale;
  }
};

struct Limits {
  LimitArc arc1, arc2;
  explicit Limits(const JointLimits& l)
      : arc1(l.theta1Min, l.theta1Max), arc2(l.theta2Min, l.theta2Max) {}
};

// Largest singular value of the 2x2 matrix [[m00, m01], [m10, m11]].
double sigmaMax(double m00, double m01, double m10, double m11) {
  const double s = m00 * m00 + m01 * m01 + m10 * m10 + m11 * m11;
  const double det = m00 * m11 - m01 * m10;
  return std::sqrt(0.5 * (s + std::sqrt(std::max(0.0, s * s - 4.0 * det * det))));
}

// The sample of a pose: motor angles (cos, sin) theta1, theta2 with distal joint P; `slackMm` the
// reach slack of the legs; `typeIMarginRad` the legs' smaller type I margin. With a pen offset the
// resolution and conditioning are the pen's: d(pen)/dq = J + (along I + normal Rot90) de/dq, with
// e = (P - R1) / b1 and de/dq = (J - [dR1/dtheta1, 0]) / b1 (pen_kinematics.hpp).
PointSample sampleAngles(const Geometry& g, const WorkspaceSettings& s, const Limits& limits,
                         const Vec2& p, double c1, double s1, double c2, double s2, double slackMm,
                         double typeIMarginRad) {
  PointSample out;
  // Joint limits, as an arc length at each elbow (mm).
  out.reachSlackMm = std::min({slackMm, g.a1 * limits.arc1.slackRad(c1, s1), g.a2 * limits.arc2.slackRad(c2, s2)});
  out.reachable = out.reachSlackMm >= -kReachToleranceMm;
  if (!out.reachable) return out;
  // Floating link vectors u_i = P - R_i (length b_i): the rows of A.
  const double u1x = p.x() + 0.5 * g.w - g.a1 * c1, u1y = p.y() - g.a1 * s1;
  const double u2x = p.x() - 0.5 * g.w - g.a2 * c2, u2y = p.y() - g.a2 * s2;
  const double detA = u1x * u2y - u1y * u2x;
  const double bb = g.b1 * g.b2;
  out.signedTypeII = detA / bb;
  out.muRad = std::atan2(std::abs(detA), u1x * u2x + u1y * u2y);
  out.typeIIMarginRad = std::min(out.muRad, kPi - out.muRad);
  out.typeIMarginRad = typeIMarginRad;
  if (std::abs(out.signedTypeII) < kSingularSin) {
    out.inverseCondition = 0.0;
    out.resolutionMm = kInf;
    return out;
  }
  // B = diag(a_i u_i . t_i), t_i = (-sin theta_i, cos theta_i); J = A^-1 B.
  const double B11 = g.a1 * (-u1x * s1 + u1y * c1), B22 = g.a2 * (-u2x * s2 + u2y * c2);
  double j00 = u2y * B11 / detA, j01 = -u1y * B22 / detA;
  double j10 = -u2x * B11 / detA, j11 = u1x * B22 / detA;
  if (s.penOffset) {
    const double al = s.penOffset->alongMm, no = s.penOffset->normalMm;
    const double e00 = (j00 + g.a1 * s1) / g.b1, e01 = j01 / g.b1;
    const double e10 = (j10 - g.a1 * c1) / g.b1, e11 = j11 / g.b1;
    j00 += al * e00 - no * e10;
    j01 += al * e01 - no * e11;
    j10 += al * e10 + no * e00;
    j11 += al * e11 + no * e01;
  }
  const double smax = sigmaMax(j00, j01, j10, j11);
  const double smin = smax > 0.0 ? std::abs(j00 * j11 - j01 * j10) / smax : 0.0;
  out.inverseCondition = smax > 0.0 ? smin / smax : 0.0;
  out.resolutionMm = sigmaMax(j00 * s.stepRad1, j01 * s.stepRad2, j10 * s.stepRad1, j11 * s.stepRad2);
  return out;
}

// One working mode at p: sigma1 = +1 when theta1 = chord1 + alpha1 (arm 1 '+'), sigma2 = +1 when
// theta2 = chord2 + alpha2 (arm 2 '-'), as in inverseArm1/2.
PointSample sampleMode(const Geometry& g, const WorkspaceSettings& s, const Limits& limits,
                       const Vec2& p, const ArmAtPoint& arm1, const ArmAtPoint& arm2,
                       double sigma1, double sigma2) {
  if (!arm1.inAnnulus || !arm2.inAnnulus) {
    PointSample out;
    out.reachSlackMm = std::min(arm1.slackMm, arm2.slackMm);
    return out;
  }
  // Motor angle cos/sin from the chord and elbow angles: theta = chord + sigma * alpha.
  const double c1 = arm1.cosC * arm1.cosA - sigma1 * arm1.sinC * arm1.sinA;
  const double s1 = arm1.sinC * arm1.cosA + sigma1 * arm1.cosC * arm1.sinA;
  const double c2 = arm2.cosC * arm2.cosA - sigma2 * arm2.sinC * arm2.sinA;
  const double s2 = arm2.sinC * arm2.cosA + sigma2 * arm2.cosC * arm2.sinA;
  return sampleAngles(g, s, limits, p, c1, s1, c2, s2, std::min(arm1.slackMm, arm2.slackMm),
                      std::min(arm1.typeIMarginRad, arm2.typeIMarginRad));
}

// The pen of a calibrated pen offset at `pen` in `mode`: the pose penInverse gives (leg 1 reaching
// the pen as the chain a1, c1; P on link b1; leg 2 reaching P), sampled as above. The reach slack
// is leg 1's chain to the pen and leg 2's to P; out of reach, the chain's or leg 2's (at the P of
// the chain's elbow in the mode) slack, whichever fails.
PointSample samplePen(const Geometry& g, const WorkspaceSettings& s, const Limits& limits,
                      const Vec2& pen, WorkingMode mode) {
  const PenOffset& o = *s.penOffset;
  const double c1Len = std::hypot(g.b1 + o.alongMm, o.normalMm);
  const ArmAtPoint chain = solveArm(g.a1, c1Len, pen.x() + 0.5 * g.w, pen.y());
  Vec2 P = pen;
  const IkResult ik = penInverse(g, s.penOffset, pen, mode, &P);
  if (!ik.ok()) {
    PointSample out;
    out.reachSlackMm = chain.slackMm;
    if (chain.inAnnulus) {
      // Leg 2 misses P: P of the chain's elbow with the mode's arm-1 sign.
      Geometry chainGeometry = g;
      chainGeometry.b1 = c1Len;
      if (const auto t1 = inverseArm1(chainGeometry, pen, arm1Sign(mode))) {
        const Vec2 R1 = elbow1(g, *t1);
        const double psi = std::atan2(o.normalMm, g.b1 + o.alongMm);
        const Vec2 d = (pen - R1) / c1Len;
        const Vec2 e(std::cos(psi) * d.x() + std::sin(psi) * d.y(), -std::sin(psi) * d.x() + std::cos(psi) * d.y());
        const Vec2 Pm = R1 + g.b1 * e;
        out.reachSlackMm = std::min(out.reachSlackMm, solveArm(g.a2, g.b2, Pm.x() - 0.5 * g.w, Pm.y()).slackMm);
      }
      // Reach slack within the tolerance but no pose: just outside.
      out.reachSlackMm = std::min(out.reachSlackMm, -2.0 * kReachToleranceMm);
    }
    return out;
  }
  const ArmAtPoint arm1 = solveArm(g.a1, g.b1, P.x() + 0.5 * g.w, P.y());
  const ArmAtPoint arm2 = solveArm(g.a2, g.b2, P.x() - 0.5 * g.w, P.y());
  return sampleAngles(g, s, limits, P, std::cos(ik.angles.theta1), std::sin(ik.angles.theta1),
                      std::cos(ik.angles.theta2), std::sin(ik.angles.theta2),
                      std::min(chain.slackMm, arm2.slackMm),
                      std::min(arm1.typeIMarginRad, arm2.typeIMarginRad));
}

double sigma1Of(WorkingMode m) { return arm1Sign(m) == ArmSign::Plus ? 1.0 : -1.0; }
double sigma2Of(WorkingMode m) { return arm2Sign(m) == ArmSign::Plus ? -1.0 : 1.0; }

void allocate(WorkspaceMap& map, const GridSpec& grid, WorkingMode mode, const WorkspaceSettings& s) {
  map.grid = grid;
  map.mode = mode;
  map.typeIIMarginRad = s.typeIIMarginRad;
  map.typeIMarginRad = s.typeIMarginRad;
  const std::size_t n = grid.size();
  map.reachable.resize(n);
  for (auto* v : {&map.reachSlackMm, &map.typeIIMarginRadMap, &map.typeIMarginRadMap, &map.muRad,
                  &map.signedTypeII, &map.inverseCondition, &map.resolutionMm})
    v->resize(n);
}

void store(WorkspaceMap& map, std::size_t i, const PointSample& p) {
  map.reachable[i] = p.reachable ? 1 : 0;
  map.reachSlackMm[i] = static_cast<float>(p.reachSlackMm);
  const auto f = [&](double v) { return static_cast<float>(p.reachable ? v : kNaN); };
  map.typeIIMarginRadMap[i] = f(p.typeIIMarginRad);
  map.typeIMarginRadMap[i] = f(p.typeIMarginRad);
  map.muRad[i] = f(p.muRad);
  map.signedTypeII[i] = f(p.signedTypeII);
  map.inverseCondition[i] = f(p.inverseCondition);
  map.resolutionMm[i] = f(p.resolutionMm);
}

// Fills rows [rowBegin, rowEnd) of each map in `maps` (count maps, each its own mode).
void fillRows(const Geometry& g, const WorkspaceSettings& s, WorkspaceMap* maps, int count,
              int rowBegin, int rowEnd) {
  const GridSpec& grid = maps[0].grid;
  const Limits limits(s.limits);
  double sigma1[4], sigma2[4];
  for (int m = 0; m < count; ++m) {
    sigma1[m] = sigma1Of(maps[m].mode);
    sigma2[m] = sigma2Of(maps[m].mode);
  }
  for (int iy = rowBegin; iy < rowEnd; ++iy) {
    const double y = grid.yCenter(iy);
    for (int ix = 0; ix < grid.nx; ++ix) {
      const Vec2 p(grid.xCenter(ix), y);
      const std::size_t i = grid.index(ix, iy);
      if (s.penOffset) {
        for (int m = 0; m < count; ++m) store(maps[m], i, samplePen(g, s, limits, p, maps[m].mode));
        continue;
      }
      const ArmAtPoint arm1 = solveArm(g.a1, g.b1, p.x() + 0.5 * g.w, y);
      const ArmAtPoint arm2 = solveArm(g.a2, g.b2, p.x() - 0.5 * g.w, y);
      for (int m = 0; m < count; ++m)
        store(maps[m], i, sampleMode(g, s, limits, p, arm1, arm2, sigma1[m], sigma2[m]));
    }
  }
}

void fillParallel(const Geometry& g, const WorkspaceSettings& s, WorkspaceMap* maps, int count,
                  int threads) {
  const int ny = maps[0].grid.ny;
  threads = std::clamp(threads, 1, std::max(1, ny));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back(fillRows, std::cref(g), std::cref(s), maps, count, ny * t / threads,
                         ny * (t + 1) / threads);
  fillRows(g, s, maps, count, 0, ny / threads);
  for (std::thread& w : workers) w.join();
}

}  // namespace

WorkspaceSettings workspaceSettings(const MachineProfile& p) {
  WorkspaceSettings s;
  s.limits = p.limits;
  s.typeIIMarginRad = p.typeIIMarginRad;
  s.typeIMarginRad = p.typeIMarginRad;
  s.stepRad1 = radFromDeg(1.0 / p.motors.stepsPerDeg1);
  s.stepRad2 = radFromDeg(1.0 / p.motors.stepsPerDeg2);
  s.penOffset = calibratedPenOffset(p);
  return s;
}

PointSample evaluatePoint(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                          const Vec2& p) {
  if (s.penOffset) return samplePen(g, s, Limits(s.limits), p, mode);
  const ArmAtPoint arm1 = solveArm(g.a1, g.b1, p.x() + 0.5 * g.w, p.y());
  const ArmAtPoint arm2 = solveArm(g.a2, g.b2, p.x() - 0.5 * g.w, p.y());
  return sampleMode(g, s, Limits(s.limits), p, arm1, arm2, sigma1Of(mode), sigma2Of(mode));
}

WorkspaceMap computeMap(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode,
                        const GridSpec& grid, int threads) {
  WorkspaceMap map;
  allocate(map, grid, mode, s);
  if (grid.size() > 0) fillParallel(g, s, &map, 1, threads);
  return map;
}

std::array<WorkspaceMap, 4> computeAllModes(const Geometry& g, const WorkspaceSettings& s,
                                            const GridSpec& grid, int threads) {
  std::array<WorkspaceMap, 4> maps;
  computeAllModes(g, s, grid, maps, threads);
  return maps;
}

void computeAllModes(const Geometry& g, const WorkspaceSettings& s, const GridSpec& grid,
                     std::array<WorkspaceMap, 4>& maps, int threads) {
  for (std::size_t m = 0; m < 4; ++m) allocate(maps[m], grid, kAllWorkingModes[m], s);
  if (grid.size() > 0) fillParallel(g, s, maps.data(), 4, threads);
}

double WorkspaceMap::safeSlack(std::size_t i, double lengthScaleMm) const {
  double slack = reachSlackMm[i];
  if (!reachable[i]) return slack;
  slack = std::min(slack, lengthScaleMm * (typeIIMarginRadMap[i] - typeIIMarginRad));
  slack = std::min(slack, lengthScaleMm * (typeIMarginRadMap[i] - typeIMarginRad));
  return slack;
}

}  // namespace fivebar
