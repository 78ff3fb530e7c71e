// SPDX-License-Identifier: GPL-3.0-or-later
// Parsing of the lines a GRBL 1.1 board sends (one line at a time, without the line end).
// Pure functions, no I/O. Angles stay in the board's units here (degrees: X = theta1,
// Y = theta2, conventions.md); conversion to radians happens in GrblProtocol.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fivebar::grbl {

// Up to three axes: X (theta1, deg), Y (theta2, deg), Z (pen height, mm) when present.
struct Axes {
  std::array<double, 3> v{0.0, 0.0, 0.0};
  int count = 0;
  double x() const { return v[0]; }
  double y() const { return v[1]; }
};

enum class MachineState { Unknown, Idle, Run, Hold, Jog, Alarm, Door, Check, Home, Sleep };
std::string_view toString(MachineState s);

// One "<...>" real-time status report. Fields GRBL did not send stay empty.
struct StatusReport {
  MachineState state = MachineState::Unknown;
  int subState = -1;            // Hold:0 = hold complete, Hold:1 = decelerating; -1 none
  std::optional<Axes> mpos;     // machine position
  std::optional<Axes> wpos;     // work position
  std::optional<Axes> wco;      // work coordinate offset (MPos = WPos + WCO)
  std::optional<int> plannerBlocksFree;  // Bf: first number
  std::optional<int> rxBytesFree;        // Bf: second number
  std::optional<double> feed;            // FS/F: current feed (deg/min)
  std::optional<double> spindle;         // FS: current spindle speed
  std::optional<std::array<int, 3>> overrides;  // Ov: feed, rapid, spindle (%)
  std::string pins;                      // Pn: letters, e.g. "XYP"
  // Ln: the block being executed; only from firmware built with USE_LINE_NUMBERS (a stock
  // GRBL 1.1h never sends it).
  std::optional<long> lineNumber;
  // A: accessories, sent with Ov: (every 10th/20th report and after a spindle or coolant
  // change): "S" spindle clockwise / "C" counter-clockwise (while S > 0), "F" flood, "M" mist;
  // empty when the report had no A: (all off, or no Ov: on this report).
  std::string accessories;
};

enum class LineKind {
  Empty,
  Ok,          // "ok"
  Error,       // "error:N"
  Alarm,       // "ALARM:N"
  Banner,      // "Grbl 1.1h ['$' for help]": the board has just reset
  Status,      // "<...>"
  Setting,     // "$N=V"
  Message,     // "[MSG:...]"
  GcodeState,  // "[GC:...]"
  Version,     // "[VER:...]"
  Option,      // "[OPT:...]"
  Feedback,    // any other "[...]" (e.g. [G54:...], [PRB:...], [echo:...])
  StartupEcho, // ">G54:ok" startup line execution
  Unknown,
};

struct ParsedLine {
  LineKind kind = LineKind::Unknown;
  int code = 0;          // Error / Alarm code
  int settingId = -1;    // Setting
  double settingValue = 0.0;
  std::string text;      // Banner version ("1.1h"), payload of [..] feedback, or the raw line
  std::string raw;       // the line as received (without the line end)
  StatusReport status;   // Status
};

// Parses one received line. Malformed lines give LineKind::Unknown with the raw text kept,
// never an exception.
ParsedLine parseLine(std::string_view line);

// Parses the inside of a status report (without '<' and '>'); nullopt when malformed.
std::optional<StatusReport> parseStatus(std::string_view body);

// Number parsing helpers shared with the simulator (locale-independent).
std::optional<double> parseNumber(std::string_view text);
std::optional<Axes> parseAxes(std::string_view text);  // "1.000,-2.5,0"

}  // namespace fivebar::grbl
