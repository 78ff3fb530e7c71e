// SPDX-License-Identifier: GPL-3.0-or-later
// A G-code job as the machine link sees it: the lines worth sending (comments and spaces
// removed), and for each line what it does to the pen and where it moves the joints. This is
// what progress, resume and framing are computed from. Pure; angles in degrees (G-code X =
// theta1, Y = theta2), Z in mm, as in the file.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/machine/profile.hpp"

namespace fivebar::stream {

using Point2 = std::array<double, 2>;  // theta1, theta2 in degrees

// Whether the tool draws for the given spindle state / S value / Z height (profile rules):
// pen servo: M3/M4 with S nearer penDownS than penUpS; laser: M3/M4 with S > 0; Z axis: Z on
// the zDown side of the midpoint between zUp and zDown.
bool penDownFor(const ToolSettings& tool, bool spindleOn, double spindleS, double zMm);

struct JobLine {
  int fileLine = 0;          // 1-based line number in the file
  std::string text;          // compacted text sent to the board (non-empty)
  bool motion = false;       // produces a planner block (a move of at least one step)
  bool penDownDuring = false;  // a motion drawn with the pen down (a stroke segment)
  bool penDownAfter = false;   // pen state once this line has run
  bool penDownPoint = false;   // see lastPenDownPoint
  Point2 endDeg{0.0, 0.0};   // X/Y work position after this line
  double feedPerMin = 0.0;   // modal F after this line
  bool rapidModal = true;    // modal motion after this line: G0 (true) or G1
};

struct JobRules {
  ToolSettings tool;           // how pen up / down is recognised and commanded
  double stepsPerDeg1 = 0.0;   // when > 0: moves shorter than half a step are not blocks
  double stepsPerDeg2 = 0.0;
  Point2 startDeg{0.0, 0.0};   // position before the first line (only for the first segment)
};
JobRules rulesFor(const MachineProfile& profile);

struct GcodeJob {
  std::vector<JobLine> lines;        // every non-empty line, in order
  std::vector<std::string> issues;   // "line 12: ..." problems that make streaming unsafe
  bool relativeMoves = false;        // G91 used: resume cannot compute targets
};

// Reads the job text. Lines over 80 characters after compaction, arcs (G2/G3), lines GRBL
// would reject as unparsable are reported in issues with their line number.
GcodeJob parseJob(std::string_view text, const JobRules& rules);

// The job's pen-down path: strokes as sequences of joint positions (deg).
std::vector<std::vector<Point2>> strokesOf(const GcodeJob& job, const JobRules& rules);

// Index of the last "pen-down point" at or before line index `completed`: a motion line drawn
// with the pen down, or the travel that ends where a stroke starts. nullopt when none.
std::optional<std::size_t> lastPenDownPoint(const GcodeJob& job, std::size_t completed);

// G-code to raise / lower the tool per the profile (with the dwell).
std::vector<std::string> penUpCommands(const ToolSettings& tool);
std::vector<std::string> penDownCommands(const ToolSettings& tool);

// "G0 X12.345 Y-6.789": a move to joint angles (deg), 3 decimals (GRBL's resolution).
std::string moveTo(const Point2& targetDeg, bool rapid, double feedPerMin = 0.0);

}  // namespace fivebar::stream
