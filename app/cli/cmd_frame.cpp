// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar frame: the job's outline traced pen up (a laser at low power) on the machine, by the
// jog planner's checked joint-space moves (drivers/jog/jog.hpp planFrame), every line through
// the one motion check from the board's real pose, so that the maker sees where the drawing
// lands before the run.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "board_procedure.hpp"
#include "commands.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/safety.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/stream/stream_session.hpp"
#include "machine_arg.hpp"
#include "plan_drawing.hpp"
#include "plan_import_options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kFrameHelp =
    "usage: fivebar frame JOB.gcode|DRAWING --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE\n"
    "                     [--baud 115200] [--shape hull|box] [--speed MM/S] [--timeout S]\n"
    "                     [--force-profile] [--ignore-settings] [placement and import options]\n"
    "Traces the outline of a job on the machine with the pen UP (a laser tool at 1 % of its\n"
    "power), so that you see where the drawing lands on the paper before running it. JOB.gcode\n"
    "(.gcode, .nc, .ngc, .gc) is a planned job; any other file is a DRAWING (SVG) or a\n"
    "PROJECT.fivebar, planned first exactly as 'fivebar plan' plans it, with the same options.\n"
    "The outline is the convex hull of the job's pen-down points (--shape box: their bounding\n"
    "box), walked as straight lines in the job's working mode, at the profile's drawing speed\n"
    "unless --speed; it starts with a safe pen-up travel to its first corner and ends there.\n"
    "What is checked: as for 'fivebar home' and the studio's jogs. The machine's position must be\n"
    "KNOWN (after 'fivebar reference' or homing); the board's pose and its settings ($$) are\n"
    "read first, and a setting that changes how the machine moves refuses the frame (fix:\n"
    "fivebar setup --write; --ignore-settings frames anyway). Every sub-move is planned within\n"
    "the workspace, the joint limits and the type II singularity margin, and every line is\n"
    "checked from the board's pose before it is sent (and against its soft limits when $20=1).\n"
    "A job planned for another profile (its '; profile:' header) is refused unless\n"
    "--force-profile. Exit 0 when the outline was traced and the machine is back at rest.\n";

constexpr const char* kFramePlacementHelp = "For a DRAWING (see fivebar plan --help):\n";

bool isGcodeFile(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".gcode" || ext == ".nc" || ext == ".ngc" || ext == ".gc";
}

std::optional<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The job's G-code and the profile it is framed with; nullopt after saying why.
std::optional<std::pair<std::string, MachineProfile>> jobText(const Options& o, MachineProfile profile) {
  const std::string file = o.positional()[0];
  if (!isGcodeFile(file)) {
    auto planned = planDrawing(o, profile, "frame", nullptr);
    if (!planned) return std::nullopt;
    if (!planned->result.ok()) {
      printPlanProblems("frame", file, planned->result);
      return std::nullopt;
    }
    return std::pair{writeGcode(planned->result.job, planned->profile), planned->profile};
  }
  for (const char* option : {"--mode", "--at", "--scale", "--rotate", "--tolerance"})
    if (o.value(option)) throw UsageError(std::string(option) + " does not apply to a planned G-code job");
  auto text = readText(file);
  if (!text) {
    std::cerr << "fivebar frame: cannot read '" << file << "'\n";
    return std::nullopt;
  }
  const motion::JobHeader header = motion::readJobHeader(*text);
  if (header.profileName && *header.profileName != profile.name && !o.flag("--force-profile")) {
    std::cerr << "fivebar frame: " << file << " was planned for the profile '" << *header.profileName
              << "', not '" << profile.name << "': plan it again for this machine (or --force-profile if "
              << "the machines are the same)\n";
    return std::nullopt;
  }
  return std::pair{std::move(*text), std::move(profile)};
}

std::string mm1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

