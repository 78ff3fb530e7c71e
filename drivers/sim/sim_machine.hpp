// SPDX-License-Identifier: GPL-3.0-or-later
// SimMachine: a simulated GRBL 1.1h board driving a five-bar, pure logic. Bytes in through
// receive(), bytes out through takeOutput(), machine time through advance(). It answers as the
// firmware does (gnea/grbl 1.1h: protocol.c, report.c, settings.c, system.c, limits.c; checked
// against the real firmware in tests/drivers/replay_test.cpp): it starts at MPos 0,0,0 like a
// board after power-up and sends nothing when the port opens; status reports follow $10 (MPos
// or WPos, Bf: only with bit 1), WCO: on the first report after power-up, a reset or an offset
// change and then every 10th (idle) / 30th (busy) report, Ov: on the report after; a '?' is
// answered after the lines before it are executed; $I, $#, $N, $C, $G, $$ (firmware defaults,
// or the profile's settings when the board was set up), $20=1 refused without $22=1, soft limits
// -$13x..0 in machine coordinates, the 79-character line buffer without spaces, G0/G1/G4,
// G2/G3 arcs, G10 L2/L20, G28/G30 (.1), G53, G54-G59, G90/G91, G92 (.1), M0/M2/M30/M3/M4/M5,
// M2 with [MSG:Pgm End]; feed (10..200 %) and rapid (100/50/25 %) overrides as protocol.c and
// planner.c apply them (drivers/protocol/overrides.hpp), reported in Ov:; a 15-block planner with trapezoidal timing (sim_planner.hpp); ALARM:3
// at once on a reset during motion and the banner 0.6 s later; injected faults. It records the
// pen-down joint-space path. Units: X, Y degrees (theta1, theta2), Z mm.
#pragma once

#include <array>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/machine/profile.hpp"
#include "drivers/protocol/gcode_words.hpp"
#include "drivers/protocol/grbl_parser.hpp"
#include "drivers/protocol/overrides.hpp"
#include "pen_trace.hpp"
#include "sim_planner.hpp"

namespace fivebar::sim {

enum class FaultKind { None, DropAfter, ResetAfter, ErrorOn, AlarmAfter };
// One injected fault, fired once: after N received lines the link drops / the board resets
// (as a power glitch would: ALARM:3 when moving, then the banner) / a hard-limit ALARM:1 stops
// it; error-on=N answers the N-th line with error:20 instead of executing it.
struct Fault {
  FaultKind kind = FaultKind::None;
  long line = 0;
};
// Parses "drop-after=N", "reset-after=N", "error-on=N", "alarm-after=N"; nullopt otherwise.
std::optional<Fault> parseFault(std::string_view text);

using Point2 = std::array<double, 2>;  // theta1, theta2 in degrees

struct SimConfig {
  MachineProfile profile;
  Fault fault;
  bool instant = false;  // every move completes at once (acks as fast as lines arrive)
  // false: the EEPROM of a new board (the firmware's default $$ values); true: a board on which
  // `fivebar setup --write` ran for the profile (its expected settings, $10=3 included).
  bool setUp = false;
  // false: EEPROM offsets all zero (work = machine coordinates). true: the G54 offset of a board
  // referenced at the pose it was powered up in (`fivebar reference` at the home pose, then a
  // power cycle there): MPos 0,0 reads as the profile's home pose.
  bool referenced = false;
  // false: no homing switches wired (as the firmware in ../shared/tools/grbl-sim): $H searches
  // Z for 1.5 x $132 and fails with ALARM:9. true: every axis has its switch at machine
  // position 0 (the + end of travel, homing direction mask 0).
  bool homingSwitches = false;
  // The real machine the simulated motors drive (issue 13; pen_trace.hpp): its geometry, and
  // in its calibration section the true zero offsets, backlash and pen offset. nullopt: the
  // profile itself. The arms stand at the profile's home pose at power-up.
  std::optional<MachineProfile> trueMachine;
};

// The firmware's default settings (defaults.h, DEFAULTS_GENERIC).
std::map<int, double> firmwareDefaultSettings();

class SimMachine {
 public:
  explicit SimMachine(const SimConfig& config);

  void receive(std::string_view bytes);
  std::string takeOutput();
  void advance(double machineDtS);

  // Observation (tests, the sim's record file).
  grbl::MachineState state() const { return state_; }
  Axes3 machinePosition() const { return planner_.position(); }
  Axes3 workPosition() const;
  const std::vector<std::vector<Point2>>& strokes() const { return strokes_; }
  long linesReceived() const { return linesReceived_; }
  long rxOverflowBytes() const { return rxOverflow_; }
  long plannerStarvationsInStroke() const { return starvations_; }
  std::size_t plannerBlocks() const { return planner_.size(); }
  bool linkDropped() const { return linkDropped_; }
  bool penDown() const { return penDown_; }
  const grbl::MotionOverrides& overrides() const { return overrides_; }
  double clockS() const { return clockS_; }  // machine time advanced since power-up (s)
  // What the pen of the true machine really drew: polylines in the machine (base) frame, mm.
  const std::vector<std::vector<Vec2>>& drawnTrace() const { return trace_.polylines(); }
  // The motors drive another true machine from now on (SimConfig::trueMachine; nullopt: the
  // profile itself), as if the arms were swapped where they stand: the drawing so far stays.
  void setTrueMachine(std::optional<MachineProfile> trueMachine);

