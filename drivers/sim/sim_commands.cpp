// SPDX-License-Identifier: GPL-3.0-or-later
// SimMachine: execution of "$" system commands and G-code lines (see sim_machine.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "drivers/protocol/grbl_parser.hpp"
#include "sim_machine.hpp"

namespace fivebar::sim {
namespace {

using grbl::MachineState;

constexpr std::string_view kAllowedLetters = "GMXYZFSPLNTIJKR";

bool supportedG(double g) {
  static constexpr double kCodes[] = {0,  1,  2,  3,    4,  10, 17, 21, 28, 28.1, 30, 30.1, 53,
                                      54, 55, 56, 57, 58, 59, 80, 90, 91, 92, 92.1, 94};
  return std::any_of(std::begin(kCodes), std::end(kCodes),
                     [g](double c) { return std::abs(g - c) < 1e-9; });
}
bool supportedM(double m) {
  static constexpr double kCodes[] = {0, 1, 2, 3, 4, 5, 8, 9, 30};  // no M7: not compiled in
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
    if (word.letter == 'G' && jog &&
        !(word.value == 90 || word.value == 91 || word.value == 21 || word.value == 53))
      return 16;
    if (word.letter == 'M' && !supportedM(word.value)) return 20;
  }
  return 0;
}

}  // namespace

