// SPDX-License-Identifier: GPL-3.0-or-later
#include "gcode_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "drivers/protocol/gcode_words.hpp"
#include "drivers/protocol/grbl_protocol.hpp"

namespace fivebar::stream {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", std::abs(v) < 0.0005 ? 0.0 : v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// Modal state while reading the file.
struct Modal {
  bool absolute = true;
  bool spindleOn = false;
  double spindleS = 0.0;
  double feed = 0.0;
  bool rapid = true;
  std::array<double, 3> pos{0.0, 0.0, 0.0};
};

bool sameStep(double a, double b, double stepsPerUnit) {
  if (stepsPerUnit <= 0.0) return a == b;
  return std::lround(a * stepsPerUnit) == std::lround(b * stepsPerUnit);
}

// A pen-down point is a motion drawn with the pen down, or the pen-up travel that ends where
// the next stroke starts.
void markPenDownPoints(GcodeJob& job) {
  bool nextMotionDraws = false;
  for (std::size_t i = job.lines.size(); i-- > 0;) {
    JobLine& l = job.lines[i];
    if (!l.motion) continue;
    l.penDownPoint = l.penDownDuring || nextMotionDraws;
    nextMotionDraws = l.penDownDuring;
  }
}

}  // namespace

bool penDownFor(const ToolSettings& t, bool spindleOn, double spindleS, double zMm) {
  switch (t.kind) {
    case ToolKind::PenServo:
      return spindleOn && std::abs(spindleS - t.penDownS) < std::abs(spindleS - t.penUpS);
    case ToolKind::Laser: return spindleOn && spindleS > 0.0;
    case ToolKind::ZAxis: {
      const double mid = 0.5 * (t.zUpMm + t.zDownMm);
      return t.zDownMm < t.zUpMm ? zMm <= mid : zMm >= mid;
    }
  }
  return false;
}

JobRules rulesFor(const MachineProfile& p) {
  JobRules r;
  r.tool = p.tool;
  r.stepsPerDeg1 = p.motors.stepsPerDeg1;
  r.stepsPerDeg2 = p.motors.stepsPerDeg2;
  r.startDeg = {degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2)};
  return r;
}

GcodeJob parseJob(std::string_view text, const JobRules& rules) {
  GcodeJob job;
  Modal m;
  m.pos = {rules.startDeg[0], rules.startDeg[1], rules.tool.kind == ToolKind::ZAxis ? rules.tool.zUpMm : 0.0};
  int fileLine = 0;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view raw = text.substr(start, end - start);
    start = end + 1;
    ++fileLine;
    const std::string compacted = gcode::compact(raw);
    if (compacted.empty()) {
      if (end == text.size()) break;
      continue;
    }
    const std::string where = "line " + std::to_string(fileLine) + ": ";
    if (int(compacted.size()) > grbl::kMaxLineChars)
      job.issues.push_back(where + "longer than GRBL's " + std::to_string(grbl::kMaxLineChars) +
                           " characters after removing comments and spaces");
    const gcode::Words w = gcode::parseWords(raw);
    if (!w.ok()) job.issues.push_back(where + "not valid G-code ('" + compacted + "')");
    if (w.hasCode('G', 2) || w.hasCode('G', 3))
      job.issues.push_back(where + "arc (G2/G3) sent to a joint-space machine");
    if (w.hasCode('G', 90)) m.absolute = true;
    if (w.hasCode('G', 91)) { m.absolute = false; job.relativeMoves = true; }
    if (w.has('F')) m.feed = *w.get('F');
    if (w.hasCode('G', 0)) m.rapid = true;
    if (w.hasCode('G', 1)) m.rapid = false;
    if (w.has('S')) m.spindleS = *w.get('S');
    if (w.hasCode('M', 3) || w.hasCode('M', 4)) m.spindleOn = true;
    if (w.hasCode('M', 5) || w.hasCode('M', 2) || w.hasCode('M', 30)) m.spindleOn = false;
    JobLine line;
    line.fileLine = fileLine;
    line.text = compacted;
    const bool offsets = w.hasCode('G', 10) || w.hasCode('G', 92) || w.hasCode('G', 4);
    const bool penBefore = penDownFor(rules.tool, m.spindleOn, m.spindleS, m.pos[2]);
    if (!offsets && !compacted.starts_with("$") && (w.has('X') || w.has('Y') || w.has('Z'))) {
      auto target = m.pos;
      const char letters[3] = {'X', 'Y', 'Z'};
      for (size_t i = 0; i < 3; ++i)
        if (auto v = w.get(letters[i])) target[i] = m.absolute ? *v : m.pos[i] + *v;
      line.motion = !(sameStep(target[0], m.pos[0], rules.stepsPerDeg1) &&
                      sameStep(target[1], m.pos[1], rules.stepsPerDeg2) &&
                      sameStep(target[2], m.pos[2], 100.0));
      const bool penAfterMove = penDownFor(rules.tool, m.spindleOn, m.spindleS, target[2]);
      line.penDownDuring = line.motion && penBefore && penAfterMove;
      m.pos = target;
    }
    line.penDownAfter = penDownFor(rules.tool, m.spindleOn, m.spindleS, m.pos[2]);
    line.endDeg = {m.pos[0], m.pos[1]};
    line.feedPerMin = m.feed;
    line.rapidModal = m.rapid;
    job.lines.push_back(std::move(line));
    if (end == text.size()) break;
  }
  markPenDownPoints(job);
  return job;
}

