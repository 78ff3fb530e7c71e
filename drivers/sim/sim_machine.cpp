// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim_machine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/protocol/gcode_words.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/protocol/grbl_protocol.hpp"

namespace fivebar::sim {
namespace {

using grbl::MachineState;

constexpr const char* kBanner = "Grbl 1.1h ['$' for help]";
constexpr std::size_t kRxCapacity = 128;
constexpr std::size_t kMaxLine = 79;  // LINE_BUFFER_SIZE 80 with the terminator
constexpr double kResetBannerDelayS = 0.6;  // after ALARM:3, as the real board

std::string fmt3(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", std::abs(v) < 0.0005 ? 0.0 : v);
  return buf;
}

std::string axes(const Axes3& a) { return fmt3(a[0]) + "," + fmt3(a[1]) + "," + fmt3(a[2]); }

bool isIntegerSetting(int id) {  // settings.c: the rest print with 3 decimals
  return id < 100 && id != 11 && id != 12 && id != 24 && id != 25 && id != 27;
}

}  // namespace

std::optional<Fault> parseFault(std::string_view text) {
  static constexpr std::pair<std::string_view, FaultKind> kKinds[] = {
      {"drop-after=", FaultKind::DropAfter}, {"reset-after=", FaultKind::ResetAfter},
      {"error-on=", FaultKind::ErrorOn}, {"alarm-after=", FaultKind::AlarmAfter}};
  for (const auto& [prefix, kind] : kKinds) {
    if (text.substr(0, prefix.size()) != prefix) continue;
    const auto n = grbl::parseNumber(text.substr(prefix.size()));
    if (!n || *n < 0 || *n != std::floor(*n)) return std::nullopt;
    return Fault{kind, long(*n)};
  }
  return std::nullopt;
}

SimMachine::SimMachine(const SimConfig& config)
    : config_(config), planner_(MotionLimits{}), trace_(config.trueMachine.value_or(config.profile)) {

  settings_ = firmwareDefaultSettings();
  if (config.setUp)
    for (const auto& [id, value] : setup::expectedSettings(config.profile)) settings_[id] = value;
  applySettings();
  // A board after power-up: MPos 0,0,0, nothing sent when the port opens (the banner went out
  // at power-up, before anyone listened); locked in alarm when homing is enabled.
  planner_.setPosition({0.0, 0.0, 0.0});
  if (config.referenced) {
    const MachineProfile& p = config.profile;
    const double z = p.tool.kind == ToolKind::ZAxis ? p.tool.zUpMm : 0.0;
    coords_[0] = planner_.quantize({-degFromRad(p.homeAngles.theta1), -degFromRad(p.homeAngles.theta2), -z});
    updateWco();
  }
  if (settings_[22] == 1) state_ = MachineState::Alarm;
  // The arms stand at the profile's home pose at power-up (to the nearest step, as --referenced
  // reads it).
  const Axes3 home = planner_.quantize(
      {degFromRad(config.profile.homeAngles.theta1), degFromRad(config.profile.homeAngles.theta2), 0.0});
  physicalOffsetDeg_ = {home[0], home[1]};
  trace_.place(physicalDeg(planner_.position()));
}

void SimMachine::setTrueMachine(std::optional<MachineProfile> trueMachine) {
  config_.trueMachine = std::move(trueMachine);
  trace_.setMachine(config_.trueMachine.value_or(config_.profile));
}

void SimMachine::redefinePosition(const Axes3& m) {
  const Axes3 before = planner_.position();
  for (size_t i = 0; i < 2; ++i) physicalOffsetDeg_[i] += before[i] - m[i];
  planner_.setPosition(m);
}

void SimMachine::updateWco() {
  const Axes3 before = wco_;
  for (size_t i = 0; i < 3; ++i) wco_[i] = coords_[size_t(coordSelect_)][i] + g92_[i];
  if (wco_ != before) wcoCounter_ = 0;  // system_flag_wco_change: in the very next report
}

void SimMachine::applySettings() {
  MotionLimits m;
  for (int i = 0; i < 3; ++i) {
    m.stepsPerUnit[size_t(i)] = std::max(settings_[100 + i], 1e-3);
    m.maxRatePerS[size_t(i)] = std::max(settings_[110 + i], 1e-3) / 60.0;
    m.accelPerS2[size_t(i)] = std::max(settings_[120 + i], 1e-3);
  }
  m.junctionDeviation = settings_[11];
  planner_.setLimits(m);
}

Axes3 SimMachine::workPosition() const {
  Axes3 w = planner_.position();
  for (size_t i = 0; i < 3; ++i) w[i] -= wco_[i];
  return w;
}

std::string SimMachine::takeOutput() {
  std::string s;
  s.swap(out_);
  return s;
}

void SimMachine::receive(std::string_view bytes) {
  if (linkDropped_ || resetLeftS_ > 0.0) return;  // a resetting board drops what arrives
  for (char c : bytes) {
    if (const auto command = grbl::overrideCommandOf(c)) {
      overrideFlags_.add(*command);  // executed at the real-time check after this chunk
    } else if (grbl::realtime::isRealtime(c)) {
      realtimeByte(c);
    } else if (rx_.size() < kRxCapacity) {
      rx_.push_back(c);
    } else {
      ++rxOverflow_;  // the firmware drops bytes that do not fit
    }
  }
  applyOverrides();
  serviceLines();
}

void SimMachine::realtimeByte(char c) {
  namespace rt = grbl::realtime;
  if (c == rt::kStatus) {
    if (criticalAlarm_) return;  // a hard or soft limit alarm: silent until the reset
    if (homing_) return;         // limits_go_home serves no status request
    // protocol.c reports at its next real-time check point: after the lines received before
    // the '?' are executed (or while one waits for planner room).
    serviceLines();
    if (homing_) return;  // a '?' behind "$H": the cycle started first and serves none
    reportStatus();
  } else if (c == rt::kFeedHold) {
    // GRBL 1.1h protocol.c, EXEC_FEED_HOLD: a cycle decelerates to a hold; in IDLE (e.g. a
    // stream starved for a moment) "Grbl is not in motion. Simply indicate suspend state and
    // hold is complete": Hold:0 at once, and queued lines wait for the cycle start.
    if (state_ == MachineState::Run || state_ == MachineState::Idle) {
      holding_ = true;
      state_ = MachineState::Hold;
    } else if (state_ == MachineState::Jog) {
      jogCancel_ = true;  // a feed hold during a jog cancels it
    }
  } else if (c == rt::kCycleStart) {
    if (state_ == MachineState::Hold && !softLimitStop_) {  // no resuming a soft-limit stop
      holding_ = false;
      state_ = planner_.empty() ? MachineState::Idle : MachineState::Run;
      serviceLines();
    }
  } else if (c == rt::kSoftReset) {
    softReset();
  } else if (c == rt::kJogCancel) {
    if (state_ == MachineState::Jog) jogCancel_ = true;
  }
  // Feed and rapid overrides (0x90-0x97): receive() and applyOverrides(). Spindle overrides
  // (0x99-0x9D) and the coolant toggles are accepted and change nothing here.
}

void SimMachine::setPen(bool down) {
  if (down == penDown_) return;
  const Axes3 p = workPosition();
  const Point2 here{p[0], p[1]};
  if (down) {
    strokes_.push_back({here});
  } else if (!strokes_.empty() && strokes_.back().back() != here) {
    strokes_.back().push_back(here);  // a move cut short by a stop or an alarm
  }
  if (down) trace_.touchDown();  // a dot where the pen lands, even if it never moves
  if (!down) trace_.liftPen();
  penDown_ = down;
}

void SimMachine::softReset() {
  homingSucceeded_ = false;
  if (homing_) {  // a reset during the homing cycle: ALARM:6 (homing fail: reset)
    homing_ = false;
    homingMoves_.clear();
    planner_.clear();
    rx_.clear();
    haveCurrent_ = false;
    state_ = MachineState::Alarm;
    reply("ALARM:6");
    resetAlarm_ = true;
    resetLeftS_ = config_.instant ? 1e-9 : kResetBannerDelayS;
    return;
  }
  const bool moving = planner_.moving() ||
                      ((state_ == MachineState::Run || state_ == MachineState::Jog) &&
                       !planner_.empty());
  // mc_line waits in the soft-limit alarm for the reset, then its line returns: "ok".
  if (okOwed_) reply("ok");
  okOwed_ = false;
  setPen(false);
  planner_.clear();
  rx_.clear();
  arcSegments_.clear();
  haveCurrent_ = false;
  holding_ = jogCancel_ = criticalAlarm_ = softLimitStop_ = false;
  dwellLeftS_ = 0.0;
  dwellStarted_ = false;
  overrideFlags_.clear();
  // gc_init: G0 G54 G17 G21 G90 G94 M5 M9, G92 cleared.
  absolute_ = true;
  motionMode_ = 0;
  coordSelect_ = 0;
  g92_ = {};
  feedPerMin_ = spindleS_ = 0.0;
  spindleOn_ = spindleCcw_ = coolantFlood_ = false;
  checkMode_ = false;
  resetAlarm_ = moving || state_ == MachineState::Alarm;
  if (moving) {
    reply("ALARM:3");
    state_ = MachineState::Alarm;
    resetLeftS_ = config_.instant ? 1e-9 : kResetBannerDelayS;
    return;
  }
  finishReset();
}

void SimMachine::finishReset() {
  resetLeftS_ = -1.0;
  if (homingOkOwed_) reply("ok");  // the $H that failed returns before the reset completes
  homingOkOwed_ = false;
  updateWco();
  wcoCounter_ = ovrCounter_ = 0;  // main.c clears sys: WCO on the first report
  setOverrides({});               // and the overrides are 100 % again
  out_ += std::string("\r\n") + kBanner + "\r\n";
  if (resetAlarm_) {
    state_ = MachineState::Alarm;
    reply("[MSG:'$H'|'$X' to unlock]");
    return;
  }
  state_ = MachineState::Idle;
  for (const std::string& line : startupLines_) {  // system_execute_startup: ">line:ok"
    if (line.empty()) continue;
    const std::string before = out_;
    out_.clear();
    executeGcode(line, false);
    std::string answer = out_;
    while (!answer.empty() && (answer.back() == '\n' || answer.back() == '\r')) answer.pop_back();
    out_ = before + ">" + line + ":" + answer + "\r\n";
  }
}

void SimMachine::raiseAlarm(int code, bool critical) {
  setPen(false);
  planner_.clear();
  spindleOn_ = coolantFlood_ = false;  // mc_reset stops the spindle and the coolant
  holding_ = jogCancel_ = softLimitStop_ = false;
  haveCurrent_ = false;
  state_ = MachineState::Alarm;
  reply("ALARM:" + std::to_string(code));
  if (critical) {
    criticalAlarm_ = true;
    reply("[MSG:Reset to continue]");
  }
}

// limits.c limits_soft_check: a target beyond the travel while a cycle runs forces a feed hold
// ("all buffered blocks are guaranteed to be within workspace volume so just come to a
// controlled stop so position is not lost"), waits for Idle, then mc_reset and ALARM:2; with
// the machine standing, the alarm comes at once. No further line is read meanwhile (mc_line has
// not returned), and that line is answered "ok" only at the reset.
void SimMachine::softLimitViolated() {
  okOwed_ = true;
  if (state_ == MachineState::Run && !planner_.empty()) {
    softLimitStop_ = true;
    state_ = MachineState::Hold;  // "Hold:1" while it decelerates
    return;
  }
  raiseAlarm(2, true);
}

bool SimMachine::fireFault(FaultKind kind) const {
  return !faultFired_ && config_.fault.kind == kind &&
         linesReceived_ == config_.fault.line + (kind == FaultKind::ErrorOn ? 0 : 1);
}

void SimMachine::serviceLines() {
  // protocol.c: while a hold lasts (a feed hold, or M0) protocol_exec_rt_suspend() loops until
  // the cycle start: no line is read, parsed or acknowledged; the received bytes wait.
  while (!criticalAlarm_ && !linkDropped_ && !holding_ && !softLimitStop_) {
    if (!haveCurrent_) {
      const size_t end = rx_.find_first_of("\r\n");
      if (end == std::string::npos) return;
      // protocol.c stores neither spaces, control characters nor comments, upper-cased.
      const std::string raw = rx_.substr(0, end);
      rx_.erase(0, end + 1);
      current_ = gcode::compact(raw);
      ++linesReceived_;
      haveCurrent_ = true;
      if (fireFault(FaultKind::DropAfter)) { faultFired_ = linkDropped_ = true; return; }
      if (fireFault(FaultKind::ResetAfter)) { faultFired_ = true; softReset(); return; }
      if (fireFault(FaultKind::AlarmAfter)) { faultFired_ = true; raiseAlarm(1, true); return; }
      if (fireFault(FaultKind::ErrorOn)) {
        faultFired_ = true;
        haveCurrent_ = false;
        reply("error:20");
        continue;
      }
      if (current_.size() > kMaxLine) {
        haveCurrent_ = false;
        reply("error:11");
        continue;
      }
    }
    if (executeLine(current_) == LineResult::Blocked) return;
    haveCurrent_ = false;
  }
}

SimMachine::LineResult SimMachine::executeLine(const std::string& line) {
  if (line.empty()) { reply("ok"); return LineResult::Done; }
  if (line[0] == '$') return executeSystem(line);
  return executeGcode(line, false);
}

void SimMachine::advance(double machineDtS) {
  clockS_ += machineDtS;
  if (resetLeftS_ > 0.0) {
    resetLeftS_ -= machineDtS;
    if (resetLeftS_ <= 0.0) finishReset();
    return;
  }
  if (linkDropped_ || criticalAlarm_) return;
  if (homing_) {
    planner_.advance(machineDtS, false, config_.instant,
                     [this](const Block& b) { trace_.moveTo(physicalDeg(b.target), false); });
    trace_.moveTo(physicalDeg(planner_.position()), false);
    if (planner_.empty() && homingPauseS_ > 0.0) homingPauseS_ = config_.instant ? 0.0 : homingPauseS_ - machineDtS;
    homingStep();
    if (!homing_) serviceLines();
    return;
  }
  const bool hadBlocks = !planner_.empty();
  planner_.advance(machineDtS, holding_ || jogCancel_ || softLimitStop_, config_.instant,
                   [this](const Block& b) { blockDone(b); });
  if (!planner_.empty())  // the pen's true path along the block under way
    trace_.moveTo(physicalDeg(planner_.position()), planner_.blocks().front().penDown);
  if (softLimitStop_ && !planner_.moving()) {  // stopped under control: the alarm, position kept
    softLimitStop_ = false;
    state_ = MachineState::Idle;
    raiseAlarm(2, true);
    return;
  }
  if (jogCancel_ && !planner_.moving()) {
    planner_.clear();
    jogCancel_ = false;
    state_ = MachineState::Idle;
  }
  if (dwellLeftS_ > 0.0) dwellLeftS_ = config_.instant ? 0.0 : dwellLeftS_ - machineDtS;
  if (planner_.empty() && !holding_ &&
      (state_ == MachineState::Run || state_ == MachineState::Jog))
    state_ = MachineState::Idle;
  if (hadBlocks && planner_.empty() && penDown_ && !haveCurrent_ &&
      rx_.find_first_of("\r\n") == std::string::npos)
    ++starvations_;
  serviceLines();
}

void SimMachine::blockDone(const Block& b) {
  trace_.moveTo(physicalDeg(b.target), b.penDown);
  const Point2 start{b.start[0] - wco_[0], b.start[1] - wco_[1]};
  const Point2 end{b.target[0] - wco_[0], b.target[1] - wco_[1]};
  if (b.penDown) {
    if (!penDown_ || strokes_.empty()) {
      strokes_.push_back({start});
      penDown_ = true;
    }
    strokes_.back().push_back(end);
  }
  if (config_.profile.tool.kind == ToolKind::ZAxis)
    setPen(penDownFor(spindleS_, spindleOn_, b.target[2] - wco_[2]));
}

bool SimMachine::penDownFor(double spindleS, bool spindleOn, double z) const {
  return stream::penDownFor(config_.profile.tool, spindleOn, spindleS, z);
}

// limits.c / system.c: with soft limits on, every target must lie within -$13x..0 in machine
// coordinates (homing direction mask 0, HOMING_FORCE_SET_ORIGIN off).
bool SimMachine::withinLimits(const Axes3& machineTarget) const {
  if (settings_.at(20) != 1) return true;
  for (int i = 0; i < 3; ++i) {
    const double slack = 0.5 / planner_.limits().stepsPerUnit[size_t(i)];
    if (machineTarget[size_t(i)] > slack || machineTarget[size_t(i)] < -settings_.at(130 + i) - slack)
      return false;
  }
  return true;
}

void SimMachine::reportStatus() {
  // report.c report_realtime_status, field by field.
  if (resetLeftS_ > 0.0) return;
  const int mask = int(settings_[10]);
  const bool busy = state_ == MachineState::Run || state_ == MachineState::Hold ||
                    state_ == MachineState::Jog || state_ == MachineState::Home;
  std::string s = "<";
  s += grbl::toString(state_);
  if (state_ == MachineState::Hold) s += planner_.moving() ? ":1" : ":0";
  Axes3 p = planner_.position();
  if (!(mask & 1))
    for (size_t i = 0; i < 3; ++i) p[i] -= wco_[i];
  s += (mask & 1) ? "|MPos:" : "|WPos:";
  s += axes(p);
  if (mask & 2)
    s += "|Bf:" + std::to_string(int(Planner::kCapacity - planner_.size())) + "," +
         std::to_string(int(kRxCapacity - rx_.size()));
  s += "|FS:" + std::to_string(long(std::lround(planner_.speed() * 60.0))) + "," +
       std::to_string(long(std::lround(spindleOn_ ? spindleS_ : 0.0)));
  if (wcoCounter_ > 0) {
    --wcoCounter_;
  } else {
    wcoCounter_ = busy ? 29 : 9;
    if (ovrCounter_ == 0) ovrCounter_ = 1;
    s += "|WCO:" + axes(wco_);
  }
  if (ovrCounter_ > 0) {
    --ovrCounter_;
  } else {
    ovrCounter_ = busy ? 19 : 9;
    s += "|Ov:" + std::to_string(overrides_.feedPct) + "," + std::to_string(overrides_.rapidPct) + ",100";
    // spindle_get_state: on while its PWM runs (S > 0), S clockwise (M3), C counter-clockwise
    // (M4); F flood coolant (M8). No Ln: (USE_LINE_NUMBERS is off in the stock config.h).
    const bool spindleRuns = spindleOn_ && spindleS_ > 0.0;
    if (spindleRuns || coolantFlood_)
      s += std::string("|A:") + (spindleRuns ? (spindleCcw_ ? "C" : "S") : "") + (coolantFlood_ ? "F" : "");
  }
  reply(s + ">");
}

void SimMachine::reportSettings() {
  for (const auto& [id, value] : settings_) {
    char buf[64];
    if (isIntegerSetting(id))
      std::snprintf(buf, sizeof buf, "$%d=%ld", id, long(std::lround(value)));
    else
      std::snprintf(buf, sizeof buf, "$%d=%.3f", id, value);
    reply(buf);
  }
}

}  // namespace fivebar::sim
