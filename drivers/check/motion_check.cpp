// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion_check.hpp"

#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "core/planning/safety.hpp"
#include "drivers/protocol/gcode_words.hpp"
#include "drivers/protocol/grbl_parser.hpp"
#include "soft_limits.hpp"

namespace fivebar::motion {
namespace {


bool isCode(double value, double code) { return std::abs(value - code) < 1e-6; }

// The kinematic angles of a board position: X, Y are commanded angles (what GRBL counts); the
// checks work on kinematic = commanded + the profile's zero offsets (docs/calibration.md).
JointAngles jointsOf(const MachineProfile& profile, const Axes3& workDeg) {
  return kinematicFromCommanded(profile.calibration, {radFromDeg(workDeg[0]), radFromDeg(workDeg[1])});
}

LineCheck refuse(Message reason) {
  LineCheck c;
  c.verdict = Verdict::Refused;
  c.reason = std::move(reason);
  return c;
}

// The reason a G word makes the line uncheckable, or an empty message when it is fine.
Message refusedCode(double g, bool jog) {
  if (isCode(g, 2) || isCode(g, 3))
    return FB_TR("MotionCheck",
                 "G2/G3 arcs are not arcs in joint space (X and Y are motor angles): plan the drawing "
                 "with 'fivebar plan', which turns arcs into checked straight segments");
  if (g >= 38.0 && g < 39.0)
    return FB_TR("MotionCheck", "probing (G38) is not supported on a five-bar machine");
  if (isCode(g, 20))
    return FB_TR("MotionCheck",
                 "G20 (inches) would scale the motor angles by 25.4: X and Y are degrees, use G21");
  if (isCode(g, 10) || (g >= 92.0 && g < 93.0))
    return FB_TR("MotionCheck", "G10/G92 change the coordinates the checks rely on: %1").arg(referenceHint());
  if (g >= 55.0 && g < 60.0)
    return FB_TR("MotionCheck",
                 "G55-G59 select another work coordinate system; the checked link works in G54");
  if (jog && !(isCode(g, 90) || isCode(g, 91) || isCode(g, 53) || isCode(g, 21)))
    return FB_TR("MotionCheck", "a jog ($J=) takes only G90, G91, G53 and G21");
  return {};
}

// The board's soft-limit check (GRBL limits_soft_check on every target, in machine coordinates)
// of a line interpretLine accepted; an empty message when the board would take it.
Message softLimitRefusal(const LineCheck& c, const BoardPose& pose) {
  if (c.verdict != Verdict::Motion || !pose.softTravelDeg) return {};
  const std::array<double, 2>& travel = *pose.softTravelDeg;
  for (const Axes3& t : c.targetsWork) {
    const std::array<double, 2> machine{t[0] + pose.wco[0], t[1] + pose.wco[1]};
    const auto axis = setup::axisOutsideTravel(machine, travel);
    if (!axis) continue;
    const std::size_t a = std::size_t(*axis);
    Message outcome = c.jog ? FB_TR("MotionCheck", "the board would refuse the jog (error:15)")
                            : FB_TR("MotionCheck",
                                    "the board would stop with a soft-limit alarm (ALARM:2)");
    return FB_TR("MotionCheck",
                 "the target %1 takes motor %2 to %3 deg in machine coordinates, outside the "
                 "board's soft-limit travel %4..0 deg ($%5=%6): %7; home the machine or set its "
                 "reference so that the travel matches the profile, or choose a target inside it")
        .arg(anglesMessage(t[0], t[1]))
        .arg(*axis + 1)
        .arg(machine[a], 3)
        .arg(-travel[a], 3)
        .arg(130 + *axis)
        .arg(travel[a], 3)
        .arg(std::move(outcome));
  }
  return {};
}

}  // namespace

Message referenceHint() {
  return FB_TR("MotionCheck",
               "set the machine's reference with 'fivebar reference' (or home it with 'fivebar home')");
}

Message workspaceHint() {
  return FB_TR("MotionCheck", "choose a target inside the workspace (fivebar workspace shows it)");
}

std::string anglesText(double theta1Deg, double theta2Deg) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f) deg", theta1Deg, theta2Deg);
  return buf;
}

Message anglesMessage(double theta1Deg, double theta2Deg) {
  return FB_TR("MotionCheck", "(%1, %2) deg").arg(theta1Deg, 3).arg(theta2Deg, 3);
}

