// SPDX-License-Identifier: GPL-3.0-or-later
// Built-in machine presets (conventions.md "Seed machines", plus a default hobby plotter).
// Each preset is a complete, valid profile; docs/profile-schema.md lists their values.
#include <cmath>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/junction_deviation.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {
namespace {

struct PresetSpec {
  const char* name;
  Geometry geometry;
  // Joint limits, degrees, on the continuous motor angles.
  double theta1MinDeg, theta1MaxDeg, theta2MinDeg, theta2MaxDeg;
  // Home pose: the ++ inverse kinematics of this machine-frame point (mm).
  double homeXMm, homeYMm;
  double stepsPerDeg;       // $100/$101
  double maxSpeedDegPerMin; // $110/$111
  double maxAccelDegPerS2;  // $120/$121
  double drawSpeedMmPerS, travelSpeedMmPerS;
};

// Limits for the elbows-out (++) working mode: arm 1's angle is the chord angle plus the elbow
// angle (0..360 deg in practice), arm 2's the mirror image; the limits leave the whole ++
// workspace reachable while keeping each motor to less than one turn (cables, hard stops).
constexpr PresetSpec kPresets[] = {
    // Hoang et al. 2015: AC servos through 1:1, fast.
    {"hoang2015", {70, 200, 70, 200, 250}, -45, 270, -90, 225, 0, 150, 35.5556, 36000, 3000, 100,
     300},
    // Dai et al. 2022: direct-drive SCARA, all links equal.
    {"dai2022", {135, 135, 135, 135, 180}, -45, 270, -90, 225, 0, 180, 35.5556, 18000, 1500, 80,
     200},
    // The 5R IK/FK article's example constants (L1=L4=40, L2=L3=60, L5=30): a desk toy.
    {"article5r", {40, 60, 40, 60, 30}, -45, 270, -90, 225, 0, 70, 35.5556, 10800, 1000, 30, 60},
    // A hobby pen plotter with NEMA17 steppers, 16 microsteps and 4:1 belt reduction
    // (200*16*4/360 = 35.56 steps/deg). Its ++ singularity-free workspace (15 deg type II
    // margin) holds an A5 sheet (210 x 148 mm) in landscape: docs/profile-schema.md.
    // Pen-up travel at 400 mm/s: the motors' limits set the travel speed (issue 16).
    {"maker-plotter", {100, 180, 100, 180, 90}, -45, 270, -90, 225, 0, 170, 35.5556, 9000, 600,
     40, 400},
};

MachineProfile build(const PresetSpec& s) {
  MachineProfile p;
  p.name = s.name;
  p.geometry = s.geometry;
  p.limits = {radFromDeg(s.theta1MinDeg), radFromDeg(s.theta1MaxDeg), radFromDeg(s.theta2MinDeg),
              radFromDeg(s.theta2MaxDeg)};
  p.motors.stepsPerDeg1 = p.motors.stepsPerDeg2 = s.stepsPerDeg;
  p.motors.maxSpeedRadPerS1 = p.motors.maxSpeedRadPerS2 = radFromDeg(s.maxSpeedDegPerMin / 60.0);
  p.motors.maxAccelRadPerS2_1 = p.motors.maxAccelRadPerS2_2 = radFromDeg(s.maxAccelDegPerS2);
  p.tool = ToolSettings{};  // pen servo: M3 S1000 down, S0 up
  p.defaultMode = WorkingMode::PlusPlus;
  p.assembly = AssemblyMode::Plus;
  p.typeIIMarginRad = radFromDeg(15.0);
  p.typeIMarginRad = radFromDeg(2.0);
  p.drawSpeedMmPerS = s.drawSpeedMmPerS;
  p.travelSpeedMmPerS = s.travelSpeedMmPerS;
  const IkResult home = inverse(s.geometry, Vec2(s.homeXMm, s.homeYMm), WorkingMode::PlusPlus);
  // The home point is chosen inside every preset's workspace; keep the angles inside the limits.
  p.homeAngles.theta1 = unwrapNear(home.angles.theta1, 0.5 * (p.limits.theta1Min + p.limits.theta1Max));
  p.homeAngles.theta2 = unwrapNear(home.angles.theta2, 0.5 * (p.limits.theta2Min + p.limits.theta2Max));
  p.motors.junctionDeviationDeg = junctionDeviationDegFor(p, kCorneringToleranceMm);
  return p;
}

}  // namespace

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const PresetSpec& s : kPresets) names.emplace_back(s.name);
  return names;
}

std::optional<MachineProfile> preset(const std::string& name) {
  // Built once (the $11 derivation samples the workspace, a few ms).
  static const std::vector<MachineProfile> built = [] {
    std::vector<MachineProfile> all;
    for (const PresetSpec& s : kPresets) all.push_back(build(s));
    return all;
  }();
  for (const MachineProfile& p : built)
    if (name == p.name) return p;
  return std::nullopt;
}

}  // namespace fivebar
