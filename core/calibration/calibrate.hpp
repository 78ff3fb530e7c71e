// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration door: measurements of the drawn pattern in, a calibrated profile out. One
// sequence for every front end (`fivebar calibrate fit`, the studio's calibration wizard): the
// backlash rows' play (estimateBacklash), the fit of the marks or of the ruler's distances
// (fitMarks / fitDistances), calibratedProfile, the play written in (a negative estimate, the
// measurement's noise, clamped to 0) and the profile's validation. Front ends word the outcome.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/backlash.hpp"
#include "core/calibration/fit.hpp"
#include "core/calibration/pattern.hpp"
#include "core/machine/profile.hpp"
#include "core/support/message.hpp"

namespace fivebar::calibration {

struct CalibrationInput {
  MachineProfile nominal;  // the profile the pattern was drawn with
  // Either marks measured on the sheet (any paper frame) ...
  std::vector<MarkMeasurement> marks;
  // ... or, with `distances` non-empty, a ruler's distances between marks of known poses.
  std::vector<MarkPose> poses;
  std::vector<DistanceMeasurement> distances;
  // The backlash rows: the pattern's marks and where each was measured (by mark id, the sheet's
  // frame). Empty: backlash not measured (the nominal profile's play is kept).
  std::vector<PatternMark> patternMarks;
  std::map<int, Vec2> measuredById;
  FitOptions options;
  std::string dateIso;  // the calibration's date (calibratedProfile)
};

// Where the door stopped; Calibrated when `profile` holds the result.
enum class CalibrationStage { Backlash, Fit, Validation, Calibrated };

struct CalibrationOutcome {
  CalibrationStage stage = CalibrationStage::Fit;
  std::optional<BacklashEstimate> backlash;  // when backlash rows were given (ok or not)
  CalibrationFit fit;
  std::optional<MachineProfile> profile;     // the calibrated profile (stage Calibrated)
  Message error;                             // why not, stage Backlash / Fit / Validation
  // A motor whose play estimate was negative (noise on a machine without play), written as 0.
  bool clampedMotor1 = false, clampedMotor2 = false;
  bool ok() const { return stage == CalibrationStage::Calibrated; }
};

// With `backlashRequired` a failed play estimate refuses (the CLI, asked for it with --reversed);
// without it the profile is calibrated and keeps its play (the wizard says why it was not measured).
CalibrationOutcome calibrate(const CalibrationInput& input, bool backlashRequired = false);

}  // namespace fivebar::calibration
