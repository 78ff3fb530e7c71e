// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration fit (core/calibration/fit.hpp) on the simulated maker-plotter of issue 13's goal:
// shape error over the working area before and after, a 60 mm square, outliers named, both paper
// mirror hypotheses, the distance form, and refusals (too few marks, ill-conditioned).
#include <gtest/gtest.h>

#include <cmath>

#include "calibration_scenario.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

using namespace calibration;

const MachineProfile& nominal() {
  static const MachineProfile p = *preset("maker-plotter");
  return p;
}
const Rect& area() {
  static const Rect r = test::workingArea(nominal());
  return r;
}

const ParameterEstimate& estimate(const CalibrationFit& f, const std::string& name) {
  for (const ParameterEstimate& e : f.estimates)
    if (e.name == name) return e;
  throw std::runtime_error("no estimate " + name);
}

TEST(CalibrationFit, GoalShapeErrorOverTheWorkingArea) {
  ASSERT_GE(area().width(), 200.0);
  const ShapeError before = test::areaShapeError(nominal(), area());
  for (const bool mirrored : {false, true}) {
    const auto marks = test::measuredMarks(nominal(), test::seed(), mirrored);
    const CalibrationFit fit = fitMarks(nominal(), marks);
    ASSERT_TRUE(fit.ok()) << fit.reason;
    EXPECT_EQ(fit.paper->mirrored, mirrored);
    EXPECT_TRUE(fit.outlierIds.empty());
    EXPECT_EQ(fit.used, 25);  // the final fit takes the held-out marks too
    EXPECT_EQ(fit.heldOut, 5);
    const MachineProfile calibrated = calibratedProfile(nominal(), fit, "2026-12-01");
    EXPECT_TRUE(validate(calibrated).empty());
    const ShapeError after = test::areaShapeError(calibrated, area());
    std::printf("shape error over %.0f x %.0f mm: before max %.3f rms %.3f mm, after max %.3f rms %.3f mm "
                "(held-out %.3f mm, cond %.0f)\n",
                area().width(), area().height(), before.maxMm, before.rmsMm, after.maxMm, after.rmsMm,
                fit.heldOutRmsMm, fit.conditionNumber);
    EXPECT_GT(before.maxMm, 1.5);
    EXPECT_LE(after.maxMm, 0.1);
    EXPECT_LE(fit.heldOutRmsMm, 0.2);  // includes the 0.05 mm noise of both coordinates
    EXPECT_GT(fit.beforeRmsMm, 10.0 * fit.afterRmsMm);
    // The fitted parameters lie within a few standard deviations of the truth.
    const MachineParameters truth = test::trueMakerPlotter();
    const double truthMm[] = {truth.geometry.a1, truth.geometry.b1, truth.geometry.a2, truth.geometry.b2, truth.geometry.w};
    const char* names[] = {"a1", "b1", "a2", "b2", "w"};
    for (int i = 0; i < 5; ++i) {
      const ParameterEstimate& e = estimate(fit, names[i]);
      EXPECT_GT(e.stdDev, 0.0) << names[i];
      EXPECT_NEAR(e.value, truthMm[i], 5.0 * e.stdDev + 0.01) << names[i];
    }
    const ParameterEstimate& z1 = estimate(fit, "zeroOffset1");
    EXPECT_NEAR(z1.value, degFromRad(truth.zeroOffsetRad1), 5.0 * z1.stdDev + 0.005);
  }
}

TEST(CalibrationFit, A60MmSquareIsDrawnWithin0_1Mm) {
  const auto marks = test::measuredMarks(nominal(), test::seed(), false);
  const CalibrationFit fit = fitMarks(nominal(), marks);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  const MachineProfile calibrated = calibratedProfile(nominal(), fit, "2026-12-01");
  const Vec2 c((area().xMin + area().xMax) / 2, (area().yMin + area().yMax) / 2);
  std::vector<Vec2> square;
  const Vec2 corners[] = {c + Vec2(-30, -30), c + Vec2(30, -30), c + Vec2(30, 30), c + Vec2(-30, 30)};
  for (int k = 0; k < 4; ++k)
    for (int s = 0; s < 60; ++s) square.push_back(corners[k] + (corners[(k + 1) % 4] - corners[k]) * (s / 60.0));
  const ShapeError before = shapeError(test::drawnBy(test::trueMakerPlotter(), nominal(), square), square);
  const ShapeError after = shapeError(test::drawnBy(test::trueMakerPlotter(), calibrated, square), square);
  std::printf("60 mm square: before max %.3f mm, after max %.3f mm\n", before.maxMm, after.maxMm);
  EXPECT_GT(before.maxMm, 0.3);
  EXPECT_LE(after.maxMm, 0.1);
}

