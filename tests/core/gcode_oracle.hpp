// SPDX-License-Identifier: GPL-3.0-or-later
// Test oracle: a verbatim copy of the G-code writer as it was before the formatting was made
// fast (core/gcode.cpp, 2026-11-22), in namespace fivebar::oracle. The optimised writer must
// give byte-identical text for every job; gcode_test.cpp compares the two on seeded random jobs.
// Do not "fix" this file: it is the reference.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/output/gcode.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::oracle {
namespace {

// Fixed-point text of `value` with `decimals` decimals, as printf("%.*f") writes it, but never
// "-0.000". std::to_chars gives the same digits without locale and is several times faster on
// the million numbers of a large job.
std::string fixed(double value, int decimals) {
  char buf[64];
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  std::string s;
  if (r.ec == std::errc{}) {
    s.assign(buf, r.ptr);
  } else {  // too long for the buffer (|value| near 1e60 or more): let snprintf size it
    s.resize(static_cast<size_t>(std::snprintf(nullptr, 0, "%.*f", decimals, value)) + 1);
    s.resize(static_cast<size_t>(std::snprintf(s.data(), s.size(), "%.*f", decimals, value)));
  }
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

bool jointLimitsSet(const JointLimits& l) {
  return l.theta1Max - l.theta1Min < JointLimits::kDefaultSpan &&
         l.theta2Max - l.theta2Min < JointLimits::kDefaultSpan;
}

struct Setting {
  int number;
  std::string value;
  const char* meaning;
};

std::vector<Setting> settingsOf(const MachineProfile& p) {
  const MotorSettings& m = p.motors;
  const bool laser = p.tool.kind == ToolKind::Laser;
  const bool limits = jointLimitsSet(p.limits);
  const double maxS = std::max({p.tool.penDownS, p.tool.penUpS, p.tool.laserPowerS, 1.0});
  std::vector<Setting> s = {
      {11, fixed(m.junctionDeviationDeg, 4), "junction deviation, deg"},
      {20, p.hasHomingSwitches && limits ? "1" : "0", "soft limits"},
      {21, "0", "hard limits"},
      {22, p.hasHomingSwitches ? "1" : "0", "homing cycle"},
      {30, fixed(maxS, 0), "max S"},
      {31, "0", "min S"},
      {32, laser ? "1" : "0", "laser mode"},
      {100, fixed(m.stepsPerDeg1, 4), "motor 1 steps/deg"},
      {101, fixed(m.stepsPerDeg2, 4), "motor 2 steps/deg"},
      {110, fixed(degFromRad(m.maxSpeedRadPerS1) * 60.0, 1), "motor 1 max rate, deg/min"},
      {111, fixed(degFromRad(m.maxSpeedRadPerS2) * 60.0, 1), "motor 2 max rate, deg/min"},
      {120, fixed(degFromRad(m.maxAccelRadPerS2_1), 1), "motor 1 acceleration, deg/s^2"},
      {121, fixed(degFromRad(m.maxAccelRadPerS2_2), 1), "motor 2 acceleration, deg/s^2"},
  };
  if (p.tool.kind == ToolKind::ZAxis)
    s.push_back({112, fixed(p.tool.zFeedMmPerMin, 1), "Z max rate, mm/min"});
  if (limits) {
    s.push_back({130, fixed(degFromRad(p.limits.theta1Max - p.limits.theta1Min), 3),
                 "motor 1 travel, deg"});
    s.push_back({131, fixed(degFromRad(p.limits.theta2Max - p.limits.theta2Min), 3),
                 "motor 2 travel, deg"});
  }
  std::sort(s.begin(), s.end(), [](const Setting& a, const Setting& b) { return a.number < b.number; });
  return s;
}

// "$100=35.5556" (built with += : GCC 12 warns falsely on "literal" + std::string&&).
std::string settingText(const Setting& s) {
  std::string text = "$";
  text += std::to_string(s.number);
  text += '=';
  text += s.value;
  return text;
}

// Appends lines, each checked against GRBL's line length.
class Lines {
 public:
  void add(std::string line) {
    if (line.size() > static_cast<size_t>(kGcodeMaxLineLength))
      throw std::logic_error("G-code line longer than 80 characters: " + line.substr(0, 40));
    text_ += line;
    text_ += '\n';
  }
  void comment(const std::string& text) {
    std::string line = "; " + text;
    if (line.size() > static_cast<size_t>(kGcodeMaxLineLength)) line.resize(kGcodeMaxLineLength);
    add(line);
  }
  std::string text_;
};

class Writer {
 public:
  Writer(const PlannedJob& job, const MachineProfile& p, const GcodeOptions& o)
      : job_(job), p_(p), o_(o) {}

  std::string run() {
    header();
    for (size_t i = 0; i < job_.moves.size(); ++i) move(job_.moves[i]);
    if (p_.tool.kind != ToolKind::ZAxis) out_.add("M5");
    out_.add("M2");
    return out_.text_;
  }

 private:
  void header() {
    out_.comment("FiveBar Studio job for GRBL 1.1, host-side kinematics");
    out_.comment("X = theta1 deg, Y = theta2 deg (continuous), F = joint rate deg/min");
    out_.comment("profile: " + job_.profileName);
    out_.comment("working mode " + std::string(toString(job_.mode)) + ", assembly " +
                 std::string(toString(job_.assembly)));
    out_.comment("start pose X" + fixed(degFromRad(job_.start.theta1), o_.angleDecimals) + " Y" +
                 fixed(degFromRad(job_.start.theta2), o_.angleDecimals));
    out_.comment("estimated time " + fixed(job_.summary.estimatedTimeS, 1) + " s, " +
                 std::to_string(job_.summary.segments) + " drawing segments");
    out_.comment("expects these GRBL settings:");
    for (const Setting& s : settingsOf(p_))
      out_.comment(settingText(s) + " (" + s.meaning + ")");
    out_.add("G21 G90 G94");
    if (p_.tool.kind == ToolKind::Laser) out_.add("M4 S0");
  }

  void move(const JobMove& m) {
    switch (m.kind) {
      case JobMoveKind::Draw:
      case JobMoveKind::Travel: motion(m); break;
      case JobMoveKind::PenDown: tool(m, true); break;
      case JobMoveKind::PenUp: tool(m, false); break;
      case JobMoveKind::Dwell: out_.add("G4 P" + fixed(m.dwellS, 3)); break;
      case JobMoveKind::Pause:
        out_.comment("pause: change the tool, then resume (cycle start)");
        out_.add("M0");
        break;
    }
  }

  void motion(const JobMove& m) {
    if (o_.strokeComments && m.kind == JobMoveKind::Travel && m.strokeIndex >= 0 &&
        m.strokeIndex != commentedStroke_) {
      const PlannedStroke& s = job_.strokes[static_cast<size_t>(m.strokeIndex)];
      out_.comment("stroke " + std::to_string(m.strokeIndex) + " layer " +
                   std::to_string(s.layerIndex) + " path " + std::to_string(s.pathIndex));
      commentedStroke_ = m.strokeIndex;
    }
    std::string line = "G1 X" + fixed(degFromRad(m.target.theta1), o_.angleDecimals) + " Y" +
                       fixed(degFromRad(m.target.theta2), o_.angleDecimals);
    const std::string f = fixed(degFromRad(m.jointFeedRadPerS) * 60.0, o_.feedDecimals);
    if (f != lastFeed_) {
      line += " F" + f;
      lastFeed_ = f;
    }
    if (p_.tool.kind == ToolKind::Laser) {
      const std::string s = m.kind == JobMoveKind::Draw ? fixed(laserPower_, 0) : "0";
      if (s != lastS_) {
        line += " S" + s;
        lastS_ = s;
      }
    }
    out_.add(line);
  }

  void tool(const JobMove& m, bool down) {
    switch (p_.tool.kind) {
      case ToolKind::PenServo:
        if (down || p_.tool.penUpS > 0.0)
          out_.add("M3 S" + fixed(down ? m.toolValue : p_.tool.penUpS, 0));
        else
          out_.add("M5");
        if (m.dwellS > 0.0) out_.add("G4 P" + fixed(m.dwellS, 3));
        break;
      case ToolKind::ZAxis:
        out_.add("G1 Z" + fixed(m.toolValue, 3) + " F" + fixed(p_.tool.zFeedMmPerMin, 1));
        lastFeed_.clear();  // F is modal: the next XY move sets its own again
        break;
      case ToolKind::Laser:
        laserPower_ = down ? m.toolValue : 0.0;  // carried by the S word of the next G1
        break;
    }
  }

  const PlannedJob& job_;
  const MachineProfile& p_;
  const GcodeOptions& o_;
  Lines out_;
  std::string lastFeed_, lastS_ = "0";
  double laserPower_ = 0.0;
  int commentedStroke_ = -1;
};

}  // namespace

inline std::string grblSettings(const MachineProfile& profile) {
  std::string text;
  for (const Setting& s : settingsOf(profile))
    text += settingText(s) + "\n";
  return text;
}

inline std::string writeGcode(const PlannedJob& job, const MachineProfile& profile,
                       const GcodeOptions& options) {
  return Writer(job, profile, options).run();
}

}  // namespace fivebar::oracle
