// SimMachine: execution of "$" system commands and G-code lines (see sim_machine.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "grbl_parser.hpp"
#include "sim_machine.hpp"

namespace fivebar::sim {
namespace {

using grbl::MachineState;

constexpr std::string_view kAllowedLetters = "GMXYZFSPLNT";

bool supportedG(double g) {
  static constexpr double kCodes[] = {0, 1, 4, 10, 17, 21, 54, 90, 91, 92, 94};
  return std::any_of(std::begin(kCodes), std::end(kCodes),
                     [g](double c) { return std::abs(g - c) < 1e-9; });
}
bool supportedM(double m) {
  static constexpr double kCodes[] = {0, 2, 3, 4, 5, 8, 9, 30};
  return std::any_of(std::begin(kCodes), std::end(kCodes),
                     [m](double c) { return std::abs(m - c) < 1e-9; });
}

// GRBL error code for a line's words, 0 when every word is one this machine understands.
int checkWords(const gcode::Words& w, bool jog) {
  if (w.status == gcode::WordsStatus::BadNumber) return 2;
  if (!w.ok()) return 1;
  for (const gcode::Word& word : w.words) {
    if (kAllowedLetters.find(word.letter) == std::string_view::npos) return 20;
    if (jog && std::string_view("GXYZFN").find(word.letter) == std::string_view::npos) return 16;
    if (word.letter == 'G' && !supportedG(word.value)) return 20;
    if (word.letter == 'G' && jog && !(word.value == 90 || word.value == 91 || word.value == 21))
      return 16;
    if (word.letter == 'M' && !supportedM(word.value)) return 20;
  }
  return 0;
}

}  // namespace

SimMachine::LineResult SimMachine::executeSystem(const std::string& line) {
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
    if (state_ == MachineState::Run || state_ == MachineState::Hold) { reply("error:8"); return LineResult::Done; }
    reportSettings();
  } else if (line == "$G") {
    reply(std::string("[GC:") + (rapidMode_ ? "G0" : "G1") + " G54 G17 G21 " +
          (absolute_ ? "G90" : "G91") + " G94 " + (spindleOn_ ? "M3" : "M5") + " M9 T0 F" +
          std::to_string(long(feedPerMin_)) + " S" + std::to_string(long(spindleS_)) + "]");
  } else if (!idleOrAlarm) {
    reply("error:8");
    return LineResult::Done;
  } else if (line == "$I") {
    reply("[VER:1.1h.20190830:fivebar-sim]");
    reply("[OPT:V,15,128]");
  } else if (line == "$#") {
    const Axes3& w = wco_;
    char buf[96];
    std::snprintf(buf, sizeof buf, "[G54:%.3f,%.3f,%.3f]", w[0], w[1], w[2]);
    reply(buf);
  } else if (line == "$X") {
    if (state_ == MachineState::Alarm) reply("[MSG:Caution: Unlocked]");
    state_ = MachineState::Idle;
  } else if (line == "$H") {
    if (settings_[22] != 1) { reply("error:5"); return LineResult::Done; }
    const MachineProfile& p = config_.profile;
    planner_.setPosition(planner_.quantize({degFromRad(p.homeAngles.theta1),
                                            degFromRad(p.homeAngles.theta2),
                                            planner_.position()[2]}));
    state_ = MachineState::Idle;
  } else {
    const size_t eq = line.find('=');
    const auto id = eq == std::string::npos ? std::nullopt
                                            : grbl::parseNumber(line.substr(1, eq - 1));
    const auto value = eq == std::string::npos ? std::nullopt : grbl::parseNumber(line.substr(eq + 1));
    if (!id || !settings_.count(int(*id))) { reply("error:3"); return LineResult::Done; }
    if (!value) { reply("error:2"); return LineResult::Done; }
    if (*value < 0) { reply("error:4"); return LineResult::Done; }
    settings_[int(*id)] = *value;
    applySettings();
  }
  reply("ok");
  return LineResult::Done;
}