LineCheck interpretLine(std::string_view line, const BoardPose& pose) {
  const std::string text = gcode::compact(line);
  LineCheck out;
  if (text.empty()) return out;
  std::string_view body = text;
  if (text.rfind("$J=", 0) == 0) {
    out.jog = true;
    body.remove_prefix(3);
  } else if (text[0] == '$') {
    out.systemCommand = true;
    return out;
  }
  const gcode::Words w = gcode::parseWords(body);
  if (!w.ok()) return out;  // the board rejects it with error:N; nothing moves
  bool absolute = pose.absolute, machineCoords = false;
  std::optional<double> goHome;
  for (const gcode::Word& word : w.words) {
    if (word.letter != 'G') continue;
    if (Message why = refusedCode(word.value, out.jog); !why.empty()) return refuse(std::move(why));
    if (isCode(word.value, 90)) absolute = true;
    if (isCode(word.value, 91)) absolute = false;
    if (isCode(word.value, 53)) machineCoords = true;
    if (isCode(word.value, 28) || isCode(word.value, 30)) goHome = word.value;
  }
  const char letters[3] = {'X', 'Y', 'Z'};
  const bool jointWords = w.has('X') || w.has('Y');
  if (!jointWords && !goHome && !w.has('Z')) return out;
  Axes3 target = pose.workDeg;
  for (size_t i = 0; i < 3; ++i) {
    const auto v = w.get(letters[i]);
    if (!v) continue;
    if (machineCoords) target[i] = *v - pose.wco[i];
    else target[i] = absolute ? *v : pose.workDeg[i] + *v;
  }
  if (goHome) {
    const auto& stored = isCode(*goHome, 28) ? pose.g28Machine : pose.g30Machine;
    if (!stored)
      return refuse(FB_TR("MotionCheck",
                          "G28/G30 go to a position stored on the board, which is not known here; "
                          "move to the point with a G0 line instead"));
    if (w.has('X') || w.has('Y') || w.has('Z')) out.targetsWork.push_back(target);
    Axes3 home{};
    for (size_t i = 0; i < 3; ++i) home[i] = (*stored)[i] - pose.wco[i];
    out.targetsWork.push_back(home);
    out.verdict = Verdict::Motion;
    return out;
  }
  out.targetsWork.push_back(target);
  out.verdict = jointWords ? Verdict::Motion : Verdict::Pass;
  return out;
}

void applyLine(std::string_view line, const LineCheck& check, BoardPose& pose) {
  if (!check.ok() || check.systemCommand) return;
  if (!check.jog) {
    const gcode::Words w = gcode::parseWords(line);
    if (w.ok()) {
      if (w.hasCode('G', 90)) pose.absolute = true;
      if (w.hasCode('G', 91)) pose.absolute = false;
    }
  }
  if (!check.targetsWork.empty()) pose.workDeg = check.targetsWork.back();
}

LineCheck checkLine(const MachineProfile& profile, std::string_view line, const BoardPose& pose) {
  LineCheck c = interpretLine(line, pose);
  if (c.verdict != Verdict::Motion) return c;
  if (Message why = softLimitRefusal(c, pose); !why.empty()) return refuse(std::move(why));
  const MoveCheck here = checkPose(profile, jointsOf(profile, pose.workDeg));
  if (!here.ok())
    return refuse(FB_TR("MotionCheck",
                        "the machine's position %1 is not a safe pose of %2 (%3), so no move from "
                        "it can be checked: %4 first")
                      .arg(anglesMessage(pose.workDeg[0], pose.workDeg[1]))
                      .arg(profile.name)
                      .arg(std::string(toString(here.status)))
                      .arg(referenceHint()));
  Axes3 from = pose.workDeg;
  for (const Axes3& to : c.targetsWork) {
    const MoveCheck m = checkJointMove(profile, jointsOf(profile, from), jointsOf(profile, to));
    if (!m.ok())
      return refuse(FB_TR("MotionCheck",
                          "the move from %1 to %2 %3; %4")
                        .arg(anglesMessage(from[0], from[1]))
                        .arg(anglesMessage(to[0], to[1]))
                        .arg(describeMove(m))
                        .arg(workspaceHint()));
    from = to;
  }
  return c;
}