std::vector<std::vector<Point2>> strokesOf(const GcodeJob& job, const JobRules& rules) {
  std::vector<std::vector<Point2>> strokes;
  Point2 pos = rules.startDeg;
  bool inStroke = false;
  for (const JobLine& l : job.lines) {
    if (!l.motion) {
      if (!l.penDownAfter) inStroke = false;
      continue;
    }
    if (l.penDownDuring) {
      if (!inStroke) strokes.push_back({pos});
      inStroke = true;
      strokes.back().push_back(l.endDeg);
    } else {
      inStroke = false;
    }
    pos = l.endDeg;
  }
  return strokes;
}

std::optional<std::size_t> lastPenDownPoint(const GcodeJob& job, std::size_t completed) {
  const std::size_t n = std::min(completed + 1, job.lines.size());
  for (std::size_t i = n; i-- > 0;)
    if (job.lines[i].penDownPoint) return i;
  return std::nullopt;
}

std::vector<std::string> penUpCommands(const ToolSettings& t) {
  const std::string dwell = "G4P" + num(t.penUpDelayS);
  switch (t.kind) {
    case ToolKind::PenServo:
      return {t.penUpS > 0.0 ? "M3S" + num(t.penUpS) : std::string("M5"), dwell};
    case ToolKind::Laser: return {"M5"};
    case ToolKind::ZAxis: return {"G0Z" + num(t.zUpMm)};
  }
  return {};
}

std::vector<std::string> penDownCommands(const ToolSettings& t) {
  switch (t.kind) {
    case ToolKind::PenServo: return {"M3S" + num(t.penDownS), "G4P" + num(t.penDownDelayS)};
    case ToolKind::Laser: return {"M4S" + num(t.laserPowerS)};
    case ToolKind::ZAxis: return {"G1Z" + num(t.zDownMm) + "F" + num(t.zFeedMmPerMin)};
  }
  return {};
}

std::string moveTo(const Point2& targetDeg, bool rapid, double feedPerMin) {
  std::string s = std::string(rapid ? "G0" : "G1") + "X" + num(targetDeg[0]) + "Y" + num(targetDeg[1]);
  if (!rapid && feedPerMin > 0.0) s.append("F").append(num(feedPerMin));
  return s;
}

}  // namespace fivebar::stream
