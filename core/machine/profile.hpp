// SPDX-License-Identifier: GPL-3.0-or-later
// A machine profile: everything the studio, the planner and the driver need to know about one
// physical five-bar. Stored as versioned JSON (schema: docs/profile-schema.md).
// Inside the core every angle is in radians; the JSON file holds degrees.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/modes.hpp"
#include "core/machine/calibration.hpp"

namespace fivebar {

enum class ToolKind { PenServo, ZAxis, Laser };

struct ToolSettings {
  ToolKind kind = ToolKind::PenServo;
  // Pen servo: M3 S<penDownS> lowers, M5 (or M3 S<penUpS>) raises, each followed by a dwell.
  double penUpS = 0.0;
  double penDownS = 1000.0;
  double penUpDelayS = 0.15;
  double penDownDelayS = 0.15;
  // Z axis: G-code Z in mm.
  double zUpMm = 5.0;
  double zDownMm = 0.0;
  double zFeedMmPerMin = 600.0;
  // Laser: M4 S<laserPowerS> while drawing, M5 (S0) in travel.
  double laserPowerS = 1000.0;
};

struct MotorSettings {
  double stepsPerDeg1 = 35.5556;  // $100: 200 steps * 16 microsteps * 4:1 / 360
  double stepsPerDeg2 = 35.5556;  // $101
  double maxSpeedRadPerS1 = 3.0;  // $110 (stored as deg/min in GRBL)
  double maxSpeedRadPerS2 = 3.0;  // $111
  double maxAccelRadPerS2_1 = 20.0;  // $120 (deg/s^2 in GRBL)
  double maxAccelRadPerS2_2 = 20.0;  // $121
  double junctionDeviationDeg = 0.01;  // $11, in the joint-space units GRBL sees (deg)
};

struct MachineProfile {
  static constexpr int kSchemaVersion = 1;
  std::string name;
  Geometry geometry;
  JointLimits limits;
  MotorSettings motors;
  ToolSettings tool;
  WorkingMode defaultMode = WorkingMode::PlusPlus;  // working mode the machine is built in
  AssemblyMode assembly = AssemblyMode::Plus;       // assembly mode; never changed by a plan
  double drawSpeedMmPerS = 40.0;
  double travelSpeedMmPerS = 80.0;
  double typeIIMarginRad = 0.2618;  // 15 deg: closest allowed approach to a type II singularity
  double typeIMarginRad = 0.0349;   // 2 deg: keeps legs off full stretch/fold
  int baudRate = 115200;
  bool hasHomingSwitches = false;
  JointAngles homeAngles;  // reference pose after $H or "set reference pose"
  // Set once the machine has been calibrated (issue 13). homeAngles and limits are commanded
  // angles (what G-code and GRBL see); the kinematics uses commanded + zero offset.
  std::optional<MachineCalibration> calibration;
};

struct ProfileLoad {
  std::optional<MachineProfile> profile;  // set when loading succeeded
  std::vector<ValidationIssue> issues;    // field paths like "geometry.a1", "motors.stepsPerDeg1"
};

// Built-in presets: "hoang2015", "dai2022", "article5r" (conventions.md) and "maker-plotter".
std::vector<std::string> presetNames();
std::optional<MachineProfile> preset(const std::string& name);

// Full validation (geometry, limits, motors, tool, speeds, margins).
std::vector<ValidationIssue> validate(const MachineProfile& p);

// JSON text <-> profile. Errors name the field (and line where the JSON itself is broken).
std::string toJson(const MachineProfile& p);
ProfileLoad profileFromJson(const std::string& text, const std::string& sourceName);
ProfileLoad loadProfile(const std::string& path);
// Atomic save: writes a temporary file beside `path`, flushes it, then renames it over `path`.
// Returns an error message, or an empty string on success.
std::string saveProfile(const MachineProfile& p, const std::string& path);

// "--machine PRESET|FILE": a preset name, otherwise a file path.
ProfileLoad resolveMachine(const std::string& presetOrPath);

}  // namespace fivebar
