// SimMachine: the "$" system commands, as GRBL 1.1h's system.c and settings.c answer them.
#include <cmath>
#include <cstdio>

#include "grbl_parser.hpp"
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
    // Homing with switches: the pull-off position, -$27 in machine coordinates on every axis
    // (limits.c without HOMING_FORCE_SET_ORIGIN, homing direction mask 0).
    const double pullOff = settings_[27];
    planner_.setPosition(planner_.quantize({-pullOff, -pullOff, -pullOff}));
    state_ = MachineState::Idle;
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
