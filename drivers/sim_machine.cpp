#include "sim_machine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "gcode_job.hpp"
#include "grbl_protocol.hpp"

namespace fivebar::sim {
namespace {

using grbl::MachineState;

constexpr const char* kBanner = "Grbl 1.1h ['$' for help]";
constexpr std::size_t kRxCapacity = 128;
constexpr std::size_t kMaxLine = 80;
constexpr int kWcoEveryReports = 10;

std::string fmt3(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", std::abs(v) < 0.0005 ? 0.0 : v);
  return buf;
}

std::string axes(const Axes3& a) { return fmt3(a[0]) + "," + fmt3(a[1]) + "," + fmt3(a[2]); }

bool isIntegerSetting(int id) {
  return id < 100 && id != 11 && id != 12 && !(id >= 24 && id <= 27);
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

SimMachine::SimMachine(const SimConfig& config) : config_(config), planner_(MotionLimits{}) {
  const MachineProfile& p = config.profile;
  const bool limited = p.limits.theta1Max < 1e8 && p.limits.theta2Max < 1e8;
  const double zRate = p.tool.zFeedMmPerMin;
  settings_ = {{0, 10},   {1, 25},   {2, 0},    {3, 0},    {4, 0},    {5, 0},   {6, 0},
               {10, 1},   {11, p.motors.junctionDeviationDeg},
               {12, 0.002}, {13, 0}, {20, limited ? 1 : 0}, {21, 0},
               {22, p.hasHomingSwitches ? 1 : 0}, {23, 0}, {24, 25}, {25, 500}, {26, 250},
               {27, 1},   {30, 1000}, {31, 0},  {32, p.tool.kind == ToolKind::Laser ? 1 : 0},
               {100, p.motors.stepsPerDeg1}, {101, p.motors.stepsPerDeg2}, {102, 100},
               {110, degFromRad(p.motors.maxSpeedRadPerS1) * 60.0},
               {111, degFromRad(p.motors.maxSpeedRadPerS2) * 60.0}, {112, zRate},
               {120, degFromRad(p.motors.maxAccelRadPerS2_1)},
               {121, degFromRad(p.motors.maxAccelRadPerS2_2)}, {122, 200},
               {130, limited ? degFromRad(p.limits.theta1Max - p.limits.theta1Min) : 360},
               {131, limited ? degFromRad(p.limits.theta2Max - p.limits.theta2Min) : 360},
               {132, 50}};
  applySettings();
  const double z = p.tool.kind == ToolKind::ZAxis ? p.tool.zUpMm : 0.0;
  planner_.setPosition(planner_.quantize(
      {degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2), z}));
  out_ += std::string("\r\n") + kBanner + "\r\n";
  if (settings_[22] == 1) {
    state_ = MachineState::Alarm;
    reply("[MSG:'$H'|'$X' to unlock]");
  }
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
  if (linkDropped_) return;
  for (char c : bytes) {
    if (grbl::realtime::isRealtime(c)) {
      realtimeByte(c);
    } else if (rx_.size() < kRxCapacity) {
      rx_.push_back(c);
    } else {
      ++rxOverflow_;  // the firmware drops bytes that do not fit
    }
  }
  serviceLines();
}

void SimMachine::realtimeByte(char c) {
  namespace rt = grbl::realtime;
  if (c == rt::kStatus) {
    reportStatus();
  } else if (c == rt::kFeedHold) {
    if (state_ == MachineState::Run) {
      holding_ = true;
      state_ = MachineState::Hold;
    } else if (state_ == MachineState::Jog) {
      jogCancel_ = true;  // a feed hold during a jog cancels it
    }
  } else if (c == rt::kCycleStart) {
    if (state_ == MachineState::Hold) {
      holding_ = false;
      state_ = planner_.empty() ? MachineState::Idle : MachineState::Run;
      serviceLines();
    }
  } else if (c == rt::kSoftReset) {
    softReset();
  } else if (c == rt::kJogCancel) {
    if (state_ == MachineState::Jog) jogCancel_ = true;
  }
  // Overrides (0x90-0x9D) are accepted and have no effect on the simulated timing.
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
  penDown_ = down;
}

void SimMachine::softReset() {
  const bool moving = planner_.moving() ||
                      ((state_ == MachineState::Run || state_ == MachineState::Jog) &&
                       !planner_.empty());
  const bool alarmAfter = moving || state_ == MachineState::Alarm;
  setPen(false);
  planner_.clear();
  rx_.clear();
  haveCurrent_ = false;
  holding_ = jogCancel_ = criticalAlarm_ = false;
  dwellLeftS_ = 0.0;
  dwellStarted_ = false;
  absolute_ = rapidMode_ = true;
  feedPerMin_ = spindleS_ = 0.0;
  spindleOn_ = false;
  if (moving) reply("ALARM:3");
  out_ += std::string("\r\n") + kBanner + "\r\n";
  state_ = alarmAfter ? MachineState::Alarm : MachineState::Idle;
  if (alarmAfter) reply("[MSG:'$H'|'$X' to unlock]");
}

void SimMachine::raiseAlarm(int code, bool critical) {
  setPen(false);
  planner_.clear();
  spindleOn_ = false;
  holding_ = jogCancel_ = false;
  haveCurrent_ = false;
  state_ = MachineState::Alarm;
  reply("ALARM:" + std::to_string(code));
  if (critical) {
    criticalAlarm_ = true;
    reply("[MSG:Reset to continue]");
  }
}

bool SimMachine::fireFault(FaultKind kind) const {
  return !faultFired_ && config_.fault.kind == kind &&
         linesReceived_ == config_.fault.line + (kind == FaultKind::ErrorOn ? 0 : 1);
}

void SimMachine::serviceLines() {
  while (!criticalAlarm_ && !linkDropped_) {
    if (!haveCurrent_) {
      const size_t end = rx_.find_first_of("\r\n");
      if (end == std::string::npos) return;
      current_ = rx_.substr(0, end);
      rx_.erase(0, end + 1);
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
  if (linkDropped_ || criticalAlarm_) return;
  const bool hadBlocks = !planner_.empty();
  planner_.advance(machineDtS, holding_ || jogCancel_, config_.instant,
                   [this](const Block& b) { blockDone(b); });
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
  return job::penDownFor(config_.profile.tool, spindleOn, spindleS, z);
}

bool SimMachine::withinLimits(const Axes3& machineTarget) const {
  if (settings_.at(20) != 1) return true;
  const JointLimits& l = config_.profile.limits;
  const double slack = 0.5 / planner_.limits().stepsPerUnit[0];
  return machineTarget[0] >= degFromRad(l.theta1Min) - slack &&
         machineTarget[0] <= degFromRad(l.theta1Max) + slack &&
         machineTarget[1] >= degFromRad(l.theta2Min) - slack &&
         machineTarget[1] <= degFromRad(l.theta2Max) + slack;
}

void SimMachine::reportStatus() {
  std::string s = "<";
  s += grbl::toString(state_);
  if (state_ == MachineState::Hold) s += planner_.moving() ? ":1" : ":0";
  s += "|MPos:" + axes(planner_.position());
  s += "|Bf:" + std::to_string(int(Planner::kCapacity - planner_.size())) + "," +
       std::to_string(int(kRxCapacity - rx_.size()));
  s += "|FS:" + std::to_string(long(std::lround(planner_.speed() * 60.0))) + "," +
       std::to_string(long(std::lround(spindleOn_ ? spindleS_ : 0.0)));
  if (reportsSinceWco_ == 0) s += "|WCO:" + axes(wco_) + "|Ov:100,100,100";
  reportsSinceWco_ = (reportsSinceWco_ + 1) % kWcoEveryReports;
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