 private:
  enum class LineResult { Done, Blocked };
  void serviceLines();
  LineResult executeLine(const std::string& line);
  LineResult executeSystem(const std::string& line);
  LineResult executeGcode(const std::string& line, bool jog);
  LineResult setSetting(const std::string& line);
  bool arc(const gcode::Words& w, bool clockwise);  // false when it replied an error
  void reportParameters();
  LineResult home();   // $H: starts or continues the homing cycle
  void homingStep();   // called as machine time passes while homing
  void finishReset();
  Axes3 coordSystem(int index) const;  // G54 = 0 .. G59 = 5, machine offsets
  bool motion(const gcode::Words& w, bool jog, bool rapidMove);  // false: replied an error/alarm
  void addBlock(const Axes3& target, double feedPerMin, bool rapid, bool jog);
  void updateWco();
  bool syncReady() const { return planner_.empty(); }
  void realtimeByte(char c);
  void applyOverrides();
  void setOverrides(const grbl::MotionOverrides& overrides);
  void softReset();
  void raiseAlarm(int code, bool critical);
  void softLimitViolated();  // limits.c limits_soft_check, for a target beyond the travel
  void setPen(bool down);
  void blockDone(const Block& b);
  void reply(std::string_view text) { out_ += text; out_ += "\r\n"; }
  void reportStatus();
  void reportSettings();
  void applySettings();
  bool withinLimits(const Axes3& machineTarget) const;
  bool fireFault(FaultKind kind) const;
  bool penDownFor(double spindleS, bool spindleOn, double z) const;
  // The motors' physical angles (commanded frame, deg) at machine position m: the power-up
  // pose is the profile's home pose; a redefined position (homing) shifts the offset.
  std::array<double, 2> physicalDeg(const Axes3& m) const {
    return {m[0] + physicalOffsetDeg_[0], m[1] + physicalOffsetDeg_[1]};
  }
  void redefinePosition(const Axes3& m);  // the position reads m from now on; nothing moves

  SimConfig config_;
  Planner planner_;
  std::map<int, double> settings_;
  grbl::MachineState state_ = grbl::MachineState::Idle;
  std::string rx_;        // receive buffer (at most 128 bytes)
  std::string current_;   // the line being executed (blocked on planner room or a sync)
  bool haveCurrent_ = false;
  std::string out_;
  bool holding_ = false;
  bool jogCancel_ = false;
  bool criticalAlarm_ = false;  // waits for a soft reset
  bool softLimitStop_ = false;  // a target beyond the travel came while moving: stopping, then ALARM:2
  bool okOwed_ = false;  // the line that raised a soft-limit alarm is answered ok at the reset
  bool linkDropped_ = false;
  double dwellLeftS_ = 0.0;
  bool dwellStarted_ = false;
  bool absolute_ = true;
  int coordSelect_ = 0;             // G54
  std::array<Axes3, 6> coords_{};   // G54..G59 (EEPROM)
  Axes3 g28_{}, g30_{}, g92_{};
  std::array<std::string, 2> startupLines_;
  bool checkMode_ = false;
  double resetLeftS_ = -1.0;        // > 0: a reset in motion, banner when it reaches 0
  bool resetAlarm_ = false;
  // Homing ($H): the moves still to make (target, rate per minute; one block at a time, each
  // followed by the $26 debounce), whether it ends with the switch not found.
  struct HomingMove {
    Axes3 target{};
    double feedPerMin = 0.0;
  };
  std::deque<HomingMove> homingMoves_;
  bool homing_ = false, homingFails_ = false, homingSucceeded_ = false, homingOkOwed_ = false;
  double homingPauseS_ = 0.0;
  int wcoCounter_ = 0, ovrCounter_ = 0;
  grbl::MotionOverrides overrides_;  // feed, rapid (%)
  grbl::OverrideFlags overrideFlags_;  // received, not yet executed
  bool statusRequested_ = false;
  int motionMode_ = 0;  // G0..G3
  std::deque<Axes3> arcSegments_;
  double arcFeedPerMin_ = 0.0;
  double feedPerMin_ = 0.0;
  double spindleS_ = 0.0;
  bool spindleOn_ = false;
  bool spindleCcw_ = false;    // M4
  bool coolantFlood_ = false;  // M8
  bool penDown_ = false;
  Axes3 wco_{};
  long linesReceived_ = 0;
  double clockS_ = 0.0;
  long rxOverflow_ = 0;
  long starvations_ = 0;
  bool faultFired_ = false;
  std::vector<std::vector<Point2>> strokes_;
  std::array<double, 2> physicalOffsetDeg_{0.0, 0.0};
  PenTrace trace_;
};

}  // namespace fivebar::sim
