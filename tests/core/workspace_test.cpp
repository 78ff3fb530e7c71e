// SPDX-License-Identifier: GPL-3.0-or-later
// Workspace analysis: maps against the reference kinematics (kinematics.hpp, singularity.hpp),
// areas against an independent Monte Carlo estimate, type II loci, the inscribed rectangle.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cmath>
#include <random>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/singularity.hpp"
#include "core/workspace/workspace.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

// An asymmetric machine (a1 != a2, b1 != b2): catches an arm formula using the other arm's data.
const Geometry kAsymmetric{60.0, 150.0, 80.0, 170.0, 90.0};

// Reference evaluation from the scalar kinematics and singularity modules, sharing no code with
// the workspace kernel.
struct Reference {
  bool reachable = false;
  SingularityMargins margins;
  double mu = 0.0;
  double inverseCondition = 0.0;
  double resolutionMm = 0.0;
};

bool withinLimits(double theta, double lo, double hi) {
  for (int k = -3; k <= 3; ++k) {
    const double t = theta + 2.0 * kPi * k;
    if (t >= lo && t <= hi) return true;
  }
  return false;
}

Reference reference(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Vec2& p) {
  Reference r;
  const IkResult ik = inverse(g, p, mode);
  if (!ik.ok()) return r;
  const JointLimits& l = s.limits;
  r.reachable = withinLimits(ik.angles.theta1, l.theta1Min, l.theta1Max) &&
                withinLimits(ik.angles.theta2, l.theta2Min, l.theta2Max);
  const Pose pose = makePose(g, ik.angles, p);
  r.margins = singularityMargins(g, pose);
  r.mu = transmissionAngles(g, pose).mu;
  r.inverseCondition = inverseCondition(g, pose);
  if (const auto J = cartesianJacobian(g, pose)) {
    const Eigen::Matrix2d scaled = *J * Eigen::Vector2d(s.stepRad1, s.stepRad2).asDiagonal();
    r.resolutionMm = Eigen::JacobiSVD<Eigen::Matrix2d>(scaled).singularValues()(0);
  }
  return r;
}

bool referenceSafe(const Geometry& g, const WorkspaceSettings& s, WorkingMode mode, const Vec2& p) {
  const Reference r = reference(g, s, mode, p);
  return r.reachable && r.margins.typeII >= s.typeIIMarginRad &&
         r.margins.typeI() >= s.typeIMarginRad;
}

WorkspaceSettings unlimited() {
  WorkspaceSettings s;
  s.stepRad1 = radFromDeg(1.0 / 35.5556);
  s.stepRad2 = radFromDeg(1.0 / 17.7778);  // different steps per motor
  return s;
}

Vec2 randomPointIn(const GridSpec& grid, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ux(grid.x0, grid.x0 + grid.nx * grid.cellMm);
  std::uniform_real_distribution<double> uy(grid.y0, grid.y0 + grid.ny * grid.cellMm);
  return {ux(rng), uy(rng)};
}

TEST(WorkspacePoint, MatchesReferenceKinematicsInEveryMode) {
  auto rng = test::rng();
  WorkspaceSettings s = unlimited();
  s.limits = {radFromDeg(-30), radFromDeg(250), radFromDeg(-80), radFromDeg(200)};
  const GridSpec grid = gridCovering(kAsymmetric, 64, false);
  int reachableCount = 0;
  for (int n = 0; n < 4000; ++n) {
    const Vec2 p = randomPointIn(grid, rng);
    for (WorkingMode mode : kAllWorkingModes) {
      const PointSample x = evaluatePoint(kAsymmetric, s, mode, p);
      const Reference r = reference(kAsymmetric, s, mode, p);
      ASSERT_EQ(x.reachable, r.reachable) << p.transpose() << " mode " << toString(mode);
      EXPECT_EQ(x.reachSlackMm >= 0.0, r.reachable) << p.transpose();
      if (!r.reachable) continue;
      ++reachableCount;
      EXPECT_NEAR(x.typeIIMarginRad, r.margins.typeII, 1e-9);
      EXPECT_NEAR(x.typeIMarginRad, r.margins.typeI(), 1e-7);
      EXPECT_NEAR(x.muRad, r.mu, 1e-9);
      EXPECT_NEAR(std::asin(std::min(1.0, std::abs(x.signedTypeII))), r.margins.typeII, 1e-7);
      EXPECT_NEAR(x.inverseCondition, r.inverseCondition, 1e-7);
      if (r.resolutionMm > 0.0 && std::isfinite(x.resolutionMm)) {
        EXPECT_NEAR(x.resolutionMm / r.resolutionMm, 1.0, 1e-7);
      }
    }
  }
  EXPECT_GT(reachableCount, 2000);  // the sample really exercised reachable points
}

