// SPDX-License-Identifier: GPL-3.0-or-later
// The pen's kinematics: contract in pen_kinematics.hpp, derivation in docs/calibration.md.
#include "core/machine/pen_kinematics.hpp"

#include <cmath>

namespace fivebar {
namespace {

// Shortest distal link c1 (mm) a pen offset may leave from R1 to the pen: below it the pen sits
// on the elbow and leg 1 cannot aim it.
constexpr double kMinPenLinkMm = 1e-9;
// Recursion depth of distalPath's splitting (2^20 pieces per segment at most).
constexpr int kMaxSplitDepth = 20;

// Leg 1 as the chain M1 -> R1 -> pen: length c1 from R1 to the pen, and the angle psi from the
// link direction e (R1 -> P) to the direction R1 -> pen.
struct PenLink {
  double c1 = 0.0;
  double psi = 0.0;
};
PenLink penLink(const Geometry& g, const PenOffset& o) {
  return {std::hypot(g.b1 + o.alongMm, o.normalMm), std::atan2(o.normalMm, g.b1 + o.alongMm)};
}

Vec2 rotated(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// theta1 and P for one elbow sign of the chain M1 -> R1 -> pen; nullopt out of reach.
std::optional<std::pair<double, Vec2>> leg1Candidate(const Geometry& g, const PenLink& l, const Vec2& pen,
                                                     ArmSign sign) {
  Geometry chain = g;
  chain.b1 = l.c1;
  const auto t1 = inverseArm1(chain, pen, sign);
  if (!t1) return std::nullopt;
  const Vec2 R1 = elbow1(g, *t1);
  const Vec2 e = rotated((pen - R1) / l.c1, -l.psi);
  return std::make_pair(*t1, Vec2(R1 + g.b1 * e));
}

bool arm1IsPlus(const Geometry& g, double theta1, const Vec2& P) {
  return cross(P - g.motor1(), elbow1(g, theta1) - g.motor1()) >= 0.0;
}

// Leg 1's angle and P for the pen in working mode `mode`: of the chain's two elbow solutions,
// the one whose arm-1 sign about P is the mode's (the chain's own sign when both or neither are).
std::optional<std::pair<double, Vec2>> solveLeg1(const Geometry& g, const PenOffset& o, const Vec2& pen,
                                                 WorkingMode mode) {
  const PenLink l = penLink(g, o);
  if (l.c1 < kMinPenLinkMm) return std::nullopt;
  const ArmSign want = arm1Sign(mode);
  const ArmSign other = want == ArmSign::Plus ? ArmSign::Minus : ArmSign::Plus;
  const auto same = leg1Candidate(g, l, pen, want), flip = leg1Candidate(g, l, pen, other);
  const auto matches = [&](const std::optional<std::pair<double, Vec2>>& c) {
    return c && arm1IsPlus(g, c->first, c->second) == (want == ArmSign::Plus);
  };
  if (matches(flip) && !matches(same)) return flip;
  return same;
}

void splitInto(const Geometry& g, const PenOffset& o, WorkingMode mode, const Vec2& a, const Vec2& pa,
               const Vec2& b, const Vec2& pb, int depth, std::vector<Vec2>& out, bool& failed, Vec2& failedAt) {
  if (failed) return;
  const Vec2 m = 0.5 * (a + b);
  if (depth < kMaxSplitDepth && (b - a).norm() > kDistalMinPieceMm) {
    const auto leg = solveLeg1(g, o, m, mode);
    if (!leg || !inverseArm2(g, leg->second, arm2Sign(mode))) {
      failed = true;
      failedAt = m;
      return;
    }
    const Vec2 pm = leg->second;
    if ((pm - 0.5 * (pa + pb)).norm() > kDistalChordToleranceMm) {
      splitInto(g, o, mode, a, pa, m, pm, depth + 1, out, failed, failedAt);
      splitInto(g, o, mode, m, pm, b, pb, depth + 1, out, failed, failedAt);
      return;
    }
  }
  out.push_back(pb);
}

}  // namespace

Vec2 penFromDistal(const std::optional<PenOffset>& pen, const Geometry& g, const Vec2& R1, const Vec2& P) {
  if (!pen) return P;
  const Vec2 e = (P - R1) / g.b1;
  const Vec2 n(-e.y(), e.x());
  return P + pen->alongMm * e + pen->normalMm * n;
}

FkResult penForward(const Geometry& g, const std::optional<PenOffset>& pen, const JointAngles& q,
                    AssemblyMode assembly) {
  FkResult fk = forward(g, q, assembly);
  if (fk.ok() && pen) fk.p = penFromDistal(pen, g, elbow1(g, q.theta1), fk.p);
  return fk;
}

IkResult penInverse(const Geometry& g, const std::optional<PenOffset>& pen, const Vec2& penXY,
                    WorkingMode mode, Vec2* distal) {
  if (!pen) {
    if (distal) *distal = penXY;
    return inverse(g, penXY, mode);
  }
  const auto leg1 = solveLeg1(g, *pen, penXY, mode);
  if (!leg1) return {};
  const auto t2 = inverseArm2(g, leg1->second, arm2Sign(mode));
  if (!t2) return {};
  if (distal) *distal = leg1->second;
  return {IkStatus::Ok, {leg1->first, *t2}};
}

int unreachableLeg(const Geometry& g, const std::optional<PenOffset>& pen, const Vec2& penXY, WorkingMode mode) {
  if (!pen) {
    if (!inverseArm1(g, penXY, arm1Sign(mode))) return 1;
    return inverseArm2(g, penXY, arm2Sign(mode)) ? 0 : 2;
  }
  const auto leg1 = solveLeg1(g, *pen, penXY, mode);
  if (!leg1) return 1;
  return inverseArm2(g, leg1->second, arm2Sign(mode)) ? 0 : 2;
}

std::optional<std::vector<Vec2>> distalPath(const Geometry& g, const PenOffset& pen, WorkingMode mode,
                                            std::span<const Vec2> penStroke, Vec2* failedAt) {
  std::vector<Vec2> out;
  out.reserve(penStroke.size());
  bool failed = false;
  Vec2 where = Vec2::Zero();
  Vec2 prevPen = Vec2::Zero(), prevP = Vec2::Zero();
  for (std::size_t k = 0; k < penStroke.size(); ++k) {
    const Vec2& x = penStroke[k];
    const auto leg = solveLeg1(g, pen, x, mode);
    if (!leg || !inverseArm2(g, leg->second, arm2Sign(mode))) {
      if (failedAt) *failedAt = x;
      return std::nullopt;
    }
    if (k == 0) out.push_back(leg->second);
    else splitInto(g, pen, mode, prevPen, prevP, x, leg->second, 0, out, failed, where);
    if (failed) {
      if (failedAt) *failedAt = where;
      return std::nullopt;
    }
    prevPen = x;
    prevP = leg->second;
  }
  return out;
}

double penDeviationFactor(const Geometry& g, const std::optional<PenOffset>& pen) {
  if (!pen) return 1.0;
  return 1.0 + std::hypot(pen->alongMm, pen->normalMm) / (g.b1 * kPenLeverSinMu1);
}

}  // namespace fivebar
