// SimMachine: a GRBL 1.1-compatible simulated five-bar controller, pure logic. Bytes in through
// receive(), bytes out through takeOutput(), machine time through advance(). It implements the
// subset the studio uses: G0/G1/G4/G90/G91/G10 L20/G92/M3/M4/M5/S/F, $J=, $H, $X, $$, $N=V,
// $I, $G and the real-time bytes ? ! ~ 0x18 0x85; a 128-byte receive buffer; a 15-block
// planner with trapezoidal timing (sim_planner.hpp); soft-limit alarms from the profile's
// joint limits; error:N for bad lines; ALARM:3 after a reset during motion; injected faults.
// It records the pen-down joint-space path. Units: X, Y degrees (theta1, theta2), Z mm.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/machine/profile.hpp"
#include "gcode_words.hpp"
#include "grbl_parser.hpp"
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
};

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

 private:
  enum class LineResult { Done, Blocked };
  void serviceLines();
  LineResult executeLine(const std::string& line);
  LineResult executeSystem(const std::string& line);
  LineResult executeGcode(const std::string& line, bool jog);
  bool motion(const gcode::Words& w, bool jog);  // false when it replied an error/alarm
  bool syncReady() const { return planner_.empty(); }
  void realtimeByte(char c);
  void softReset();
  void raiseAlarm(int code, bool critical);
  void setPen(bool down);
  void blockDone(const Block& b);
  void reply(std::string_view text) { out_ += text; out_ += "\r\n"; }
  void reportStatus();
  void reportSettings();
  void applySettings();
  bool withinLimits(const Axes3& machineTarget) const;
  bool fireFault(FaultKind kind) const;
  bool penDownFor(double spindleS, bool spindleOn, double z) const;

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
  bool linkDropped_ = false;
  double dwellLeftS_ = 0.0;
  bool dwellStarted_ = false;
  bool absolute_ = true;
  bool rapidMode_ = true;
  double feedPerMin_ = 0.0;
  double spindleS_ = 0.0;
  bool spindleOn_ = false;
  bool penDown_ = false;
  Axes3 wco_{};
  long linesReceived_ = 0;
  long rxOverflow_ = 0;
  long starvations_ = 0;
  int reportsSinceWco_ = 0;
  bool faultFired_ = false;
  std::vector<std::vector<Point2>> strokes_;
};

}  // namespace fivebar::sim
