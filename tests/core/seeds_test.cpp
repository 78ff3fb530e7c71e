// SPDX-License-Identifier: GPL-3.0-or-later
// The core kinematics (core/kinematics.hpp) against independent re-implementations, inside this
// file, of every formulation in the seed papers (/work/shared/seeds/), each mapped explicitly
// onto conventions.md. The core must agree with each in all four working modes and both
// assembly modes, for asymmetric links and off-centre targets, on seeded random points; and the
// papers' facts about their own machines must hold when checked with the core.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

// The seed machines (conventions.md presets) and asymmetric variants.
const Geometry kHoang{70.0, 200.0, 70.0, 200.0, 250.0};
const Geometry kDai{135.0, 135.0, 135.0, 135.0, 180.0};
const Geometry kArticle{40.0, 60.0, 40.0, 60.0, 30.0};
const Geometry kAsymmetric{55.0, 130.0, 70.0, 110.0, 42.0};
const Geometry kAsymmetricWide{90.0, 160.0, 60.0, 190.0, 120.0};
const Geometry kGeneral[] = {kHoang, kArticle, kAsymmetric, kAsymmetricWide, kDai};

constexpr double kAngleTolRad = 1e-9;
constexpr double kPositionTolMm = 1e-9;
// Paper formulas use acos, which loses digits at the reach boundary; samples stay this far
// inside every reach circle.
constexpr double kReachMarginMm = 0.01;

double angleDiff(double a, double b) { return std::remainder(a - b, 2.0 * kPi); }

bool strictlyReachable(const Geometry& g, const Vec2& p) {
  const double d1 = (p - g.motor1()).norm(), d2 = (p - g.motor2()).norm();
  return d1 < g.a1 + g.b1 - kReachMarginMm && d1 > std::abs(g.a1 - g.b1) + kReachMarginMm &&
         d2 < g.a2 + g.b2 - kReachMarginMm && d2 > std::abs(g.a2 - g.b2) + kReachMarginMm;
}

// A random point reachable by both legs, anywhere in the workspace (off-centre included);
// upperHalf restricts it to y > 0 for formulations that assume it.
Vec2 randomReachable(const Geometry& g, std::mt19937_64& rng, bool upperHalf = false) {
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + 0.5 * g.w;
  std::uniform_real_distribution<double> ux(-reach, reach), uy(upperHalf ? 0.0 : -reach, reach);
  for (;;) {
    const Vec2 p(ux(rng), uy(rng));
    if (strictlyReachable(g, p)) return p;
  }
}

double sign(ArmSign s) { return s == ArmSign::Plus ? 1.0 : -1.0; }

// ---------------------------------------------------------------------------------------------
// Gamble 2020 thesis, section 2.2 (law of cosines) and Table 1; section 2.1 (circle intersection).
// Frame: M1 at the origin, M2 at (w, 0): xG = x + w/2, same y. Angles: theta_i = angle M_j M_i R_i,
// "measured away from the other motor": theta1G from +x counter-clockwise (= our theta1), theta2G
// from -x clockwise, so our theta2 = pi - theta2G. alpha_i (eq. 17) is unsigned: the formulation
// covers y >= 0, the work-area side, and is sampled there. Table 1: '+' is alpha_i + beta_i, which
// is elbow-out, i.e. conventions.md '+' for both arms.
// ---------------------------------------------------------------------------------------------
struct GambleIk {
  double theta1G, theta2G;
};
GambleIk gambleInverse(const Geometry& g, const Vec2& p, ArmSign s1, ArmSign s2) {
  const double xG = p.x() + 0.5 * g.w, y = p.y();
  const double c1 = std::sqrt(xG * xG + y * y);                  // eq. 19
  const double c2 = std::sqrt((xG - g.w) * (xG - g.w) + y * y);  // eq. 20
  // eq. 17 (law of cosines in triangle M1 M2 P); eqs. 21-22 are its simplification, also valid
  // for coaxial motors (w = 0).
  const double alpha1 = g.w > 0.0 ? std::acos((c2 * c2 - c1 * c1 - g.w * g.w) / (-2.0 * c1 * g.w))
                                  : std::acos(xG / c1);
  const double alpha2 = g.w > 0.0 ? std::acos((c1 * c1 - c2 * c2 - g.w * g.w) / (-2.0 * c2 * g.w))
                                  : std::acos((g.w - xG) / c2);
  const double beta1 = std::acos((g.b1 * g.b1 - g.a1 * g.a1 - c1 * c1) / (-2.0 * g.a1 * c1));  // 18
  const double beta2 = std::acos((g.b2 * g.b2 - g.a2 * g.a2 - c2 * c2) / (-2.0 * g.a2 * c2));
  return {alpha1 + sign(s1) * beta1, alpha2 + sign(s2) * beta2};  // Table 1
}

