// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration door (core/calibration/calibrate.hpp): the one sequence the CLI's `calibrate fit`
// and the studio's wizard both run.
#include <gtest/gtest.h>

#include "calibration_scenario.hpp"
#include "core/calibration/calibrate.hpp"
#include "core/calibration/pattern.hpp"

namespace fivebar {
namespace {

using namespace fivebar::calibration;

CalibrationInput marksInput() {
  CalibrationInput in;
  in.nominal = *preset("maker-plotter");
  in.marks = test::measuredMarks(in.nominal, 7, false);
  in.dateIso = "2026-12-04T00:00:00Z";
  return in;
}

TEST(CalibrateDoor, MarksGiveTheProfileTheStepsByHandGive) {
  const CalibrationInput in = marksInput();
  const CalibrationOutcome out = calibrate(in);
  ASSERT_TRUE(out.ok()) << out.error;
  ASSERT_TRUE(out.profile.has_value());
  EXPECT_FALSE(out.backlash.has_value());  // no backlash rows given
  // The same as fitting and applying by hand.
  const CalibrationFit fit = fitMarks(in.nominal, in.marks);
  ASSERT_TRUE(fit.ok());
  const MachineProfile byHand = calibratedProfile(in.nominal, fit, in.dateIso);
  EXPECT_EQ(out.profile->geometry, byHand.geometry);
  ASSERT_TRUE(out.profile->calibration.has_value());
  EXPECT_EQ(out.profile->calibration->zeroOffsetRad1, byHand.calibration->zeroOffsetRad1);
  // And it found the true machine.
  EXPECT_NEAR(out.profile->geometry.a2, test::trueMakerPlotter().geometry.a2, 0.15);
  EXPECT_TRUE(validate(*out.profile).empty());
}

// A calibrated profile is this machine's, not the preset's: it gets its own name (with the
// calibration's day), and calibrating it again keeps one mark with the new day.
TEST(CalibrateDoor, ACalibratedProfileGetsItsOwnName) {
  const CalibrationInput in = marksInput();
  const CalibrationOutcome out = calibrate(in);
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_EQ(out.profile->name, "maker-plotter (calibrated 2026-12-04)");
  EXPECT_NE(out.profile->name, in.nominal.name);
  EXPECT_EQ(calibratedProfileName(out.profile->name, "2027-01-05T10:00:00Z"), "maker-plotter (calibrated 2027-01-05)");
  EXPECT_EQ(calibratedProfileName("my plotter", ""), "my plotter (calibrated)");
  EXPECT_EQ(calibratedProfileName("my plotter (calibrated)", "2027-01-05"), "my plotter (calibrated 2027-01-05)");
}

TEST(CalibrateDoor, BacklashRowsNotMeasuredRefuseOnlyWhenRequired) {
  CalibrationInput in = marksInput();
  const PatternResult pattern = makeCalibrationPattern(in.nominal, PatternOptions{});
  ASSERT_TRUE(pattern.pattern.has_value());
  in.patternMarks = pattern.pattern->marks;  // rows given, none of their marks measured
  const CalibrationOutcome required = calibrate(in, true);
  EXPECT_EQ(required.stage, CalibrationStage::Backlash);
  EXPECT_FALSE(required.profile.has_value());
  EXPECT_FALSE(required.error.empty());
  const CalibrationOutcome optional = calibrate(in, false);
  ASSERT_TRUE(optional.ok()) << optional.error;
  ASSERT_TRUE(optional.backlash.has_value());
  EXPECT_FALSE(optional.backlash->ok());
  // The nominal profile's play is kept (none).
  EXPECT_EQ(optional.profile->calibration->backlashRad1, 0.0);
}

TEST(CalibrateDoor, AFitThatFailsSaysWhyAndWritesNoProfile) {
  CalibrationInput in = marksInput();
  in.marks.resize(3);  // far too few marks
  const CalibrationOutcome out = calibrate(in);
  EXPECT_EQ(out.stage, CalibrationStage::Fit);
  EXPECT_FALSE(out.profile.has_value());
  EXPECT_EQ(out.error.text(), out.fit.reason.text());
  EXPECT_FALSE(out.error.empty());
}

}  // namespace
}  // namespace fivebar