TEST(WorkspaceMap, CellsEqualPointEvaluationAndThreadsAgree) {
  WorkspaceSettings s = unlimited();
  s.limits = {radFromDeg(-45), radFromDeg(270), radFromDeg(-90), radFromDeg(225)};
  const GridSpec grid = gridCovering(kAsymmetric, 97);
  const auto all = computeAllModes(kAsymmetric, s, grid, 2);
  for (std::size_t m = 0; m < 4; ++m) {
    const WorkspaceMap one = computeMap(kAsymmetric, s, kAllWorkingModes[m], grid, 1);
    ASSERT_EQ(all[m].mode, kAllWorkingModes[m]);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      ASSERT_EQ(one.reachable[i], all[m].reachable[i]);
      ASSERT_EQ(one.reachSlackMm[i], all[m].reachSlackMm[i]);
    }
    for (int iy = 0; iy < grid.ny; iy += 7) {
      for (int ix = 0; ix < grid.nx; ix += 5) {
        const std::size_t i = grid.index(ix, iy);
        const Vec2 p(grid.xCenter(ix), grid.yCenter(iy));
        const PointSample x = evaluatePoint(kAsymmetric, s, kAllWorkingModes[m], p);
        ASSERT_EQ(all[m].reachable[i] != 0, x.reachable);
        if (!x.reachable) {
          EXPECT_TRUE(std::isnan(all[m].muRad[i]));
          continue;
        }
        EXPECT_NEAR(all[m].muRad[i], x.muRad, 1e-6);
        EXPECT_NEAR(all[m].typeIIMarginRadMap[i], x.typeIIMarginRad, 1e-6);
        EXPECT_NEAR(all[m].inverseCondition[i], x.inverseCondition, 1e-6);
      }
    }
  }
}

TEST(WorkspaceMap, ReusedStorageGivesTheSameMaps) {
  const WorkspaceSettings s = unlimited();
  const GridSpec grid = gridCovering(kAsymmetric, 80);
  std::array<WorkspaceMap, 4> reused = computeAllModes(Geometry{50, 120, 50, 120, 60}, s, grid);
  computeAllModes(kAsymmetric, s, grid, reused);
  const auto fresh = computeAllModes(kAsymmetric, s, grid);
  for (std::size_t m = 0; m < 4; ++m)
    for (std::size_t i = 0; i < grid.size(); ++i)
      ASSERT_EQ(reused[m].reachSlackMm[i], fresh[m].reachSlackMm[i]);
}

// Monte Carlo over the grid's box with the reference kinematics: an estimate sharing no code
// with the grid counting.
TEST(WorkspaceAnalysis, AreasAgreeWithMonteCarlo) {
  auto rng = test::rng();
  WorkspaceSettings s = unlimited();
  s.limits = {radFromDeg(-45), radFromDeg(270), radFromDeg(-90), radFromDeg(225)};
  const GridSpec grid = gridCovering(kAsymmetric, 300);
  const double boxArea = grid.nx * grid.cellMm * grid.ny * grid.cellMm;
  for (WorkingMode mode : {WorkingMode::PlusPlus, WorkingMode::PlusMinus}) {
    const WorkspaceAnalysis a = analyse(computeMap(kAsymmetric, s, mode, grid), kAsymmetric, s);
    const int samples = 60000;
    int reach = 0, safe = 0;
    for (int n = 0; n < samples; ++n) {
      const Vec2 p = randomPointIn(grid, rng);
      const Reference r = reference(kAsymmetric, s, mode, p);
      reach += r.reachable ? 1 : 0;
      safe += referenceSafe(kAsymmetric, s, mode, p) ? 1 : 0;
    }
    const double mcReach = boxArea * reach / samples, mcSafe = boxArea * safe / samples;
    // Tolerance: 4 standard errors of the estimate plus the grid's boundary error.
    const double tolReach = 4.0 * boxArea * std::sqrt(0.25 / samples) + 0.01 * mcReach;
    EXPECT_NEAR(a.reachableAreaMm2, mcReach, tolReach) << toString(mode);
    EXPECT_NEAR(a.safeAreaMm2, mcSafe, tolReach) << toString(mode);
    EXPECT_GT(a.safeAreaMm2, 0.0);
    EXPECT_LE(a.safeAreaMm2, a.reachableAreaMm2);
  }
}