int frame(const Options& o) {
  if (o.positional().size() != 1) throw UsageError("frame needs exactly one JOB.gcode or DRAWING");
  const std::string port = o.required("--port");
  const std::string machineArg = o.required("--machine");
  const std::string shapeText = o.value("--shape").value_or("hull");
  if (shapeText != "hull" && shapeText != "box") throw UsageError("--shape must be hull or box, got '" + shapeText + "'");
  const jog::FrameShape shape = shapeText == "box" ? jog::FrameShape::BoundingBox : jog::FrameShape::ConvexHull;
  auto machine = loadMachine(machineArg, "frame", std::cerr);
  if (!machine) return 1;
  auto job = jobText(o, std::move(*machine));
  if (!job) return 1;
  const MachineProfile& profile = job->second;
  const double speedMmPerS = o.value("--speed") ? numberArg(*o.value("--speed"), "--speed", true)
                                                : profile.drawSpeedMmPerS;
  const stream::JobRules rules = stream::rulesFor(profile);
  const stream::GcodeJob gcode = stream::parseJob(job->first, rules);
  // The frame from the home pose, for its length: the default time allowed.
  const jog::JogPlan fromHome = jog::planFrame(profile, profile.homeAngles, gcode, rules, shape, speedMmPerS);
  if (fromHome.status == jog::JogStatus::Blocked && stream::strokesOf(gcode, rules).empty()) {
    std::cerr << "fivebar frame: " << o.positional()[0] << ": " << fromHome.reason.text() << "\n";
    return 1;
  }
  const double timeoutS = o.value("--timeout") ? numberArg(*o.value("--timeout"), "--timeout", true)
                                               : 60.0 + 3.0 * fromHome.lengthMm / speedMmPerS;
  const bool laser = profile.tool.kind == ToolKind::Laser;
  // The outline's extent: the bounding box of the job's pen-down points (machine frame, mm).
  Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
  for (const auto& stroke : stream::strokesOf(gcode, rules))
    for (const auto& q : stroke) {
      const FkResult fk = penForward(profile, kinematicFromCommanded(profile.calibration,
                                                                     {radFromDeg(q[0]), radFromDeg(q[1])}));
      if (fk.ok()) { lo = lo.cwiseMin(fk.p); hi = hi.cwiseMax(fk.p); }
    }
  std::optional<JointAngles> end;
  const auto decide = [&](const motion::BoardPose& pose,
                          MachineLink& link) -> std::optional<std::vector<std::string>> {
    if (!link.poseTrust().known()) {
      std::cerr << "fivebar frame: the machine's position is not known (" << grbl::toString(link.poseTrust().doubt())
                << "), so no frame can be planned. Put the arms in the home pose and run 'fivebar reference "
                << "--port " << port << " --machine " << machineArg << "', or home the machine, first\n";
      return std::nullopt;
    }
    if (!o.flag("--ignore-settings")) {
      const auto diffs = movingSettingDiffs(link.protocol().boardSettings(), profile);
      if (!diffs.empty()) {
        std::cerr << "fivebar frame: the board's settings differ from the profile, so the machine would not "
                  << "move as planned: " << describeSettingDiffs(diffs)
                  << ". Fix: fivebar setup --port " << port << " --machine " << machineArg
                  << " --write (or --ignore-settings to frame anyway)\n";
        return std::nullopt;
      }
    }
    const JointAngles from{radFromDeg(pose.workDeg[0]), radFromDeg(pose.workDeg[1])};
    if (const MoveCheck here = checkPose(profile, from); !here.ok()) {
      std::cerr << "fivebar frame: the machine reports " << motion::anglesText(pose.workDeg[0], pose.workDeg[1])
                << ", which is not a safe pose of " << profile.name << " (" << describe(here) << ")\n";
      return std::nullopt;
    }
    const jog::JogPlan plan = jog::planFrame(profile, from, gcode, rules, shape, speedMmPerS);
    if (!plan.ok()) {
      std::cerr << "fivebar frame: no checked frame of the job: " << plan.reason.text() << "\n";
      return std::nullopt;
    }
    motion::BoardPose at = pose;
    for (const std::string& line : plan.lines) {
      const motion::LineCheck c = motion::checkLine(profile, line, at);  // the one motion check
      if (!c.ok()) {
        std::cerr << "fivebar frame: refused '" << line << "' (nothing was sent): " << c.reason.text() << "\n";
        return std::nullopt;
      }
      motion::applyLine(line, c, at);
    }
    std::printf("framing %s: %s mm of outline (%s x %s mm, x %s..%s, y %s..%s mm), %s, in %zu checked moves\n",
                o.positional()[0].c_str(), mm1(plan.lengthMm).c_str(), mm1(hi.x() - lo.x()).c_str(),
                mm1(hi.y() - lo.y()).c_str(), mm1(lo.x()).c_str(), mm1(hi.x()).c_str(), mm1(lo.y()).c_str(),
                mm1(hi.y()).c_str(), laser ? "laser at low power" : "pen up", plan.targets.size());
    std::fflush(stdout);
    end = plan.targets.back();
    link.poseTrust().aboutToMove();
    return plan.lines;
  };
  const auto verify = [&](const motion::BoardPose& pose) {
    if (end && std::abs(pose.workDeg[0] - degFromRad(end->theta1)) <= 0.01 &&
        std::abs(pose.workDeg[1] - degFromRad(end->theta2)) <= 0.01) {
      std::printf("framed: the pen is at the outline's first corner %s\n",
                  motion::anglesText(pose.workDeg[0], pose.workDeg[1]).c_str());
      return 0;
    }
    std::cerr << "fivebar frame: the machine stopped at " << motion::anglesText(pose.workDeg[0], pose.workDeg[1])
              << ", not at the outline's first corner\n";
    return 1;
  };
  return runProcedure(o, "frame", timeoutS, decide, verify, false, true);
}

}  // namespace

int runFrame(const Args& args) {
  try {
    const Options o(args, withPlacementValuedOptions({"--port", "--baud", "--timeout", "--shape", "--speed"}),
                    withPlacementFlags({"--help", "--force-profile", "--ignore-settings"}));
    if (o.flag("--help")) {
      std::cout << kFrameHelp << kFramePlacementHelp << kPlacementHelp << kPlanImportHelp;
      return 0;
    }
    return frame(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar frame: " << e.what() << "\n\n" << kFrameHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
