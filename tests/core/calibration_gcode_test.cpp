// SPDX-License-Identifier: GPL-3.0-or-later
// A calibration in the G-code (issue 13): the plan holds kinematic angles, G-code carries commanded
// ones (kinematic - zero offset), the home pose is commanded; and the whole chain (fit -> plan ->
// G-code -> the true machine) draws a 60 mm square within 0.1 mm.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "calibration_scenario.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "gcode_text.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

using test::linesOf;
using test::wordsOf;

Drawing square60() {
  Drawing d;
  d.layers.resize(1);
  Polyline pl;
  for (const Vec2& c : {Vec2(0, 0), Vec2(60, 0), Vec2(60, 60), Vec2(0, 60), Vec2(0, 0)}) pl.points.push_back(c);
  d.layers[0].paths.push_back(pl);
  return d;
}

PlanResult planSquare(const MachineProfile& p, const Vec2& at) {
  PlanOptions o;
  o.atMm = at;
  return planJob(square60(), p, o);
}

TEST(CalibrationGcode, CommandedAnglesDifferFromThePlanExactlyByTheOffset) {
  const MachineProfile plain = *preset("maker-plotter");
  MachineProfile calibrated = plain;
  calibrated.calibration.emplace();
  calibrated.calibration->zeroOffsetRad1 = radFromDeg(1.25);
  calibrated.calibration->zeroOffsetRad2 = radFromDeg(-0.75);
  const PlanResult r = planSquare(plain, Vec2(-30, 140));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto a = linesOf(writeGcode(r.job, plain)), b = linesOf(writeGcode(r.job, calibrated));
  ASSERT_EQ(a.size() + 1, b.size());  // one comment line more
  int moves = 0;
  for (std::size_t i = 0, j = 0; i < a.size(); ++i, ++j) {
    if (b[j].rfind("; calibrated:", 0) == 0) ++j;
    if (a[i].rfind("G1 ", 0) != 0) {
      if (a[i].rfind("; start pose", 0) != 0) {
        EXPECT_EQ(a[i], b[j]);
      }
      continue;
    }
    const auto wa = wordsOf(a[i]), wb = wordsOf(b[j]);
    EXPECT_NEAR(wa.at('X') - wb.at('X'), 1.25, 1.01e-4) << a[i] << " / " << b[j];
    EXPECT_NEAR(wa.at('Y') - wb.at('Y'), -0.75, 1.01e-4) << a[i] << " / " << b[j];
    ++moves;
  }
  EXPECT_GT(moves, 4);
  // Planned with the calibrated profile, the job starts at the commanded home pose.
  const PlanResult rc = planSquare(calibrated, Vec2(-30, 140));
  ASSERT_TRUE(rc.ok()) << rc.message;
  const std::string text = writeGcode(rc.job, calibrated);
  char expected[80];
  std::snprintf(expected, sizeof expected, "; start pose X%.4f Y%.4f", degFromRad(plain.homeAngles.theta1),
                degFromRad(plain.homeAngles.theta2));
  EXPECT_NE(text.find(expected), std::string::npos) << text.substr(0, 600);
}

TEST(CalibrationGcode, FitPlanGcodeAndTheTrueMachineDrawA60MmSquareWithin0_1Mm) {
  const MachineProfile nominal = *preset("maker-plotter");
  const auto marks = test::measuredMarks(nominal, test::seed(), false);
  const calibration::CalibrationFit fit = calibration::fitMarks(nominal, marks);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  const MachineProfile calibrated = calibration::calibratedProfile(nominal, fit, "2026-12-01");
  for (const MachineProfile* p : {&nominal, &calibrated}) {
    const PlanResult r = planSquare(*p, Vec2(-30, 140));
    ASSERT_TRUE(r.ok()) << r.message;
    // Every G1 target while the pen is down: where the host believes the pen is (its own model)
    // and where the true machine puts it.
    std::vector<Vec2> believed, drawn;
    bool down = false;
    for (const std::string& line : linesOf(writeGcode(r.job, *p))) {
      if (line.rfind("M3 S1000", 0) == 0) down = true;
      if (line.rfind("M5", 0) == 0 || line.rfind("M3 S0", 0) == 0) down = false;
      if (!down || line.rfind("G1 ", 0) != 0) continue;
      const auto w = wordsOf(line);
      const JointAngles commanded{radFromDeg(w.at('X')), radFromDeg(w.at('Y'))};
      believed.push_back(*calibration::penPosition(calibration::parametersOf(*p), p->assembly, commanded));
      drawn.push_back(*calibration::penPosition(test::trueMakerPlotter(), p->assembly, commanded));
    }
    ASSERT_GT(drawn.size(), 4u);
    const calibration::ShapeError e = calibration::shapeError(drawn, believed);
    std::printf("%s: 60 mm square via G-code, shape error max %.3f mm over %zu points\n",
                p->calibration ? "calibrated" : "nominal", e.maxMm, drawn.size());
    if (p->calibration) {
      EXPECT_LE(e.maxMm, 0.1);
    } else {
      EXPECT_GT(e.maxMm, 0.3);
    }
  }
}

}  // namespace
}  // namespace fivebar