// Eqs. 1-15 with the printed typos fixed: eq. 6 uses x_R2, and v5 = v2^2 - 2 v2 x_R1 + a1^2 - b1^2
// (printed "a1^2 b1^2"). positiveRadical picks +sqrt in eq. 12, the larger y_P.
std::optional<Vec2> gambleForward(const Geometry& g, double theta1, double theta2,
                                  bool positiveRadical) {
  const double theta2G = kPi - theta2;  // Gamble measures motor 2 from -x, clockwise
  const double xR1 = g.a1 * std::cos(theta1), yR1 = g.a1 * std::sin(theta1);          // 1, 2
  const double xR2 = g.w - g.a2 * std::cos(theta2G), yR2 = g.a2 * std::sin(theta2G);  // 3, 4
  const double v1 = (yR1 - yR2) / (xR2 - xR1);                                        // 10
  const double v2 = (g.b1 * g.b1 - g.b2 * g.b2 - g.a1 * g.a1 + xR2 * xR2 + yR2 * yR2) /
                    (2.0 * (xR2 - xR1));                                   // 11
  const double v3 = 1.0 + v1 * v1;                                         // 13
  const double v4 = 2.0 * (v1 * v2 - v1 * xR1 - yR1);                      // 14
  const double v5 = g.a1 * g.a1 - g.b1 * g.b1 - 2.0 * v2 * xR1 + v2 * v2;  // 15
  const double disc = v4 * v4 - 4.0 * v3 * v5;
  if (disc < 0.0) return std::nullopt;
  const double yP = (-v4 + (positiveRadical ? 1.0 : -1.0) * std::sqrt(disc)) / (2.0 * v3);  // 12
  const double xP = v1 * yP + v2;                                                           // 9
  return Vec2(xP - 0.5 * g.w, yP);  // back to the machine frame
}

TEST(SeedGamble, LawOfCosinesTable1MatchesCoreInEveryMode) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng, /*upperHalf=*/true);
      for (WorkingMode m : kAllWorkingModes) {
        const IkResult core = inverse(g, p, m);
        ASSERT_TRUE(core.ok());
        const GambleIk gamble = gambleInverse(g, p, arm1Sign(m), arm2Sign(m));
        EXPECT_NEAR(angleDiff(core.angles.theta1, gamble.theta1G), 0.0, kAngleTolRad)
            << "mode " << toString(m) << " at " << p.transpose();
        EXPECT_NEAR(angleDiff(core.angles.theta2, kPi - gamble.theta2G), 0.0, kAngleTolRad)
            << "mode " << toString(m) << " at " << p.transpose();
      }
    }
  }
}

TEST(SeedGamble, TransmissionAngleEq23IsPiMinusCoreMu) {
  // Gamble's mu_i = angle M_i R_i P (pi at full stretch); the core's mu_i is measured between
  // M_i->R_i continued and R_i->P (0 at full stretch), so core mu_i = pi - Gamble mu_i.
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 300; ++i) {
      const Vec2 p = randomReachable(g, rng);
      const double c1 = (p - g.motor1()).norm(), c2 = (p - g.motor2()).norm();
      const double mu1G = std::acos((c1 * c1 - g.a1 * g.a1 - g.b1 * g.b1) / (-2.0 * g.a1 * g.b1));
      const double mu2G = std::acos((c2 * c2 - g.a2 * g.a2 - g.b2 * g.b2) / (-2.0 * g.a2 * g.b2));
      for (WorkingMode m : kAllWorkingModes) {
        const TransmissionAngles t = transmissionAngles(g, makePose(g, inverse(g, p, m).angles, p));
        EXPECT_NEAR(t.mu1, kPi - mu1G, 1e-7) << toString(m);
        EXPECT_NEAR(t.mu2, kPi - mu2G, 1e-7) << toString(m);
      }
    }
  }
}

