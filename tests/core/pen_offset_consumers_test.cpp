// SPDX-License-Identifier: GPL-3.0-or-later
// The calibrated pen offset where pen positions meet motor angles outside the planner (issue 13):
// the stroke optimiser's travel estimate, the time-optimal reference and the workspace maps work
// on the pen's kinematics (pen_kinematics.hpp) when the profile has a pen offset. Each test
// compares against penInverse / penForward directly and fails when the plain kinematics of P is
// used instead.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/machine/pen_kinematics.hpp"
#include "core/planning/optimise.hpp"
#include "core/planning/time_optimal.hpp"
#include "core/workspace/workspace.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

MachineProfile withPenOffset(double alongMm, double normalMm) {
  MachineProfile p = preset("maker-plotter").value_or(MachineProfile{});
  MachineCalibration c;
  c.penOffset = PenOffset{alongMm, normalMm};
  p.calibration = c;
  return p;
}

TEST(PenOffsetConsumers, OptimiserTravelIsBetweenThePensAngles) {
  const MachineProfile p = withPenOffset(12.0, -9.0);
  const WorkingMode mode = p.defaultMode;
  std::vector<Stroke> strokes(2);
  strokes[0].points = {Vec2(-60, 150), Vec2(-20, 160)};
  strokes[1].points = {Vec2(50, 200), Vec2(70, 180)};
  const IkResult a = penInverse(p, strokes[0].points.back(), mode);
  const IkResult b = penInverse(p, strokes[1].points.front(), mode);
  ASSERT_TRUE(a.ok() && b.ok());
  const double expected = jointTravelTimeS(p.motors, a.angles, b.angles);
  const double plain = jointTravelTimeS(p.motors, inverse(p.geometry, strokes[0].points.back(), mode).angles,
                                        inverse(p.geometry, strokes[1].points.front(), mode).angles);
  ASSERT_GT(std::abs(plain - expected), 1e-3 * expected);  // the offset matters here
  EXPECT_NEAR(travelTimeS(strokes, p, mode), expected, 1e-12);
  OptimiseOptions o;
  o.measureTravel = true;
  o.reorder = false;
  o.join = false;
  EXPECT_NEAR(optimise(strokes, p, mode, o).report.travelBeforeS, expected, 1e-12);
}

// Speed-limited motors (huge accelerations and asked speed): the time of a path is the integral of
// max_i |dq_i/ds| / vmax_i, here summed over the pen's motor angles 0.01 mm apart.
TEST(PenOffsetConsumers, TimeOptimalRatesAreThePensRates) {
  const MachineProfile p = withPenOffset(12.0, -9.0);
  const std::optional<PenOffset> pen = calibratedPenOffset(p);
  MotorLimits lim = motorLimitsOf(p);
  lim.maxAccelRadPerS2[0] = lim.maxAccelRadPerS2[1] = 1e12;
  const Vec2 a(-50, 140), b(40, 200);
  double reference = 0.0;
  JointAngles prev = penInverse(p, a, p.defaultMode).angles;
  const int n = 20000;
  for (int k = 1; k <= n; ++k) {
    const IkResult ik = penInverse(p, a + (b - a) * (static_cast<double>(k) / n), p.defaultMode);
    ASSERT_TRUE(ik.ok());
    reference += std::max(std::abs(std::remainder(ik.angles.theta1 - prev.theta1, 2.0 * kPi)) / lim.maxSpeedRadPerS[0],
                          std::abs(std::remainder(ik.angles.theta2 - prev.theta2, 2.0 * kPi)) / lim.maxSpeedRadPerS[1]);
    prev = ik.angles;
  }
  TimeOptimalOptions fine;
  fine.gridStepMm = 0.05;
  const std::vector<Vec2> path{a, b};
  const double withPen = timeOptimalPathS(p.geometry, pen, p.defaultMode, path, 1e9, lim, fine);
  const double atP = timeOptimalPathS(p.geometry, p.defaultMode, path, 1e9, lim, fine);
  std::printf("speed-limited line: reference %.5f s, pen rates %.5f s, P's rates %.5f s\n", reference, withPen, atP);
  EXPECT_NEAR(withPen, reference, 2e-3 * reference);
  EXPECT_GT(std::abs(atP - reference), 1e-2 * reference);
}

