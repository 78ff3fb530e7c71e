// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/kinematics/geometry.hpp"

#include <cmath>

namespace fivebar {
namespace {

void checkLength(std::vector<ValidationIssue>& out, const char* field, double v, bool allowZero) {
  if (!std::isfinite(v)) {
    out.push_back({field, FB_TR("Profile", "%1 must be a finite number of millimetres").arg(field)});
  } else if (v < 0.0 || (!allowZero && v == 0.0)) {
    out.push_back({field, (allowZero ? FB_TR("Profile", "%1 is %2 mm; it must be zero or positive")
                                     : FB_TR("Profile", "%1 is %2 mm; it must be positive"))
                              .arg(field)
                              .argSignificant(v, 6)});
  }
}

}  // namespace

std::vector<ValidationIssue> validate(const Geometry& g) {
  std::vector<ValidationIssue> out;
  checkLength(out, "a1", g.a1, false);
  checkLength(out, "b1", g.b1, false);
  checkLength(out, "a2", g.a2, false);
  checkLength(out, "b2", g.b2, false);
  checkLength(out, "w", g.w, true);
  if (!out.empty()) return out;
  // The loop closes for some pose iff the annuli of the two legs (radii |ai-bi|..ai+bi around
  // each motor) intersect: the outer reach must span the base, and neither annulus' hole may
  // swallow the other's disc.
  const double r1 = g.a1 + g.b1, r2 = g.a2 + g.b2;
  const double h1 = std::abs(g.a1 - g.b1), h2 = std::abs(g.a2 - g.b2);
  if (r1 + r2 < g.w) {
    out.push_back({"w", FB_TR("Profile", "the legs can never meet: a1+b1 + a2+b2 = %1 mm is less than w = %2 mm")
                            .argSignificant(r1 + r2, 6)
                            .argSignificant(g.w, 6)});
  } else if (h1 > g.w + r2 || h2 > g.w + r1) {
    out.push_back({h1 > h2 ? "b1" : "b2",
                   FB_TR("Profile", "the legs can never meet: one leg's dead zone |a-b| encloses "
                                    "the other leg's whole reach")});
  }
  return out;
}

std::vector<ValidationIssue> validate(const Geometry& g, const JointLimits& l) {
  std::vector<ValidationIssue> out = validate(g);
  auto checkPair = [&](const char* field, double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      out.push_back({field, FB_TR("Profile", "%1 limits must be finite numbers of degrees").arg(field)});
    } else if (!(lo < hi)) {
      out.push_back({field, FB_TR("Profile", "%1 minimum %2 deg is not below its maximum %3 deg, so no "
                                             "pose is allowed")
                                .arg(field)
                                .argSignificant(degFromRad(lo), 6)
                                .argSignificant(degFromRad(hi), 6)});
    }
  };
  checkPair("limits.theta1", l.theta1Min, l.theta1Max);
  checkPair("limits.theta2", l.theta2Min, l.theta2Max);
  if (!out.empty()) return out;
  // Is there a closable pose inside the limits? Sample the limit box (at most one turn each).
  const int n = 181;
  const double span1 = std::min(l.theta1Max - l.theta1Min, 2.0 * kPi);
  const double span2 = std::min(l.theta2Max - l.theta2Min, 2.0 * kPi);
  for (int i = 0; i < n; ++i) {
    const double t1 = l.theta1Min + span1 * i / (n - 1);
    const Vec2 R1 = g.motor1() + g.a1 * Vec2(std::cos(t1), std::sin(t1));
    for (int j = 0; j < n; ++j) {
      const double t2 = l.theta2Min + span2 * j / (n - 1);
      const Vec2 R2 = g.motor2() + g.a2 * Vec2(std::cos(t2), std::sin(t2));
      const double d = (R2 - R1).norm();
      if (d <= g.b1 + g.b2 && d >= std::abs(g.b1 - g.b2)) return out;
    }
  }
  out.push_back({"limits", FB_TR("Profile", "the joint limits exclude every pose in which the linkage closes")});
  return out;
}

}  // namespace fivebar
