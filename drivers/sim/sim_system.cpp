// SPDX-License-Identifier: GPL-3.0-or-later
// SimMachine: the "$" system commands, as GRBL 1.1h's system.c and settings.c answer them.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "drivers/protocol/grbl_parser.hpp"
#include "sim_machine.hpp"

namespace fivebar::sim {
namespace {

using grbl::MachineState;

std::string axesText(const Axes3& a) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f,%.3f,%.3f", a[0], a[1], a[2]);
  return buf;
}

}  // namespace

std::map<int, double> firmwareDefaultSettings() {
  return {{0, 10},    {1, 25},    {2, 0},     {3, 0},     {4, 0},     {5, 0},    {6, 0},
          {10, 1},    {11, 0.010}, {12, 0.002}, {13, 0},  {20, 0},    {21, 0},   {22, 0},
          {23, 0},    {24, 25},   {25, 500},  {26, 250},  {27, 1},    {30, 1000}, {31, 0},
          {32, 0},    {100, 250}, {101, 250}, {102, 250}, {110, 500}, {111, 500}, {112, 500},
          {120, 10},  {121, 10},  {122, 10},  {130, 200}, {131, 200}, {132, 200}};
}

SimMachine::LineResult SimMachine::executeSystem(const std::string& line) {
  // system.c: $J= jogs in Idle or Jog; $$ $G $C $X $N... need Idle or Alarm where noted.
  if (line == "$H" && (homing_ || homingSucceeded_)) return home();  // the cycle under way
  const bool idleOrAlarm = state_ == MachineState::Idle || state_ == MachineState::Alarm;
  if (line.rfind("$J=", 0) == 0) {
    if (state_ != MachineState::Idle && state_ != MachineState::Jog) {
      reply("error:8");
      return LineResult::Done;
    }
    return executeGcode(line.substr(3), true);
  }
  if (line == "$") {
    reply("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
  } else if (line == "$$") {
    if (!idleOrAlarm && state_ != MachineState::Check) { reply("error:8"); return LineResult::Done; }
    reportSettings();
  } else if (line == "$G") {
    char buf[160];
    std::snprintf(buf, sizeof buf, "[GC:%s G%d G17 G21 %s G94 %s M9 T0 F%ld S%ld]",
                  motionMode_ == 0 ? "G0" : motionMode_ == 1 ? "G1" : motionMode_ == 2 ? "G2" : "G3",
                  54 + coordSelect_, absolute_ ? "G90" : "G91", spindleOn_ ? "M3" : "M5",
                  long(feedPerMin_), long(spindleS_));
    reply(buf);
  } else if (line == "$C") {
    if (state_ == MachineState::Check) {
      checkMode_ = false;
      reply("[MSG:Disabled]");
      reply("ok");
      softReset();  // leaving check mode resets the board (mc_reset)
      return LineResult::Done;
    }
    if (state_ != MachineState::Idle) { reply("error:8"); return LineResult::Done; }
    checkMode_ = true;
    state_ = MachineState::Check;
    reply("[MSG:Enabled]");
  } else if (line == "$X") {
    if (state_ == MachineState::Alarm) {
      reply("[MSG:Caution: Unlocked]");
      state_ = MachineState::Idle;
    }
  } else if (!idleOrAlarm) {
    reply("error:8");
    return LineResult::Done;
  } else if (line == "$I") {
    reply("[VER:1.1h.20190830:]");
    reply("[OPT:V,15,128]");
  } else if (line == "$#") {
    reportParameters();
  } else if (line == "$N") {
    for (int i = 0; i < 2; ++i) reply("$N" + std::to_string(i) + "=" + startupLines_[size_t(i)]);
  } else if (line.rfind("$N", 0) == 0 && line.size() > 3 && line[3] == '=' &&
             (line[2] == '0' || line[2] == '1')) {
    startupLines_[size_t(line[2] - '0')] = line.substr(4);
  } else if (line == "$H") {
    if (settings_[22] != 1) { reply("error:5"); return LineResult::Done; }
    return home();
  } else {
    return setSetting(line);
  }
  reply("ok");
  return LineResult::Done;
}

SimMachine::LineResult SimMachine::setSetting(const std::string& line) {
  const size_t eq = line.find('=');
  const auto id = eq == std::string::npos ? std::nullopt : grbl::parseNumber(line.substr(1, eq - 1));
  const auto value = eq == std::string::npos ? std::nullopt : grbl::parseNumber(line.substr(eq + 1));
  if (!id) { reply("error:3"); return LineResult::Done; }
  if (!value) { reply("error:2"); return LineResult::Done; }
  if (*value < 0) { reply("error:4"); return LineResult::Done; }
  if (!settings_.count(int(*id))) { reply("error:3"); return LineResult::Done; }
  if (int(*id) == 20 && *value != 0 && settings_[22] != 1) {  // soft limits need homing
    reply("error:10");
    return LineResult::Done;
  }
  settings_[int(*id)] = int(*id) < 100 && int(*id) != 11 && int(*id) != 12 && int(*id) != 24 && int(*id) != 25 &&
                                    int(*id) != 27
                            ? std::trunc(*value)
                            : *value;
  if (int(*id) == 22 && *value == 0) settings_[20] = 0;  // disabling homing disables soft limits
  applySettings();
  reply("ok");
  return LineResult::Done;
}

// limits.c limits_go_home, homing direction mask 0: cycle 0 homes Z, cycle 1 X and Y together.
// Each cycle approaches the switches in + direction at the seek rate $25 (at most 1.5 x the
// axes' max travel $13x), pulls off $27, approaches again at the feed rate $24 and pulls off
// again; the machine position is then -$27 (no HOMING_FORCE_SET_ORIGIN). Without a switch the
// first approach runs its whole search distance (the axis counted from 0) and ends in ALARM:9,
// and the board resets as after mc_reset: the $H line's "ok", the banner and the unlock
// message 0.6 s later. While
// homing, '?' is not answered and received lines wait. Timing: one block per phase (the axes
// of cycle 1 arrive together), each followed by the $26 debounce.
SimMachine::LineResult SimMachine::home() {
  if (homing_) return LineResult::Blocked;  // the cycle runs; the ok comes at its end
  if (homingSucceeded_) {
    homingSucceeded_ = false;
    state_ = MachineState::Idle;
    reply("ok");
    return LineResult::Done;
  }
  planner_.clear();
  homingMoves_.clear();
  homingFails_ = false;
  const double seek = settings_[25], feed = settings_[24], pullOff = settings_[27];
  Axes3 at = planner_.position();
  for (const std::vector<size_t>& cycle : {std::vector<size_t>{2}, std::vector<size_t>{0, 1}}) {
    double search = 0.0;
    for (size_t i : cycle) search = std::max(search, 1.5 * settings_[int(130 + i)]);
    const double rate = seek * std::sqrt(double(cycle.size()));
    Axes3 approach = at;
    bool found = true;
    for (size_t i : cycle) {
      found = found && config_.homingSwitches && at[i] <= 0.0 && -at[i] <= search;
      approach[i] = at[i] + search;
    }
    if (!found) {  // the switch is not within the search distance
      // limits_go_home zeroes the cycle's axes before each approach: after the failed search
      // they read the search distance, wherever they started.
      Axes3 zeroed = at;
      for (size_t i : cycle) {
        zeroed[i] = 0.0;
        approach[i] = search;
      }
      redefinePosition(zeroed);
      homingMoves_.push_back({approach, rate});
      homingFails_ = true;
      break;
    }
    Axes3 atSwitch = at, pulledOff = at;
    for (size_t i : cycle) {
      atSwitch[i] = 0.0;
      pulledOff[i] = -pullOff;
    }
    homingMoves_.push_back({atSwitch, rate});
    homingMoves_.push_back({pulledOff, rate});
    homingMoves_.push_back({atSwitch, feed * std::sqrt(double(cycle.size()))});
    homingMoves_.push_back({pulledOff, rate});
    at = pulledOff;
  }
  homing_ = true;
  homingPauseS_ = 0.0;
  state_ = MachineState::Home;
  homingStep();
  return homing_ ? LineResult::Blocked : LineResult::Done;
}

void SimMachine::homingStep() {
  if (!homing_ || !planner_.empty() || homingPauseS_ > 0.0) return;
  if (!homingMoves_.empty()) {
    const HomingMove m = homingMoves_.front();
    homingMoves_.pop_front();
    if (!planner_.add(m.target, m.feedPerMin / 60.0, false, false, false, /*systemMotion=*/true))
      planner_.setPosition(m.target);
    if (config_.instant)
      planner_.advance(0.0, false, true, [this](const Block& b) { trace_.moveTo(physicalDeg(b.target), false); });
    homingPauseS_ = homingMoves_.empty() && homingFails_ ? 0.0 : settings_[26] / 1000.0;
    if (!planner_.empty() || homingPauseS_ > 0.0) return;
    homingStep();
    return;
  }
  homing_ = false;
  if (homingFails_) {  // EXEC_ALARM_HOMING_FAIL_APPROACH, then mc_reset
    haveCurrent_ = false;
    rx_.clear();
    state_ = MachineState::Alarm;
    reply("ALARM:9");
    homingOkOwed_ = true;  // answered at the reset, before the banner
    resetAlarm_ = true;
    resetLeftS_ = config_.instant ? 1e-9 : 0.6;
    return;
  }
  homingSucceeded_ = true;  // the $H line completes on its next service
}

void SimMachine::reportParameters() {
  for (int i = 0; i < 6; ++i) reply("[G" + std::to_string(54 + i) + ":" + axesText(coords_[size_t(i)]) + "]");
  reply("[G28:" + axesText(g28_) + "]");
  reply("[G30:" + axesText(g30_) + "]");
  reply("[G92:" + axesText(g92_) + "]");
  reply("[TLO:0.000]");
  reply("[PRB:0.000,0.000,0.000:0]");
}

Axes3 SimMachine::coordSystem(int index) const { return coords_[size_t(index)]; }

}  // namespace fivebar::sim