TEST(SeedGamble, CircleIntersectionMatchesCoreAndLargerYIsNotAnAssemblyMode) {
  // Gamble's '+' (larger y_P) is assembly '+' only while x_R2 > x_R1: choosing the FK branch by
  // "larger y" flips the assembly mode when the elbows swap sides (a trap in style.md).
  auto rng = test::rng();
  int swappedSeen = 0, sameSeen = 0;
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const JointAngles q = inverse(g, p, m).angles;
        const Pose pose = makePose(g, q, p);
        if (std::abs(pose.R2.x() - pose.R1.x()) < 1.0) continue;  // eq. 10 divides by this
        if (singularityMargins(g, pose).typeII < 1e-4) continue;
        const bool r2Right = pose.R2.x() > pose.R1.x();
        (r2Right ? sameSeen : swappedSeen) += 1;
        for (AssemblyMode am : kAllAssemblyModes) {
          const FkResult core = forward(g, q, am);
          ASSERT_TRUE(core.ok());
          const bool positive = (am == AssemblyMode::Plus) == r2Right;
          const auto gamble = gambleForward(g, q.theta1, q.theta2, positive);
          ASSERT_TRUE(gamble.has_value());
          EXPECT_LT((core.p - *gamble).norm(), 1e-8)
              << "assembly " << toString(am) << " mode " << toString(m) << " at " << p.transpose();
        }
      }
    }
  }
  EXPECT_GT(sameSeen, 0);
  EXPECT_GT(swappedSeen, 0);
}

// ---------------------------------------------------------------------------------------------
// Hoang, Vuong, Pham 2015: tangent-half-angle IK (eq. 3) and FK (eq. 2).
// Frame: O = M1 at the origin, B = M2 at (lc, 0) with lc = w: xH = x + w/2, same y. theta1,
// theta4 (our theta1, theta2) counter-clockwise from +x, as ours. The paper is symmetric
// (la, lb); here each leg uses its own a_i, b_i (eq. 3 is per leg; in eq. 2, G gains b2^2 - b1^2).
// Branches: with E cos t + F sin t + G = 0 and t = 2 atan(u), '+' in eq. 3 gives chord + alpha
// (elbow counter-clockwise of the chord) for both motors: that is arm 1 '+' but arm 2 '-'. In
// eq. 2, '+' puts P counter-clockwise of R2->R1 seen from R2, i.e. right of R1->R2: assembly '-'.
// ---------------------------------------------------------------------------------------------
double halfAngleRoot(double E, double F, double G, double s) {
  return 2.0 * std::atan((-F + s * std::sqrt(E * E + F * F - G * G)) / (G - E));
}

JointAngles hoangInverse(const Geometry& g, const Vec2& p, double s1, double s4) {
  const double xH = p.x() + 0.5 * g.w, y = p.y(), lc = g.w;
  const double E1 = -2.0 * g.a1 * xH, F1 = -2.0 * g.a1 * y;
  const double G1 = g.a1 * g.a1 - g.b1 * g.b1 + xH * xH + y * y;
  const double E4 = 2.0 * g.a2 * (-xH + lc), F4 = -2.0 * g.a2 * y;
  const double G4 = lc * lc + g.a2 * g.a2 - g.b2 * g.b2 + xH * xH + y * y - 2.0 * lc * xH;
  return {halfAngleRoot(E1, F1, G1, s1), halfAngleRoot(E4, F4, G4, s4)};
}

Vec2 hoangForward(const Geometry& g, double theta1, double theta4, double s) {
  const double lc = g.w;
  const double cx = lc + g.a2 * std::cos(theta4) - g.a1 * std::cos(theta1);  // C - A
  const double cy = g.a2 * std::sin(theta4) - g.a1 * std::sin(theta1);
  const double E = 2.0 * g.b2 * cx, F = 2.0 * g.b2 * cy;
  const double G = cx * cx + cy * cy + g.b2 * g.b2 - g.b1 * g.b1;
  const double theta3 = halfAngleRoot(E, F, G, s);
  const double xH = lc + g.a2 * std::cos(theta4) + g.b2 * std::cos(theta3);
  const double yH = g.a2 * std::sin(theta4) + g.b2 * std::sin(theta3);
  return {xH - 0.5 * g.w, yH};
}

