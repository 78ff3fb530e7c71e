// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/calibrate.hpp"

#include <algorithm>

namespace fivebar::calibration {

CalibrationOutcome calibrate(const CalibrationInput& input, bool backlashRequired) {
  CalibrationOutcome out;
  if (!input.patternMarks.empty()) {
    out.backlash = estimateBacklash(input.patternMarks, input.measuredById);
    if (!out.backlash->ok() && backlashRequired) {
      out.stage = CalibrationStage::Backlash;
      out.error = out.backlash->error;
      return out;
    }
  }
  out.fit = input.distances.empty() ? fitMarks(input.nominal, input.marks, input.options)
                                    : fitDistances(input.nominal, input.poses, input.distances,
                                                   input.options);
  if (!out.fit.ok()) {
    out.stage = CalibrationStage::Fit;
    out.error = out.fit.reason;
    return out;
  }
  MachineProfile calibrated = calibratedProfile(input.nominal, out.fit, input.dateIso);
  if (out.backlash && out.backlash->ok() && calibrated.calibration) {
    const MotorPlay& play = out.backlash->play;
    out.clampedMotor1 = play.motor1Rad < 0.0;
    out.clampedMotor2 = play.motor2Rad < 0.0;
    calibrated.calibration->backlashRad1 = std::max(0.0, play.motor1Rad);
    calibrated.calibration->backlashRad2 = std::max(0.0, play.motor2Rad);
  }
  if (const std::vector<ValidationIssue> issues = validate(calibrated); !issues.empty()) {
    out.stage = CalibrationStage::Validation;
    out.error = issues.front().message;
    return out;
  }
  out.stage = CalibrationStage::Calibrated;
  out.profile = std::move(calibrated);
  return out;
}

}  // namespace fivebar::calibration