LinesCheck checkBoardLines(const std::vector<std::string>& lines, BoardPose pose) {
  LinesCheck out;
  for (const std::string& line : lines) {
    const LineCheck c = interpretLine(line, pose);
    if (!c.ok()) {
      out.reason = c.reason;
      return out;
    }
    if (Message why = softLimitRefusal(c, pose); !why.empty()) {
      out.reason = std::move(why);
      return out;
    }
    applyLine(line, c, pose);
    ++out.passing;
  }
  return out;
}

std::optional<BoardPose> boardPoseOf(const grbl::GrblProtocol& protocol) {
  const auto w = protocol.workPositionDeg();
  if (!w) return std::nullopt;
  BoardPose pose;
  pose.workDeg = w->v;
  if (const auto& wco = protocol.workOffset()) pose.wco = wco->v;
  if (const auto g28 = protocol.parameter("G28")) pose.g28Machine = g28->v;
  if (const auto g30 = protocol.parameter("G30")) pose.g30Machine = g30->v;
  pose.softTravelDeg = setup::softLimitTravelDeg(protocol.boardSettings());
  return pose;
}

FileCheck checkFile(const MachineProfile& profile, std::string_view text,
                    std::optional<Axes3> startWork) {
  FileCheck out;
  BoardPose pose;
  if (startWork) pose.workDeg = *startWork;
  std::vector<JointAngles> poses;
  if (startWork) poses.push_back(jointsOf(profile, *startWork));
  std::vector<int> moveLine;  // file line of move i (poses[i] -> poses[i + 1])
  std::vector<std::string> moveText;
  const auto fail = [&](int fileLine, const std::string& lineText, const std::string& why) {
    out.ok = false;
    out.fileLine = fileLine;
    out.reason = "line " + std::to_string(fileLine) + " '" + lineText + "': " + why;
    return out;
  };
  int fileLine = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view raw = text.substr(start, end - start);
    start = end + 1;
    ++fileLine;
    const LineCheck c = interpretLine(raw, pose);
    if (!c.ok()) return fail(fileLine, gcode::compact(raw), c.reason.text());
    if (c.systemCommand)
      return fail(fileLine, gcode::compact(raw),
                  "system commands and settings do not belong in a job; use fivebar send or "
                  "fivebar setup");
    if (c.verdict == Verdict::Motion) {
      ++out.motionLines;
      if (!out.firstTargetWork) out.firstTargetWork = c.targetsWork.front();
      if (poses.empty()) {
        startWork = c.targetsWork.front();
        poses.push_back(jointsOf(profile, *startWork));
      }
      for (const Axes3& t : c.targetsWork) {
        poses.push_back(jointsOf(profile, t));
        moveLine.push_back(fileLine);
        moveText.push_back(gcode::compact(raw));
      }
    }
    applyLine(raw, c, pose);
  }
  if (poses.empty()) return out;  // nothing moves the joints
  const MoveCheck first = checkPose(profile, poses.front());
  if (!first.ok())
    return fail(0, "", "the job's start " + anglesText((*startWork)[0], (*startWork)[1]) +
                           " is not a safe pose: " + describe(first));
  const PathCheck path = checkJointPath(profile, poses);
  if (!path.ok()) {
    const PathProblem& p = path.problems.front();
    const JointAngles a = commandedFromKinematic(profile.calibration, poses[p.move]);
    const JointAngles b = commandedFromKinematic(profile.calibration, poses[p.move + 1]);
    return fail(moveLine[p.move], moveText[p.move],
                "the move from " + anglesText(degFromRad(a.theta1), degFromRad(a.theta2)) + " to " +
                    anglesText(degFromRad(b.theta1), degFromRad(b.theta2)) + " " + describe(p.check));
  }
  return out;
}

JobHeader readJobHeader(std::string_view text) {
  JobHeader h;
  size_t start = 0;
  for (int n = 0; n < 60 && start < text.size(); ++n) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.rfind("; profile: ", 0) == 0) h.profileName = std::string(line.substr(11));
    if (line.rfind("; start pose X", 0) == 0) {
      const std::string_view rest = line.substr(14);
      const size_t y = rest.find(" Y");
      if (y == std::string_view::npos) continue;
      const auto a = grbl::parseNumber(rest.substr(0, y));
      const auto b = grbl::parseNumber(rest.substr(y + 2));
      if (a && b) h.startDeg = std::array<double, 2>{*a, *b};
    }
  }
  return h;
}

}  // namespace fivebar::motion