TEST(WorkspaceAnalysis, UnlimitedReachableAreaIsTheAnnuliIntersection) {
  // Without joint limits every mode reaches the whole intersection of the two annuli; the
  // work-side half of it is estimated here from the annulus inequalities alone.
  auto rng = test::rng();
  const Geometry g{40, 60, 40, 60, 30};
  const WorkspaceSettings s = unlimited();
  const GridSpec grid = gridCovering(g, 256);
  const double boxArea = grid.nx * grid.cellMm * grid.ny * grid.cellMm;
  int inside = 0;
  const int samples = 100000;
  for (int n = 0; n < samples; ++n) {
    const Vec2 p = randomPointIn(grid, rng);
    const double d1 = (p - g.motor1()).norm(), d2 = (p - g.motor2()).norm();
    inside += (d1 <= 100 && d1 >= 20 && d2 <= 100 && d2 >= 20) ? 1 : 0;
  }
  const double expected = boxArea * inside / samples;
  for (WorkingMode mode : kAllWorkingModes) {
    const WorkspaceAnalysis a = analyse(computeMap(g, s, mode, grid), g, s);
    EXPECT_NEAR(a.reachableAreaMm2, expected, 0.02 * expected) << toString(mode);
  }
}

TEST(WorkspaceAnalysis, Hoang2015EnclosesTheirRectangle) {
  const MachineProfile p = *preset("hoang2015");
  const WorkspaceSettings s = workspaceSettings(p);
  const WorkspaceMap map = computeMap(p.geometry, s, WorkingMode::PlusPlus, gridCovering(p.geometry, 400));
  const auto shaped = largestSafeRectangle(map, p.geometry, s, 110.0 / 90.0);
  ASSERT_TRUE(shaped);
  EXPECT_GE(shaped->width(), 110.0);
  EXPECT_GE(shaped->height(), 90.0);
  EXPECT_NEAR(shaped->width() / shaped->height(), 110.0 / 90.0, 1e-9);
  const WorkspaceAnalysis a = analyse(map, p.geometry, s);
  ASSERT_TRUE(a.largestRectangle);
  EXPECT_GE(a.largestRectangle->area(), 110.0 * 90.0);
  // Hoang's eq. (9) holds, so no type II singularity lies in the workspace (any mode).
  for (WorkingMode mode : kAllWorkingModes) {
    const WorkspaceAnalysis m = analyse(computeMap(p.geometry, unlimited(), mode, map.grid), p.geometry, unlimited());
    EXPECT_TRUE(m.typeIILoci.empty()) << toString(mode);
  }
}

TEST(WorkspaceAnalysis, RectangleLiesInTheSafeRegion) {
  for (const char* name : {"hoang2015", "maker-plotter", "dai2022"}) {
    const MachineProfile p = *preset(name);
    const WorkspaceSettings s = workspaceSettings(p);
    for (WorkingMode mode : {WorkingMode::PlusPlus, WorkingMode::MinusPlus}) {
      const WorkspaceMap map = computeMap(p.geometry, s, mode, gridCovering(p.geometry, 200));
      const auto r = largestSafeRectangle(map, p.geometry, s);
      ASSERT_TRUE(r) << name;
      EXPECT_GT(r->area(), 0.0);
      // Dense check with the reference kinematics, edges included.
      const int n = 120;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          const Vec2 q(r->xMin + r->width() * i / n, r->yMin + r->height() * j / n);
          ASSERT_TRUE(referenceSafe(p.geometry, s, mode, q))
              << name << " " << toString(mode) << " at " << q.transpose();
        }
    }
  }
}

