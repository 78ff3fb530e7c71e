// SPDX-License-Identifier: GPL-3.0-or-later
// The one table of a machine profile's numeric fields: for each its JSON path, label, unit,
// valid range and decimals, with accessors in the file's units (deg, deg/min, deg/s^2, mm, s).
// Validation (profile.cpp), the JSON reader and writer (profile.cpp) and the studio's profile
// editor (widgets/panels/profile_editor.cpp) all read this table; conversions come from units.hpp.
// Non-numeric members (name, modes, tool kind, homing switches) are handled beside it.
#pragma once

#include <string>
#include <vector>

#include "core/machine/profile.hpp"

namespace fivebar {

// What validation requires of a field's value (in file units).
enum class FieldRule {
  Positive,     // finite and > 0
  NonNegative,  // finite and >= 0
  Between,      // finite and within [validMin, validMax]
  Finite,       // finite; further checks are cross-field (limits pair, home within limits, z up > z down)
};

struct ProfileField {
  const char* path;      // JSON path and validate() field, e.g. "motors.maxSpeedDegPerMin1"
  const char* label;     // what a maker reads, e.g. "Motor 1 maximum speed"
  const char* unit;      // display unit in the file's terms ("mm", "deg", "deg/min", ...); "" when none
  FieldRule rule;
  double validMin;       // with Between; otherwise informative (0 for Positive/NonNegative)
  double validMax;       // with Between; otherwise +infinity
  double inputMin;       // range an editor accepts for typing (wider than valid, so errors can show)
  double inputMax;
  int decimals;          // shown in an editor
  bool integer;          // written and read as a JSON integer
  bool required;         // must be present when its section is present
  bool roundOnWrite;     // written rounded to 1e-9 (converted values)
  double (*get)(const MachineProfile&);    // value in file units
  void (*set)(MachineProfile&, double);    // from file units
};

// All numeric fields, grouped by section in file order: geometry, limits, motors, tool, motion,
// safety, connection, home, calibration. Reading a calibration field of an uncalibrated profile
// gives its default; setting one creates the section (and, for penOffset*, the pen offset).
const std::vector<ProfileField>& profileFields();
// The field at `path`, or nullptr.
const ProfileField* findProfileField(const std::string& path);
// Section ("geometry") and key ("a1") of a path.
std::string sectionOf(const ProfileField& f);
std::string keyOf(const ProfileField& f);
// The validation issue of one field's value against its rule, if any (message names the path).
std::vector<ValidationIssue> checkField(const ProfileField& f, double value);

}  // namespace fivebar