SimMachine::LineResult SimMachine::executeGcode(const std::string& line, bool jog) {
  if (!arcSegments_.empty()) {  // an arc's segments wait for planner room before the ok
    while (!arcSegments_.empty() && !planner_.full()) {
      addBlock(arcSegments_.front(), arcFeedPerMin_, false, false);
      arcSegments_.pop_front();
    }
    if (!arcSegments_.empty()) return LineResult::Blocked;
    reply("ok");
    return LineResult::Done;
  }
  // protocol.c: G-code is locked in Alarm and while jogging.
  if (!jog && (state_ == MachineState::Alarm || state_ == MachineState::Jog)) {
    reply("error:9");
    return LineResult::Done;
  }
  const gcode::Words w = gcode::parseWords(line);
  if (const int err = checkWords(w, jog)) { reply("error:" + std::to_string(err)); return LineResult::Done; }
  const bool axisWords = w.has('X') || w.has('Y') || w.has('Z');
  const bool g10 = w.hasCode('G', 10), g92 = w.hasCode('G', 92), g921 = w.hasCode('G', 92.1);
  const bool goHome = w.hasCode('G', 28) || w.hasCode('G', 30);
  const bool storeHome = w.hasCode('G', 28.1) || w.hasCode('G', 30.1);
  const bool offsets = g10 || g92 || g921;
  const bool spindle = w.hasCode('M', 3) || w.hasCode('M', 4) || w.hasCode('M', 5) ||
                       (w.has('S') && spindleOn_);
  const bool programPause = !jog && w.hasCode('M', 0);
  const bool programEnd = !jog && (w.hasCode('M', 2) || w.hasCode('M', 30));
  int select = -1;
  for (int i = 0; i < 6; ++i)
    if (w.hasCode('G', 54 + i)) select = i;
  const bool needsSync = offsets || spindle || programPause || programEnd || w.hasCode('G', 4) ||
                         storeHome || select >= 0;
  if (needsSync && (!syncReady() || holding_)) return LineResult::Blocked;
  if ((axisWords || goHome) && !offsets && planner_.full()) return LineResult::Blocked;
  if (w.hasCode('G', 4)) {
    if (!w.has('P')) { reply("error:28"); return LineResult::Done; }
    if (!dwellStarted_) {
      dwellStarted_ = true;
      dwellLeftS_ = config_.instant ? 0.0 : *w.get('P');
    }
    if (dwellLeftS_ > 0.0) return LineResult::Blocked;
    dwellStarted_ = false;
  }
  // A line answered with an error leaves the modal state as it was (gcode.c checks before it
  // changes anything).
  const bool absoluteBefore = absolute_;
  const int motionBefore = motionMode_;
  const double feedBefore = feedPerMin_;
  const auto restoreModal = [&] {
    absolute_ = absoluteBefore;
    motionMode_ = motionBefore;
    feedPerMin_ = feedBefore;
  };
  if (!jog) {
    if (w.hasCode('G', 90)) absolute_ = true;
    if (w.hasCode('G', 91)) absolute_ = false;
    for (int m = 0; m < 4; ++m)
      if (w.hasCode('G', m) && m != 4) motionMode_ = m;
    if (w.has('F')) feedPerMin_ = *w.get('F');
    // gcode.c: the spindle is set (spindle_sync) when its mode changes, or its speed while it
    // runs; spindle_set_state and coolant_set_state put Ov: (and A:) in the next report.
    const bool wasOn = spindleOn_, wasCcw = spindleCcw_, wasFlood = coolantFlood_;
    const double speedBefore = spindleS_;
    if (w.has('S')) spindleS_ = *w.get('S');
    if (w.hasCode('M', 3) || w.hasCode('M', 4)) {
      spindleOn_ = true;
      spindleCcw_ = w.hasCode('M', 4);
    }
    if (w.hasCode('M', 5) || programEnd) spindleOn_ = false;
    if (w.hasCode('M', 8)) coolantFlood_ = true;
    if (w.hasCode('M', 9) || programEnd) coolantFlood_ = false;
    const bool spindleSet = spindleOn_ != wasOn || (spindleOn_ && spindleCcw_ != wasCcw) ||
                            (wasOn && spindleS_ != speedBefore);
    if (!checkMode_ && (spindleSet || coolantFlood_ != wasFlood || programEnd)) ovrCounter_ = 0;
    if (select >= 0 && select != coordSelect_) {
      coordSelect_ = select;
      updateWco();
    }
    if (checkMode_) {  // parsed, nothing executed
    } else {
      if ((spindle || programEnd) && config_.profile.tool.kind != ToolKind::ZAxis)
        setPen(penDownFor(spindleS_, spindleOn_, 0.0));
      // M0 (program pause), as GRBL: once the moves before it are done, a feed hold that only a
      // cycle start (~) ends; the lines after it wait in the buffer.
      if (programPause) {
        holding_ = true;
        state_ = MachineState::Hold;
      }
    }
    if (programEnd) {  // gcode.c: M2/M30 reset G1 G17 G90 G94 G54 M5 M9, then [MSG:Pgm End]
      setOverrides({});  // RESTORE_OVERRIDES_AFTER_PROGRAM_END (also in check mode)
      motionMode_ = 1;
      absolute_ = true;
      coordSelect_ = 0;
      updateWco();
      if (!checkMode_) wcoCounter_ = 0;  // system_flag_wco_change: WCO in the next report
      reply("[MSG:Pgm End]");
    }
  }
  const Axes3 m = planner_.plannedEnd();
  const char letters[3] = {'X', 'Y', 'Z'};
  if (g10) {
    const int l = int(w.get('L').value_or(0));
    const int pIndex = int(w.get('P').value_or(0));
    if ((l != 2 && l != 20) || pIndex < 0 || pIndex > 6) { reply("error:29"); return LineResult::Done; }
    const size_t index = size_t(pIndex == 0 ? coordSelect_ : pIndex - 1);
    for (size_t i = 0; i < 3; ++i)
      if (auto v = w.get(letters[i])) coords_[index][i] = l == 2 ? *v : m[i] - g92_[i] - *v;
    updateWco();
  } else if (g92) {
    for (size_t i = 0; i < 3; ++i)
      if (auto v = w.get(letters[i])) g92_[i] = m[i] - coords_[size_t(coordSelect_)][i] - *v;
    updateWco();
  } else if (g921) {
    g92_ = {};
    updateWco();
  } else if (storeHome) {
    (w.hasCode('G', 28.1) ? g28_ : g30_) = m;
  } else if (goHome) {
    if (axisWords && !motion(w, jog, true)) return LineResult::Done;
    const Axes3 home = w.hasCode('G', 28) ? g28_ : g30_;
    if (!checkMode_ && !withinLimits(home)) { softLimitViolated(); return LineResult::Done; }
    if (!checkMode_) addBlock(home, 0.0, true, false);
  } else if (axisWords && !jog && (motionMode_ == 2 || motionMode_ == 3)) {
    if (!arc(w, motionMode_ == 2)) { restoreModal(); return LineResult::Done; }
    if (!arcSegments_.empty()) return executeGcode(line, jog);  // waits for planner room
  } else if (axisWords) {
    if (!motion(w, jog, motionMode_ == 0)) { restoreModal(); return LineResult::Done; }
  }
  reply("ok");
  return LineResult::Done;
}

// Plans one straight move. Replies itself only on failure (error or alarm) and returns false
// then; the caller sends "ok" otherwise.
bool SimMachine::motion(const gcode::Words& w, bool jog, bool rapidMove) {
  const bool machineCoords = w.hasCode('G', 53);
  const bool absolute = machineCoords || (jog ? (w.hasCode('G', 90) || (absolute_ && !w.hasCode('G', 91)))
                                              : absolute_);
  const double feed = jog ? w.get('F').value_or(0.0) : feedPerMin_;
  const bool rapid = !jog && rapidMove;
  if (!rapid && feed <= 0.0) { reply("error:22"); return false; }
  const Axes3 end = planner_.plannedEnd();
  Axes3 target = end;
  const char letters[3] = {'X', 'Y', 'Z'};
  for (size_t i = 0; i < 3; ++i)
    if (auto v = w.get(letters[i]))
      target[i] = machineCoords ? *v : absolute ? *v + wco_[i] : end[i] + *v;
  if (!withinLimits(target)) {
    if (jog) reply("error:15");
    else softLimitViolated();
    return false;
  }
  if (checkMode_) return true;
  addBlock(target, feed, rapid, jog);
  return true;
}