TEST(SeedHoang, PrintedGEqualsSquaredElbowDistanceForSymmetricLinks) {
  // Transcription check of eq. 2's G for la = a1 = a2: G = |C - A|^2.
  auto rng = test::rng();
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const double la = kHoang.a1, lc = kHoang.w;
  for (int i = 0; i < 100; ++i) {
    const double t1 = angle(rng), t4 = angle(rng);
    const double printed = lc * lc + 2 * la * la + 2 * lc * la * std::cos(t4) -
                           2 * lc * la * std::cos(t1) - 2 * la * la * std::cos(t4 - t1);
    const Vec2 ca(lc + la * std::cos(t4) - la * std::cos(t1),
                  la * std::sin(t4) - la * std::sin(t1));
    EXPECT_NEAR(printed, ca.squaredNorm(), 1e-9);
  }
}

TEST(SeedHoang, TangentHalfAngleIkMatchesCoreInEveryMode) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        // Hoang's sign: + for arm 1 '+', - for arm 2 '+'.
        const JointAngles h = hoangInverse(g, p, sign(arm1Sign(m)), -sign(arm2Sign(m)));
        const IkResult core = inverse(g, p, m);
        ASSERT_TRUE(core.ok());
        EXPECT_NEAR(angleDiff(core.angles.theta1, h.theta1), 0.0, kAngleTolRad)
            << toString(m) << " at " << p.transpose();
        EXPECT_NEAR(angleDiff(core.angles.theta2, h.theta2), 0.0, kAngleTolRad)
            << toString(m) << " at " << p.transpose();
      }
    }
  }
}

TEST(SeedHoang, TangentHalfAngleFkMatchesCoreInBothAssemblyModes) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const JointAngles q = inverse(g, p, m).angles;
        if (singularityMargins(g, makePose(g, q, p)).typeII < 1e-4) continue;
        for (AssemblyMode am : kAllAssemblyModes) {
          const FkResult core = forward(g, q, am);
          ASSERT_TRUE(core.ok());
          const Vec2 h = hoangForward(g, q.theta1, q.theta2, am == AssemblyMode::Plus ? -1.0 : 1.0);
          EXPECT_LT((core.p - h).norm(), 1e-8)
              << "assembly " << toString(am) << " from " << p.transpose();
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The 5R article: calcInvKinematicsHalf and calcFwdKinematics5R (its Python version, in double).
// Frame: origin at the centre of L5, A (motor 1) at (-L5/2, 0), E (motor 2) at (+L5/2, 0): ours.
// Angles anticlockwise from +x: ours. Links: L1 = a1, L2 = b1, L3 = b2, L4 = a2, L5 = w.
// leftSide = true gives alpha + beta (elbow counter-clockwise of the chord), so the article's
// calcInvKinematics5r (left true, right false) is "++"; other modes flip one flag. FK: "elbow
// up" phi + alpha, counter-clockwise from R1->R2, puts P left of R1->R2: assembly '+'. (Its
// prose formula writes L1 in alpha's numerator; the code, used here, has L2.)
// ---------------------------------------------------------------------------------------------
double articleIkHalfDeg(const Vec2& anchor, const Vec2& target, double femur, double tibia,
                        bool leftSide) {
  const double dy = target.y() - anchor.y(), dx = target.x() - anchor.x();
  const double dist = std::sqrt(dy * dy + dx * dx);
  if (dist > femur + tibia || dist < std::abs(femur - tibia)) return 0.0;
  const double alpha = std::atan2(dy, dx);
  const double beta =
      std::acos((femur * femur + dist * dist - tibia * tibia) / (2.0 * femur * dist));
  const double theta = leftSide ? alpha + beta : alpha - beta;
  return theta * 180.0 / kPi;
}

std::optional<Vec2> articleFk(const Geometry& g, double theta1Deg, double theta2Deg, bool elbowUp) {
  const double t1 = theta1Deg * kPi / 180.0, t2 = theta2Deg * kPi / 180.0;
  const double L1 = g.a1, L2 = g.b1, L3 = g.b2, L4 = g.a2, L5 = g.w;
  const Vec2 B(-L5 / 2.0 + L1 * std::cos(t1), L1 * std::sin(t1));
  const Vec2 D(L5 / 2.0 + L4 * std::cos(t2), L4 * std::sin(t2));
  const double dx = D.x() - B.x(), dy = D.y() - B.y();
  const double d = std::sqrt(dx * dx + dy * dy);
  if (d > L2 + L3 || d < std::abs(L2 - L3) || d == 0.0) return std::nullopt;
  const double phi = std::atan2(dy, dx);
  const double alpha = std::acos((d * d + L2 * L2 - L3 * L3) / (2.0 * d * L2));
  const double a = elbowUp ? phi + alpha : phi - alpha;
  return Vec2(B.x() + L2 * std::cos(a), B.y() + L2 * std::sin(a));
}

TEST(SeedArticle, AtanAcosIkMatchesCoreInEveryMode) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const double t1Deg =
            articleIkHalfDeg(g.motor1(), p, g.a1, g.b1, arm1Sign(m) == ArmSign::Plus);
        const double t2Deg =
            articleIkHalfDeg(g.motor2(), p, g.a2, g.b2, arm2Sign(m) == ArmSign::Minus);
        const IkResult core = inverse(g, p, m);
        ASSERT_TRUE(core.ok());
        EXPECT_NEAR(angleDiff(core.angles.theta1, radFromDeg(t1Deg)), 0.0, kAngleTolRad)
            << toString(m);
        EXPECT_NEAR(angleDiff(core.angles.theta2, radFromDeg(t2Deg)), 0.0, kAngleTolRad)
            << toString(m);
      }
    }
  }
}

