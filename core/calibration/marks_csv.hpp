// SPDX-License-Identifier: GPL-3.0-or-later
// MARKS.csv (what `fivebar calibrate pattern` writes: the marks as commanded) and MEASURED.csv
// (where they were found on the sheet; what `fivebar calibrate fit` reads). Formats:
// docs/calibration-pattern.md. Angles in degrees as sent in the G-code, lengths in mm.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/support/message.hpp"
#include "core/calibration/pattern.hpp"

namespace fivebar {

// "id,theta1_deg,theta2_deg,x_mm,y_mm,kind,approach1,approach2,group,motor,ring_radius_mm"
inline constexpr const char* kMarksCsvHeader =
    "id,theta1_deg,theta2_deg,x_mm,y_mm,kind,approach1,approach2,group,motor,ring_radius_mm";
// "id,theta1_deg,theta2_deg,x_mm,y_mm"
inline constexpr const char* kMeasuredCsvHeader = "id,theta1_deg,theta2_deg,x_mm,y_mm";

// Angles with 4 decimals (the G-code's), positions with 4.
std::string marksCsv(const CalibrationPattern& pattern);

// A mark as read back from MARKS.csv: the pattern mark (q in rad from the degrees written) and
// its ring radius.
struct MarkRecord {
  PatternMark mark;
  double ringRadiusMm = 0.0;
};
struct MarksLoad {
  std::vector<MarkRecord> marks;
  Message error;  // "MARKS.csv:7: theta2_deg: 'abc' is not a number"; empty when ok (translatable)
  bool ok() const { return error.empty(); }
};
// Parses MARKS.csv text; `source` names it in errors. Checks the header, every field, unique ids.
MarksLoad parseMarksCsv(const std::string& text, const std::string& source);
MarksLoad loadMarksCsv(const std::string& path);

// A measured mark: id, commanded angles (deg, as in MARKS.csv), measured position (paper frame).
struct MeasuredMark {
  int id = 0;
  double theta1Deg = 0.0;
  double theta2Deg = 0.0;
  Vec2 measuredMm = Vec2::Zero();
};
// The marks' angles are written with MARKS.csv's text (4 decimals), positions with 4 decimals.
std::string measuredCsv(const std::vector<MeasuredMark>& marks);
struct MeasuredLoad {
  std::vector<MeasuredMark> marks;
  Message error;  // translatable
  bool ok() const { return error.empty(); }
};
MeasuredLoad parseMeasuredCsv(const std::string& text, const std::string& source);

}  // namespace fivebar