void SimMachine::addBlock(const Axes3& target, double feedPerMin, bool rapid, bool jog) {
  const Axes3 end = planner_.plannedEnd();
  const bool zTool = config_.profile.tool.kind == ToolKind::ZAxis;
  const bool penDown = zTool ? penDownFor(0, false, end[2] - wco_[2]) &&
                                   penDownFor(0, false, target[2] - wco_[2])
                             : penDown_;
  if (planner_.add(target, feedPerMin / 60.0, rapid, penDown, jog)) {
    if (state_ == MachineState::Idle) state_ = jog ? MachineState::Jog : MachineState::Run;
    if (config_.instant && !holding_)
      planner_.advance(0.0, false, true, [this](const Block& b) { blockDone(b); });
  }
}

// G2/G3 in the XY plane as gcode.c checks them and motion_control.c mc_arc cuts them into
// segments within $12 of the arc (here in the joint plane: X/Y are degrees).
bool SimMachine::arc(const gcode::Words& w, bool clockwise) {
  if (feedPerMin_ <= 0.0) { reply("error:22"); return false; }
  const Axes3 pos = planner_.plannedEnd();
  Axes3 target = pos;
  const char letters[3] = {'X', 'Y', 'Z'};
  for (size_t i = 0; i < 3; ++i)
    if (auto v = w.get(letters[i])) target[i] = absolute_ ? *v + wco_[i] : pos[i] + *v;
  const double x = target[0] - pos[0], y = target[1] - pos[1];
  double offX = 0.0, offY = 0.0, radius = 0.0;
  if (auto r = w.get('R')) {
    if (x == 0.0 && y == 0.0) { reply("error:33"); return false; }
    double h = 4.0 * *r * *r - x * x - y * y;
    if (h < 0.0) { reply("error:34"); return false; }
    h = -std::sqrt(h) / std::hypot(x, y);
    if (!clockwise) h = -h;
    radius = *r;
    if (radius < 0.0) { h = -h; radius = -radius; }
    offX = 0.5 * (x - y * h);
    offY = 0.5 * (y + x * h);
  } else {
    if (!w.has('I') && !w.has('J')) { reply("error:26"); return false; }
    offX = w.get('I').value_or(0.0);
    offY = w.get('J').value_or(0.0);
    radius = std::hypot(offX, offY);
    const double targetR = std::hypot(x - offX, y - offY);
    const double deltaR = std::abs(targetR - radius);
    if (deltaR > 0.005 && (deltaR > 0.5 || deltaR > 0.001 * radius)) { reply("error:33"); return false; }
  }
  const double cx = pos[0] + offX, cy = pos[1] + offY;
  const double r0 = -offX, r1 = -offY, t0 = target[0] - cx, t1 = target[1] - cy;
  double travel = std::atan2(r0 * t1 - r1 * t0, r0 * t0 + r1 * t1);
  constexpr double kEps = 5e-7;
  if (clockwise) { if (travel >= -kEps) travel -= 2.0 * M_PI; }
  else if (travel <= kEps) travel += 2.0 * M_PI;
  const double tol = settings_[12];
  const auto segments = std::size_t(std::floor(std::abs(0.5 * travel * radius) /
                                               std::sqrt(tol * (2.0 * radius - tol))));
  if (!withinLimits(target)) { softLimitViolated(); return false; }
  if (checkMode_) return true;
  arcFeedPerMin_ = feedPerMin_;
  for (std::size_t k = 1; k < segments; ++k) {
    const double a = travel * double(k) / double(segments);
    const double c = std::cos(a), s = std::sin(a);
    arcSegments_.push_back({cx + r0 * c - r1 * s, cy + r0 * s + r1 * c,
                            pos[2] + (target[2] - pos[2]) * double(k) / double(segments)});
  }
  arcSegments_.push_back(target);
  return true;
}

// protocol.c "Execute overrides": the flags gathered since the last check, once; a change puts
// Ov: in the next report and re-plans the queued blocks. A status request in the same chunk was
// served first, as protocol_exec_rt_system serves EXEC_STATUS_REPORT before the overrides.
void SimMachine::applyOverrides() {
  if (overrideFlags_.empty()) return;
  const grbl::MotionOverrides next = overrideFlags_.applyTo(overrides_);
  overrideFlags_.clear();
  if (next == overrides_) return;
  setOverrides(next);
  ovrCounter_ = 0;
}

void SimMachine::setOverrides(const grbl::MotionOverrides& overrides) {
  overrides_ = overrides;
  planner_.setOverrides(overrides.feedPct, overrides.rapidPct);
}

}  // namespace fivebar::sim
