// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/calibration_state.hpp"

#include "i18n/translated.hpp"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <random>

#include "core/calibration/backlash.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/output/gcode.hpp"

namespace fivebar::widgets::calibration {

std::optional<CalibrationPattern> makePattern(const MachineProfile& profile, PatternKind kind,
                                              int gridMarks, QString* error) {
  if (kind == PatternKind::AccuracyOnly) {
    auto pattern = accuracyOnlyPattern(profile);
    if (!pattern && error) *error = session::accuracyPatternDoesNotFit();
    return pattern;
  }
  PatternOptions options;
  options.gridMarks = gridMarks;
  PatternResult r = makeCalibrationPattern(profile, options);
  if (!r.pattern) {
    if (error) *error = translated(r.error);
    return std::nullopt;
  }
  return r.pattern;
}

std::optional<AccuracySummary> summariseLines(const std::vector<LineMeasure>& lines) {
  AccuracySummary a;
  double sumS = 0.0, sumL = 0.0;
  for (const LineMeasure& l : lines) {
    if (!l.lengthMm || !l.straightnessMm) continue;
    const double e = *l.lengthMm - kAccuracyLineLengthMm;
    a.maxStraightnessMm = std::max(a.maxStraightnessMm, std::abs(*l.straightnessMm));
    a.maxAbsLengthErrorMm = std::max(a.maxAbsLengthErrorMm, std::abs(e));
    sumS += *l.straightnessMm * *l.straightnessMm;
    sumL += e * e;
    ++a.lines;
  }
  if (a.lines == 0) return std::nullopt;
  a.rmsStraightnessMm = std::sqrt(sumS / a.lines);
  a.rmsLengthErrorMm = std::sqrt(sumL / a.lines);
  return a;
}

}  // namespace fivebar::widgets::calibration
