// SPDX-License-Identifier: GPL-3.0-or-later
// Design evaluation over a placed rectangle (docs/design.md "Measures").
#include "core/design/evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"

namespace fivebar::design {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance from point p to segment [a, b].
double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Distance between segments [a, b] and [c, d] (0 when they cross).
double segmentDistance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return 0.0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                   pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
}

// Singular values (largest first) of a 2x2 matrix, closed form.
std::pair<double, double> singularValues(double m00, double m01, double m10, double m11) {
  const double s = m00 * m00 + m01 * m01 + m10 * m10 + m11 * m11;
  const double det = std::abs(m00 * m11 - m01 * m10);
  const double root = std::sqrt(std::max(0.0, s * s - 4.0 * det * det));
  const double smax = std::sqrt(0.5 * (s + root));
  return {smax, smax > 0.0 ? det / smax : 0.0};
}

void include(Rect& box, const Vec2& p) {
  box.xMin = std::min(box.xMin, p.x());
  box.xMax = std::max(box.xMax, p.x());
  box.yMin = std::min(box.yMin, p.y());
  box.yMax = std::max(box.yMax, p.y());
}

}  // namespace

double conditionNumber(double m00, double m01, double m10, double m11) {
  const auto [smax, smin] = singularValues(m00, m01, m10, m11);
  return smin > 0.0 ? smax / smin : kInf;
}

double Violations::total(double scaleMm) const {
  return reachMm + clearanceMm + workSideMm + lengthsMm + scaleMm * (typeIRad + typeIIRad);
}

std::string Violations::binding(double scaleMm) const {
  const std::pair<double, const char*> parts[] = {
      {lengthsMm, "lengths"},          {clearanceMm, "clearance"},
      {workSideMm, "workSide"},        {reachMm, "reach"},
      {scaleMm * typeIIRad, "typeII"}, {scaleMm * typeIRad, "typeI"}};
  double worst = 0.0;
  std::string name;
  for (const auto& [v, n] : parts)
    if (v > worst) {
      worst = v;
      name = n;
    }
  return name;
}

std::vector<Vec2> rectangleSamples(const Rect& r, double spacingMm) {
  const double spacing = std::max(spacingMm, 1e-3);
  const int nx = std::max(1, static_cast<int>(std::ceil(r.width() / spacing - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(r.height() / spacing - 1e-9)));
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      out.emplace_back(r.xMin + r.width() * i / nx, r.yMin + r.height() * j / ny);
  return out;
}

Evaluation evaluateDesign(const Geometry& g, WorkingMode mode, const Rect& r,
                          const DesignRules& rules, const Sampling& sampling) {
  Evaluation e;
  DesignMeasures& m = e.measures;
  Violations& v = e.violations;
  const WorkspaceSettings& s = rules.workspace;
  v.lengthsMm = std::max({0.0, -g.a1, -g.a2, -g.b1, -g.b2, -g.w});
  for (double len : {g.a1, g.a2, g.b1, g.b2})
    if (!(len > 0.0)) v.lengthsMm = std::max(v.lengthsMm, 1.0);
  m.drivingLinkSpacingMm = g.w - g.a1 - g.a2;
  v.clearanceMm = std::max(0.0, rules.clearanceMm - m.drivingLinkSpacingMm);
  m.armsCanCollide = m.drivingLinkSpacingMm < rules.clearanceMm;
  v.workSideMm = std::max(0.0, rules.minRectangleYMm - r.yMin);
  if (v.lengthsMm > 0.0) return e;

  m.rectangleAreaMm2 = r.area();
  m.stepRad = std::max(s.stepRad1, s.stepRad2);
  m.minReachSlackMm = m.minTypeIMarginRad = m.minTypeIIMarginRad = kInf;
  m.minDrivingLinkDistanceMm = kInf;
  m.footprint = {r.xMin, r.yMin, r.xMax, r.yMax};
  include(m.footprint, g.motor1());
  include(m.footprint, g.motor2());
  double conditionSum = 0.0;
  int reachable = 0;
  for (const Vec2& p : rectangleSamples(r, sampling.spacingMm)) {
    ++m.samples;
    const PointSample ps = evaluatePoint(g, s, mode, p);
    m.minReachSlackMm = std::min(m.minReachSlackMm, ps.reachSlackMm);
    if (!ps.reachable) {
      ++m.unreachableSamples;
      v.reachMm = std::max(v.reachMm, std::max(-ps.reachSlackMm, 1e-6));
      continue;
    }
    ++reachable;
    m.minTypeIMarginRad = std::min(m.minTypeIMarginRad, ps.typeIMarginRad);
    m.minTypeIIMarginRad = std::min(m.minTypeIIMarginRad, ps.typeIIMarginRad);
    const double kappa = ps.inverseCondition > 0.0 ? 1.0 / ps.inverseCondition : kInf;
    m.worstCondition = std::max(m.worstCondition, kappa);
    conditionSum += kappa;
    m.worstMmPerStep = std::max(m.worstMmPerStep, ps.resolutionMm);
    const IkResult ik = inverse(g, p, mode);
    if (!ik.ok()) continue;  // within rounding of the reach boundary
    const Pose pose = makePose(g, ik.angles, p);
    include(m.footprint, pose.R1);
    include(m.footprint, pose.R2);
    m.minDrivingLinkDistanceMm =
        std::min(m.minDrivingLinkDistanceMm, segmentDistance(g.motor1(), pose.R1, g.motor2(), pose.R2));
    if (const auto J = cartesianJacobian(g, pose)) {
      const double sigmaMin = singularValues((*J)(0, 0), (*J)(0, 1), (*J)(1, 0), (*J)(1, 1)).second;
      m.worstMotorSpeedRadPerS = std::max(
          m.worstMotorSpeedRadPerS, sigmaMin > 0.0 ? rules.penSpeedMmPerS / sigmaMin : kInf);
    } else {
      m.worstMotorSpeedRadPerS = kInf;
    }
  }
  m.meanCondition = reachable > 0 ? conditionSum / reachable : kInf;
  if (m.unreachableSamples > 0) m.worstCondition = kInf;
  if (reachable > 0) {
    v.typeIRad = std::max(0.0, s.typeIMarginRad - m.minTypeIMarginRad);
    v.typeIIRad = std::max(0.0, s.typeIIMarginRad - m.minTypeIIMarginRad);
  } else {
    m.minTypeIMarginRad = m.minTypeIIMarginRad = 0.0;
  }
  m.footprintMm2 = m.footprint.area();
  return e;
}

}  // namespace fivebar::design