TEST(PenOffsetConsumers, WorkspaceMapsAreOfThePen) {
  const MachineProfile p = withPenOffset(12.0, -9.0);
  WorkspaceSettings s = workspaceSettings(p);
  ASSERT_TRUE(s.penOffset.has_value());
  s.limits = {-10.0, 10.0, -10.0, 10.0};  // no joint limits: reach alone
  const std::optional<PenOffset> pen = s.penOffset;
  const GridSpec grid = gridCovering(p.geometry, 90);
  for (const WorkingMode mode : {WorkingMode::PlusPlus, WorkingMode::MinusPlus}) {
    const WorkspaceMap map = computeMap(p.geometry, s, mode, grid, 2);
    WorkspaceSettings plain = s;
    plain.penOffset.reset();
    const WorkspaceMap atP = computeMap(p.geometry, plain, mode, grid, 2);
    int cells = 0, agree = 0, differFromP = 0, checked = 0, samePose = 0;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix) {
        const std::size_t i = grid.index(ix, iy);
        const Vec2 x(grid.xCenter(ix), grid.yCenter(iy));
        Vec2 P = Vec2::Zero();
        const IkResult ik = penInverse(p.geometry, pen, x, mode, &P);
        ++cells;
        agree += (map.reachable[i] != 0) == ik.ok();
        differFromP += map.reachable[i] != atP.reachable[i];
        if (!ik.ok() || !map.reachable[i]) continue;
        // The linkage's margins at the pose that puts the pen there (where that pose is the
        // mode's pose of P: away from a leg's stretch the chain's elbow is).
        const IkResult linkageAtP = inverse(p.geometry, P, mode);
        if (linkageAtP.ok() &&
            std::abs(std::remainder(linkageAtP.angles.theta1 - ik.angles.theta1, 2.0 * kPi)) < 1e-6) {
          const PointSample atDistal = evaluatePoint(p.geometry, plain, mode, P);
          EXPECT_NEAR(map.typeIIMarginRadMap[i], atDistal.typeIIMarginRad, 1e-5);
          EXPECT_NEAR(map.typeIMarginRadMap[i], atDistal.typeIMarginRad, 1e-5);
          ++samePose;
        }
        // The pen's resolution: the worst pen displacement for one step of a motor (finite
        // differences of penForward) is at most the map's worst-direction figure.
        if (ix % 7 == 0 && iy % 7 == 0 && map.typeIIMarginRadMap[i] > 0.2) {
          ++checked;
          // The pen of a nearby pose: of the two assemblies, the one next to x.
          const auto penNear = [&](const JointAngles& q) {
            double best = 1e18;
            for (const AssemblyMode a : {AssemblyMode::Plus, AssemblyMode::Minus}) {
              const FkResult f = penForward(p.geometry, pen, q, a);
              if (f.ok()) best = std::min(best, (f.p - x).norm());
            }
            return best;
          };
          const double step = std::max(penNear({ik.angles.theta1 + s.stepRad1, ik.angles.theta2}),
                                       penNear({ik.angles.theta1, ik.angles.theta2 + s.stepRad2}));
          EXPECT_LE(step, map.resolutionMm[i] * 1.001);
          EXPECT_GE(step, 0.3 * map.resolutionMm[i]);
        }
      }
    // Cells whose centre is within the reach tolerance of the boundary may go either way.
    EXPECT_GE(agree, cells - 3) << static_cast<int>(mode);
    EXPECT_GT(differFromP, 20) << "the pen's region is not P's";
    EXPECT_GT(checked, 10);
    EXPECT_GT(samePose, cells / 4);
  }
}

}  // namespace
}  // namespace fivebar
