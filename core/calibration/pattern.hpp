// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration pattern (docs/calibration-pattern.md): numbered marks at motor poses spread over
// the safe working area, edge included; rows of three marks whose middle one is approached with
// one motor reversed, to measure that motor's backlash; and Hoang's accuracy pattern
// (accuracy_pattern.hpp). Every mark is a dot (the pen lowered at the pose, no motion, after a
// pen-up approach that ends with each motor moving in a known direction) inside a ring that
// makes it easy to find, with its number beside it. Machine frame, mm, rad.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/calibration/accuracy_pattern.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/strokes.hpp"

namespace fivebar {

enum class MarkKind { Grid, Backlash };
// Direction of a motor's last motion before the pen goes down on a mark.
enum class Approach { Plus, Minus };

struct PatternMark {
  int id = 0;                        // 1, 2, ... as drawn beside the mark
  JointAngles q;                     // commanded motor angles (rad, continuous), as in the G-code
  Vec2 nominalMm = Vec2::Zero();     // forward kinematics of q in the profile, machine frame
  MarkKind kind = MarkKind::Grid;
  Approach approach1 = Approach::Plus;
  Approach approach2 = Approach::Plus;
  int group = 0;     // backlash row number (1, 2, ...); 0 for grid marks
  int motor = 0;     // backlash row: the motor whose backlash the row measures (1 or 2); else 0
  int rowIndex = 0;  // position in its row: 0, 1 (the reversed one), 2
};

struct PatternOptions {
  int gridMarks = 25;             // marks for the geometric fit (fewer when the area is small)
  int backlashRowsPerMotor = 2;   // rows of three marks per motor; 0: no backlash rows
  double ringRadiusMm = 2.5;      // ring drawn around each dot
  double digitHeightMm = 3.0;
  double clearanceMm = 9.0;       // around each mark: ring, number and approach must be safe
  double minSpacingMm = 14.0;     // between mark centres
  double approachRad = radFromDeg(2.0);  // pen-up excursion before a dot (more than any play)
  bool accuracyLines = true;      // add Hoang's accuracy pattern where it fits
};

struct CalibrationPattern {
  std::vector<PatternMark> marks;  // ordered by id
  // Strokes in plotting order (a short tour in joint space from the home pose), machine frame:
  // for each mark its ring, its number, its dot (a one-point stroke); the accuracy lines as one
  // item of the tour. dotStroke[i] is marks[i]'s dot.
  std::vector<Stroke> strokes;
  std::vector<int> dotStroke;
  std::optional<AccuracyPattern> accuracy;  // nullopt when it does not fit
  WorkingMode mode = WorkingMode::PlusPlus;
  double ringRadiusMm = 2.5;
};

struct PatternResult {
  std::optional<CalibrationPattern> pattern;
  Message error;  // why there is none (translatable, context CalibrationPattern)
};

// Marks for `profile` (its calibration left out) in its default working mode; every mark, its ring and number area and its
// approach excursions pass checkPose / checkJointMove (workspace, joint limits, type I and II
// margins). Fails when fewer than kMinPatternMarks grid marks fit.
inline constexpr int kMinPatternMarks = 8;
PatternResult makeCalibrationPattern(const MachineProfile& profile,
                                     const PatternOptions& options = {});

// Hoang's accuracy lines alone as a pattern (no marks): placeAccuracyPattern's lines, one stroke
// each, in the profile's default mode; nullopt when they do not fit in its safe area.
std::optional<CalibrationPattern> accuracyOnlyPattern(const MachineProfile& profile);

// The pattern planned by the one planner (planStrokes, in order, with the profile's calibration
// left out: no zero offsets, no backlash compensation; the pattern measures the raw machine), with each dot's approach inserted before it lowers the pen:
// a pen-up move away by approachRad against each motor's approach direction and back, both
// checked with checkJointMove. Times are estimated again afterwards.
PlanResult planCalibrationPattern(const CalibrationPattern& pattern, const MachineProfile& profile,
                                  double approachRad = PatternOptions{}.approachRad);

// The pattern planned for `profile` AS IT IS, its calibration applied by the planner (zero offsets,
// pen offset, backlash compensation), without approach excursions (the compensation takes up the
// play whatever the approach): the verification sheet and the accuracy lines drawn after
// calibration, which show what the calibration achieves. Without a calibration it draws what
// planCalibrationPattern draws, less the approaches. The path tolerance is
// kVerificationToleranceMm, so that the lines' straightness shows the machine rather than the
// planner's joint-linear chords (0.1 mm by default).
inline constexpr double kVerificationToleranceMm = 0.02;
PlanResult planVerificationPattern(const CalibrationPattern& pattern, const MachineProfile& profile);

// The pattern as an SVG picture (machine frame, y up on the page, 1 user unit = 1 mm): strokes as
// polylines, dots as small discs.
std::string patternSvg(const CalibrationPattern& pattern, double penWidthMm = 0.4);

}  // namespace fivebar