SimMachine::LineResult SimMachine::executeGcode(const std::string& line, bool jog) {
  if (!jog && state_ == MachineState::Alarm) { reply("error:9"); return LineResult::Done; }
  const gcode::Words w = gcode::parseWords(line);
  if (const int err = checkWords(w, jog)) { reply("error:" + std::to_string(err)); return LineResult::Done; }
  const bool axisWords = w.has('X') || w.has('Y') || w.has('Z');
  const bool offsets = w.hasCode('G', 10) || w.hasCode('G', 92);
  const bool spindle = w.hasCode('M', 3) || w.hasCode('M', 4) || w.hasCode('M', 5) ||
                       (w.has('S') && spindleOn_);
  const bool programPause = !jog && w.hasCode('M', 0);
  const bool needsSync = offsets || spindle || programPause || w.hasCode('G', 4) ||
                         w.hasCode('M', 2) || w.hasCode('M', 30);
  if (needsSync && (!syncReady() || holding_)) return LineResult::Blocked;
  if (axisWords && !offsets && planner_.full()) return LineResult::Blocked;
  if (w.hasCode('G', 4)) {
    if (!w.has('P')) { reply("error:28"); return LineResult::Done; }
    if (!dwellStarted_) {
      dwellStarted_ = true;
      dwellLeftS_ = config_.instant ? 0.0 : *w.get('P');
    }
    if (dwellLeftS_ > 0.0) return LineResult::Blocked;
    dwellStarted_ = false;
  }
  if (!jog) {
    if (w.hasCode('G', 90)) absolute_ = true;
    if (w.hasCode('G', 91)) absolute_ = false;
    if (w.hasCode('G', 0)) rapidMode_ = true;
    if (w.hasCode('G', 1)) rapidMode_ = false;
    if (w.has('F')) feedPerMin_ = *w.get('F');
    if (w.has('S')) spindleS_ = *w.get('S');
    if (w.hasCode('M', 3) || w.hasCode('M', 4)) spindleOn_ = true;
    if (w.hasCode('M', 5) || w.hasCode('M', 2) || w.hasCode('M', 30)) spindleOn_ = false;
    if (spindle && config_.profile.tool.kind != ToolKind::ZAxis)
      setPen(penDownFor(spindleS_, spindleOn_, 0.0));
    // M0 (program pause), as GRBL: once the moves before it are done, a feed hold that only a
    // cycle start (~) ends; the lines after it wait in the buffer.
    if (programPause) {
      holding_ = true;
      state_ = MachineState::Hold;
    }
  }
  if (offsets && axisWords) {
    const Axes3 m = planner_.position();
    const bool l2 = w.hasCode('G', 10) && w.get('L').value_or(0) == 2;
    const char letters[3] = {'X', 'Y', 'Z'};
    const Axes3 before = wco_;
    for (size_t i = 0; i < 3; ++i)
      if (auto v = w.get(letters[i])) wco_[i] = l2 ? *v : m[i] - *v;
    // GRBL 1.1 reports a changed work offset in the very next status report.
    if (wco_ != before) reportsSinceWco_ = 0;
  } else if (axisWords) {
    if (!motion(w, jog)) return LineResult::Done;
  }
  reply("ok");
  return LineResult::Done;
}

// Plans one move. Replies itself only on failure (error or alarm) and returns false then; the
// caller sends "ok" otherwise.
bool SimMachine::motion(const gcode::Words& w, bool jog) {
  const bool absolute = jog ? !w.hasCode('G', 91) : absolute_;
  const double feed = jog ? w.get('F').value_or(0.0) : feedPerMin_;
  const bool rapid = !jog && rapidMode_;
  if (!rapid && feed <= 0.0) { reply("error:22"); return false; }
  const Axes3 end = planner_.plannedEnd();
  Axes3 target = end;
  const char letters[3] = {'X', 'Y', 'Z'};
  for (size_t i = 0; i < 3; ++i)
    if (auto v = w.get(letters[i])) target[i] = absolute ? *v + wco_[i] : end[i] + *v;
  if (!withinLimits(target)) {
    if (jog) reply("error:15");
    else raiseAlarm(2, true);
    return false;
  }
  const bool zTool = config_.profile.tool.kind == ToolKind::ZAxis;
  const bool penDown = zTool ? penDownFor(0, false, end[2] - wco_[2]) &&
                                   penDownFor(0, false, target[2] - wco_[2])
                             : penDown_;
  if (planner_.add(target, feed / 60.0, rapid, penDown, jog)) {
    if (state_ == MachineState::Idle) state_ = jog ? MachineState::Jog : MachineState::Run;
    if (config_.instant && !holding_)
      planner_.advance(0.0, false, true, [this](const Block& b) { blockDone(b); });
  }
  return true;
}

}  // namespace fivebar::sim