TEST(SeedArticle, DefaultIsPlusPlusOnItsOwnMachine) {
  // calcInvKinematics5r on the article's constants (L1..L5 = 40, 60, 60, 40, 30): "++".
  const Vec2 target(5.0, 70.0);
  const double aDeg = articleIkHalfDeg(kArticle.motor1(), target, 40.0, 60.0, true);
  const double eDeg = articleIkHalfDeg(kArticle.motor2(), target, 40.0, 60.0, false);
  const IkResult core = inverse(kArticle, target, WorkingMode::PlusPlus);
  ASSERT_TRUE(core.ok());
  EXPECT_NEAR(angleDiff(core.angles.theta1, radFromDeg(aDeg)), 0.0, kAngleTolRad);
  EXPECT_NEAR(angleDiff(core.angles.theta2, radFromDeg(eDeg)), 0.0, kAngleTolRad);
}

TEST(SeedArticle, ElbowUpFkIsAssemblyPlus) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 500; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const JointAngles q = inverse(g, p, m).angles;
        if (singularityMargins(g, makePose(g, q, p)).typeII < 1e-4) continue;
        for (AssemblyMode am : kAllAssemblyModes) {
          const auto article =
              articleFk(g, degFromRad(q.theta1), degFromRad(q.theta2), am == AssemblyMode::Plus);
          const FkResult core = forward(g, q, am);
          ASSERT_TRUE(article.has_value() && core.ok());
          EXPECT_LT((core.p - *article).norm(), 1e-8) << toString(am);
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Dai et al. 2022, eqs. (9)-(14): with driving and floating link of equal length l, the elbow
// lies on the perpendicular bisector of the chord O->C: r_OA = r_OH - delta (h/o) Rot90 r_OH,
// r_OH = (C - O)/2, o = |r_OH|, h = sqrt(l^2 - o^2), Rot90 = [0 -1; 1 0] (counter-clockwise).
// Frame: origin at the base centre, motors at (-d/2, 0) and (+d/2, 0), d = w: ours. Eq. (13),
// written with x - d/2, is the motor at +d/2, i.e. our motor 2 (the paper's subscripts are
// swapped between its FK and IK sections). Eq. (14) as printed has y + delta1 k (d/2 + x); the
// rotation above gives y - delta1 k (x + d/2) (a sign typo, shown below). delta = +1 puts the
// elbow clockwise of the chord: arm 2 '+', arm 1 '-'. Only for a_i = b_i, so tested on dai2022
// and on a machine with a1 = b1 != a2 = b2.
// ---------------------------------------------------------------------------------------------
double daiMotorAngle(double l, double motorX, const Vec2& p, double delta) {
  const double x = p.x(), y = p.y();
  const double o = 0.5 * std::hypot(x - motorX, y);
  const double k = std::sqrt(l * l - o * o) / o;
  return std::atan2(y - delta * k * (x - motorX), (x - motorX) + delta * k * y);
}

const Geometry kDaiUnequal{120.0, 120.0, 150.0, 150.0, 180.0};

TEST(SeedDai, Eqs13And14MatchCoreInEveryMode) {
  auto rng = test::rng();
  for (const Geometry& g : {kDai, kDaiUnequal}) {
    for (int i = 0; i < 1000; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const double delta1 = arm1Sign(m) == ArmSign::Plus ? -1.0 : 1.0;
        const double delta2 = arm2Sign(m) == ArmSign::Plus ? 1.0 : -1.0;
        const double t1 = daiMotorAngle(g.a1, -0.5 * g.w, p, delta1);  // eq. 14 (corrected)
        const double t2 = daiMotorAngle(g.a2, 0.5 * g.w, p, delta2);   // eq. 13
        const IkResult core = inverse(g, p, m);
        ASSERT_TRUE(core.ok());
        EXPECT_NEAR(angleDiff(core.angles.theta1, t1), 0.0, kAngleTolRad) << toString(m);
        EXPECT_NEAR(angleDiff(core.angles.theta2, t2), 0.0, kAngleTolRad) << toString(m);
      }
    }
  }
}

