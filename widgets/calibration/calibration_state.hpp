// SPDX-License-Identifier: GPL-3.0-or-later
// What the calibration wizard (Machine > Calibrate...) carries from step to step: the pattern it
// draws and the accuracy lines' figures. The simulated sheet (what a true machine draws, measured)
// is the session's (session/simulated_sheet.hpp), beside the simulated board.
// Machine frame, mm and rad inside; degrees only in the widgets.
#pragma once

#include <QString>
#include <optional>
#include <vector>

#include "core/calibration/accuracy_pattern.hpp"
#include "core/calibration/pattern.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/backlash_compensation.hpp"
#include "core/planning/job.hpp"
#include "session/simulated_sheet.hpp"

namespace fivebar::widgets::calibration {

// The simulated sheet and the true machine, as the wizard's pages name them.
using fivebar::TrueMachine;
using fivebar::trueMachineProfile;
using session::DistanceRow;
using session::markShapeError;
using session::measureSimulatedDistances;
using session::measureSimulatedSheet;
using session::ShapeFigures;
using session::simulatedAccuracy;
using session::simulatedTrace;
using session::TableMark;
using session::trueMarkCentre;

// The pattern kinds the wizard offers.
enum class PatternKind { Marks, AccuracyOnly };

// The pattern for `profile`: marks (with Hoang's lines where they fit), or the accuracy lines
// alone. Empty pattern with *error when nothing fits.
std::optional<CalibrationPattern> makePattern(const MachineProfile& profile, PatternKind kind,
                                              int gridMarks, QString* error);

// One accuracy line as measured with a ruler: its length and its straightness (the widest gap
// between the line and a straight edge), mm; empty when not measured.
struct LineMeasure {
  std::optional<double> lengthMm;
  std::optional<double> straightnessMm;
};
// The figure of the accuracy lines: over the lines with both values, the largest and RMS
// straightness and length error (against kAccuracyLineLengthMm). nullopt when no line has both.
struct AccuracySummary {
  int lines = 0;
  double maxStraightnessMm = 0.0, rmsStraightnessMm = 0.0;
  double maxAbsLengthErrorMm = 0.0, rmsLengthErrorMm = 0.0;
};
std::optional<AccuracySummary> summariseLines(const std::vector<LineMeasure>& lines);

}  // namespace fivebar::widgets::calibration