TEST(WorkspaceAnalysis, MakerPlotterHoldsA5Landscape) {
  const MachineProfile p = *preset("maker-plotter");
  const WorkspaceSettings s = workspaceSettings(p);
  const WorkspaceMap map = computeMap(p.geometry, s, WorkingMode::PlusPlus, gridCovering(p.geometry, 300));
  const auto r = largestSafeRectangle(map, p.geometry, s, 210.0 / 148.0);
  ASSERT_TRUE(r);
  EXPECT_GE(r->width(), 210.0);
  EXPECT_GE(r->height(), 148.0);
}

TEST(WorkspaceAnalysis, ViolatingHoangEq9PutsTypeIILociInsideTheWorkspace) {
  // b = 150 < w/2 + a = 195: the floating links can stretch into line inside the workspace.
  const Geometry g{70, 150, 70, 150, 250};
  const WorkspaceSettings s = unlimited();
  const WorkspaceMap map = computeMap(g, s, WorkingMode::PlusPlus, gridCovering(g, 300));
  const WorkspaceAnalysis a = analyse(map, g, s);
  ASSERT_FALSE(a.typeIILoci.empty());
  std::size_t points = 0;
  for (const Polyline& line : a.typeIILoci) {
    for (const Vec2& q : line.points) {
      const Reference r = reference(g, s, WorkingMode::PlusPlus, q);
      ASSERT_TRUE(r.reachable) << q.transpose();
      EXPECT_LT(r.margins.typeII, radFromDeg(1.0)) << q.transpose();
      ++points;
    }
  }
  EXPECT_GT(points, 20u);
  // The band within the margin around the loci is excluded from the safe region.
  EXPECT_LT(a.safeAreaMm2, a.reachableAreaMm2 * 0.98);
}

TEST(WorkspaceAnalysis, ReachBoundaryIsClosedAndOnTheAnnuli) {
  const Geometry g{40, 60, 40, 60, 30};
  const WorkspaceSettings s = unlimited();
  const GridSpec grid = gridCovering(g, 256, false);
  const WorkspaceAnalysis a = analyse(computeMap(g, s, WorkingMode::PlusPlus, grid), g, s);
  ASSERT_FALSE(a.reachBoundary.empty());
  for (const Polyline& line : a.reachBoundary) {
    EXPECT_TRUE(line.closed);
    for (const Vec2& q : line.points) {
      const double d1 = (q - g.motor1()).norm(), d2 = (q - g.motor2()).norm();
      const double slack = std::min({100 - d1, d1 - 20, 100 - d2, d2 - 20});
      EXPECT_LT(std::abs(slack), 0.05 * grid.cellMm + 1e-3) << q.transpose();
    }
  }
}

TEST(WorkspaceAnalysis, NothingSafeGivesNoRectangle) {
  WorkspaceSettings s = unlimited();
  s.typeIIMarginRad = radFromDeg(89.9);  // transmission angle can hardly be that close to 90
  s.typeIMarginRad = radFromDeg(89.9);
  const Geometry g{40, 60, 40, 60, 30};
  const WorkspaceAnalysis a = analyse(computeMap(g, s, WorkingMode::PlusPlus, gridCovering(g, 64)), g, s);
  EXPECT_EQ(a.safeAreaMm2, 0.0);
  EXPECT_FALSE(a.largestRectangle);
  EXPECT_GT(a.reachableAreaMm2, 0.0);
}

TEST(WorkspaceGrid, CoversEveryReachablePointOnTheWorkSide) {
  auto rng = test::rng();
  const GridSpec grid = gridCovering(kAsymmetric, 128);
  EXPECT_EQ(std::max(grid.nx, grid.ny), 128);
  EXPECT_GE(grid.y0, 0.0 - 1e-12);
  std::uniform_real_distribution<double> u(-400.0, 400.0);
  for (int n = 0; n < 20000; ++n) {
    const Vec2 p(u(rng), std::abs(u(rng)));
    if (!inverse(kAsymmetric, p, WorkingMode::PlusPlus).ok()) continue;
    EXPECT_GE(p.x(), grid.x0);
    EXPECT_LE(p.x(), grid.x0 + grid.nx * grid.cellMm);
    EXPECT_LE(p.y(), grid.y0 + grid.ny * grid.cellMm);
  }
}

}  // namespace
}  // namespace fivebar