TEST(CalibrationFit, AMisMeasuredMarkIsNamedAsOutlier) {
  for (const std::string bad : {"13", "5", "22"}) {  // fitted, held out (every 5th), on the edge
    auto marks = test::measuredMarks(nominal(), test::seed(), true);
    for (auto& m : marks)
      if (m.id == bad) m.paperMm += Vec2(3.0 * std::cos(1.0), 3.0 * std::sin(1.0));
    const CalibrationFit fit = fitMarks(nominal(), marks);
    ASSERT_TRUE(fit.ok()) << fit.reason;
    ASSERT_EQ(fit.outlierIds, std::vector<std::string>{bad});
    for (const MeasurementResidual& r : fit.residuals)
      if (r.id == bad) {
        EXPECT_EQ(r.role, Role::Outlier);
        EXPECT_NEAR(r.residualMm, 3.0, 0.3);
      }
    const ShapeError after = test::areaShapeError(calibratedProfile(nominal(), fit, "2026-12-01"), area());
    EXPECT_LE(after.maxMm, 0.15) << bad;  // 24 marks left; the goal's 0.1 mm is for 25
  }
}

TEST(CalibrationFit, DistancesAloneCalibrateToo) {
  const auto marks = test::measuredMarks(nominal(), test::seed(), false, 0.0);
  std::vector<MarkPose> poses;
  for (const auto& m : marks) poses.push_back({m.id, m.commanded, 0});
  // Every pair of a subset: 40 ruler readings with 0.05 mm noise.
  std::mt19937_64 rng(test::seed());
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<DistanceMeasurement> d;
  for (std::size_t i = 0; i < marks.size(); ++i)
    for (std::size_t j = i + 1; j < marks.size(); j += 3)
      d.push_back({marks[i].id, marks[j].id, (marks[i].paperMm - marks[j].paperMm).norm() + noise(rng), 0});
  const CalibrationFit fit = fitDistances(nominal(), poses, d);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  EXPECT_FALSE(fit.paper);
  const ShapeError after = test::areaShapeError(calibratedProfile(nominal(), fit, "2026-12-01"), area());
  std::printf("distance form, %zu distances: after max %.3f mm, cond %.0f\n", d.size(), after.maxMm, fit.conditionNumber);
  EXPECT_LE(after.maxMm, 0.1);
}

TEST(CalibrationFit, TooFewMarksAreRefusedWithTheCount) {
  auto marks = test::measuredMarks(nominal(), test::seed(), false);
  marks.resize(6);
  const CalibrationFit fit = fitMarks(nominal(), marks);
  EXPECT_EQ(fit.status, FitStatus::TooFewMeasurements);
  EXPECT_EQ(fit.reason.text(), "6 marks are too few for 10 parameters: at least 7 marks are needed");
}

TEST(CalibrationFit, ClusteredMarksAreRefusedAsIllConditioned) {
  // Ten marks within 3 mm of one point cannot tell the link lengths apart.
  const calibration::MachineParameters truth = test::trueMakerPlotter();
  const Vec2 c((area().xMin + area().xMax) / 2, (area().yMin + area().yMax) / 2);
  std::vector<MarkMeasurement> marks;
  for (int i = 0; i < 10; ++i) {
    const Vec2 p = c + Vec2(3.0 * std::cos(i), 3.0 * std::sin(2.0 * i));
    const JointAngles q = *test::commandedFor(nominal(), p);
    marks.push_back({std::to_string(i), q, *penPosition(truth, nominal().assembly, q), 0});
  }
  const CalibrationFit fit = fitMarks(nominal(), marks);
  EXPECT_EQ(fit.status, FitStatus::IllConditioned) << fit.conditionNumber;
  EXPECT_NE(fit.reason.text().find("ill-conditioned"), std::string::npos) << fit.reason;
  EXPECT_TRUE(fit.reason.translatable());
  EXPECT_NE(fit.reason.text().find("spread the marks"), std::string::npos) << fit.reason;
}

TEST(CalibrationFit, PerfectDataRecoverTheTruth) {
  const auto marks = test::measuredMarks(nominal(), test::seed(), false, 0.0);
  const CalibrationFit fit = fitMarks(nominal(), marks);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  const MachineParameters truth = test::trueMakerPlotter();
  EXPECT_NEAR(fit.parameters.geometry.a1, truth.geometry.a1, 1e-4);
  EXPECT_NEAR(fit.parameters.geometry.w, truth.geometry.w, 1e-4);
  EXPECT_NEAR(fit.parameters.zeroOffsetRad1, truth.zeroOffsetRad1, 1e-6);
  EXPECT_NEAR(fit.parameters.zeroOffsetRad2, truth.zeroOffsetRad2, 1e-6);
  EXPECT_LT(fit.afterMaxMm, 1e-4);
}

}  // namespace
}  // namespace fivebar
