// SPDX-License-Identifier: GPL-3.0-or-later
// Hoang's accuracy pattern (Hoang et al. 2015): 10 parallel lines, 40 mm long, 10 mm apart, drawn
// to show a machine's straightness and length errors before and after calibration; and the
// figures computed from points measured along the drawn lines (in any paper frame).
#pragma once

#include <optional>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {

inline constexpr int kAccuracyLineCount = 10;
inline constexpr double kAccuracyLineLengthMm = 40.0;
inline constexpr double kAccuracyLineSpacingMm = 10.0;

struct AccuracyLine {
  Vec2 startMm = Vec2::Zero();  // machine frame
  Vec2 endMm = Vec2::Zero();
};
struct AccuracyPattern {
  std::vector<AccuracyLine> lines;  // kAccuracyLineCount, in drawing order
};

// The pattern centred on `centerMm`, lines along `direction` (unit vector, machine frame).
AccuracyPattern accuracyPatternAt(const Vec2& centerMm, const Vec2& direction);

// The pattern placed as near as possible to the centre of the profile's safe area (default
// working mode), lines along x or y, every point at least `clearanceMm` inside it (checkPose on
// points 2 mm apart and around them). nullopt when it fits nowhere.
std::optional<AccuracyPattern> placeAccuracyPattern(const MachineProfile& profile,
                                                    double clearanceMm = 3.0);

// Figures of one drawn line from points measured along it (paper frame, >= 2 points, ordered from
// its start to its end): straightness = largest distance of a point from the best-fit line
// (total least squares); length = distance between the first and last point projected on it.
struct LineAccuracy {
  double straightnessMm = 0.0;
  double lengthMm = 0.0;
  double lengthErrorMm = 0.0;  // lengthMm - nominal
};
struct AccuracyFigures {
  std::vector<LineAccuracy> lines;
  double maxStraightnessMm = 0.0;
  double rmsStraightnessMm = 0.0;
  double maxAbsLengthErrorMm = 0.0;
  double rmsLengthErrorMm = 0.0;
};
// Lines with fewer than two points, or two coincident points, are an error: nullopt.
std::optional<AccuracyFigures> accuracyFigures(const std::vector<std::vector<Vec2>>& measuredLines,
                                               double nominalLengthMm = kAccuracyLineLengthMm);

}  // namespace fivebar