TEST(SeedDai, Eq14AsPrintedMissesTheTarget) {
  // As printed, eq. 14's elbow is not l away from C (except on special lines), which is why the
  // test above uses the sign implied by eqs. (9)-(11).
  const Geometry& g = kDai;
  const Vec2 p(40.0, 150.0);
  const double x = p.x(), y = p.y(), d = g.w, l = g.a1;
  const double o = 0.5 * std::hypot(x + d / 2.0, y), k = std::sqrt(l * l - o * o) / o;
  const double printed = std::atan2(y + k * (d / 2.0 + x), x + d / 2.0 + k * y);
  const double corrected = daiMotorAngle(l, -d / 2.0, p, 1.0);
  EXPECT_GT(std::abs((elbow1(g, printed) - p).norm() - g.b1), 1.0);
  EXPECT_NEAR((elbow1(g, corrected) - p).norm(), g.b1, 1e-9);
}

TEST(SeedDai, VectorFkEqs1To6MatchesCore) {
  // r_OC = r_OA2 + r_A2H + r_HC, r_A2H = (r_OA1 - r_OA2)/2, r_HC = -gamma (h/a) Rot90 r_A2H,
  // a = |r_A2H|, h = sqrt(l^2 - a^2). gamma = +1 puts C left of A1->A2: assembly '+'. (The
  // expanded eqs. 7-8 as printed carry typos; the vector form is used.)
  auto rng = test::rng();
  const Geometry& g = kDai;
  for (int i = 0; i < 1000; ++i) {
    const Vec2 p = randomReachable(g, rng);
    for (WorkingMode m : kAllWorkingModes) {
      const JointAngles q = inverse(g, p, m).angles;
      if (singularityMargins(g, makePose(g, q, p)).typeII < 1e-4) continue;
      const Vec2 A1 = elbow1(g, q.theta1), A2 = elbow2(g, q.theta2);
      const Vec2 A2H = 0.5 * (A1 - A2);
      const double a = A2H.norm(), h = std::sqrt(g.b1 * g.b1 - a * a);
      const Vec2 rot(-A2H.y(), A2H.x());
      for (AssemblyMode am : kAllAssemblyModes) {
        const double gamma = am == AssemblyMode::Plus ? 1.0 : -1.0;
        const Vec2 C = A2 + A2H - gamma * (h / a) * rot;
        const FkResult core = forward(g, q, am);
        ASSERT_TRUE(core.ok());
        EXPECT_LT((core.p - C).norm(), 1e-8) << toString(am);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Round trips on every seed machine, and the papers' claims about their machines.
// ---------------------------------------------------------------------------------------------
TEST(SeedMachines, ForwardOfInverseIsIdentityInEveryBranch) {
  auto rng = test::rng();
  for (const Geometry& g : kGeneral) {
    for (int i = 0; i < 1000; ++i) {
      const Vec2 p = randomReachable(g, rng);
      for (WorkingMode m : kAllWorkingModes) {
        const IkResult ik = inverse(g, p, m);
        ASSERT_TRUE(ik.ok());
        const Pose pose = makePose(g, ik.angles, p);
        const FkResult fk = forward(g, ik.angles, assemblyModeOf(pose));
        ASSERT_TRUE(fk.ok());
        if (singularityMargins(g, pose).typeII > 1e-4) {
          EXPECT_LT((fk.p - p).norm(), kPositionTolMm) << toString(m) << " at " << p.transpose();
        }
      }
    }
  }
}

// Smallest type II margin over a grid of reachable points, in every working mode.
double minTypeIIMargin(const Geometry& g, double stepMm) {
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2) + 0.5 * g.w;
  double smallest = kPi;
  for (double x = -reach; x <= reach; x += stepMm)
    for (double y = -reach; y <= reach; y += stepMm) {
      const Vec2 p(x, y);
      if (!strictlyReachable(g, p)) continue;
      for (WorkingMode m : kAllWorkingModes)
        smallest = std::min(smallest,
                            singularityMargins(g, makePose(g, inverse(g, p, m).angles, p)).typeII);
    }
  return smallest;
}

TEST(SeedHoang, Eq9HoldsAndTheWorkspaceHasNoTypeII) {
  const double la = kHoang.a1, lb = kHoang.b1, lc = kHoang.w;
  // Eq. 9 (and with it workspace type 1 of Table 1: 2 la < lc < 2 lb, lb > lc/2 + la).
  EXPECT_GT(lc, 2.0 * la);
  EXPECT_GT(lb, lc / 2.0 + la);
  EXPECT_LT(lc, 2.0 * lb);
  // Why it works: the elbow distance |R1R2| stays in [lc - 2 la, lc + 2 la] = [110, 390], so
  // the angle at P between the floating links, acos(1 - |R1R2|^2 / (2 lb^2)), never reaches
  // 0 or pi. Its closest approach bounds the type II margin everywhere, in every mode.
  const auto angleAtP = [&](double d) { return std::acos(1.0 - d * d / (2.0 * lb * lb)); };
  const double bound = std::min(angleAtP(lc - 2.0 * la), kPi - angleAtP(lc + 2.0 * la));
  EXPECT_GT(bound, 0.4);
  EXPECT_GE(minTypeIIMargin(kHoang, 2.0), bound - 1e-9);
}

TEST(SeedHoang, WorkspaceHolds110By90RectangleSingularityFree) {
  const double la = kHoang.a1, lb = kHoang.b1, lc = kHoang.w, lw = 110.0, hw = 90.0;
  const double R = la + lb, r = lb - la;
  // Eq. 10: the tallest rectangle of width lw centred between the motors, corners on the outer
  // (top) and inner (bottom) reach circles.
  const double top = std::sqrt(R * R - 0.25 * (lc + lw) * (lc + lw));
  const double bottom = std::sqrt(r * r - 0.25 * (lc - lw) * (lc - lw));
  ASSERT_GE(top - bottom, hw);
  const double y0 = 0.5 * (top + bottom) - 0.5 * hw;  // centred vertically in that band
  // Every point of the rectangle's edges and interior (1 mm grid, corners exact) is reachable
  // in "++", away from type II, and strictly inside the workspace (not type I).
  for (double u = 0.0; u <= lw + 1e-9; u += lw / 110.0)
    for (double v = 0.0; v <= hw + 1e-9; v += hw / 90.0) {
      const Vec2 p(-0.5 * lw + u, y0 + v);
      const IkResult ik = inverse(kHoang, p, WorkingMode::PlusPlus);
      ASSERT_TRUE(ik.ok()) << p.transpose();
      const SingularityMargins sm = singularityMargins(kHoang, makePose(kHoang, ik.angles, p));
      EXPECT_GT(sm.typeII, 0.4) << p.transpose();
      EXPECT_GT(sm.typeI(), 0.0) << p.transpose();
    }
}

TEST(SeedHoang, BreakingEq9BringsTypeIIIntoTheWorkspace) {
  // lb < lc/2 + la: the floating links can stretch into a line inside the workspace.
  const Geometry g{70.0, 150.0, 70.0, 150.0, 250.0};
  ASSERT_LT(g.b1, g.w / 2.0 + g.a1);
  EXPECT_LT(minTypeIIMargin(g, 1.0), 0.02);
}

}  // namespace
}  // namespace fivebar
