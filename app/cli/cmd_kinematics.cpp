// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar ik / fk: line-oriented inverse and forward kinematics filters.
//   ik: "x,y" (mm, machine frame) per stdin line -> "theta1,theta2" (deg, (-180, 180], 9 decimals)
//   fk: "theta1,theta2" (deg) per stdin line     -> "x,y" (mm, 9 decimals)
// A point or pose the linkage cannot reach prints "unreachable". ik reports the geometry's
// reachability only: joint limits apply to continuous motion (plans, jogs), not to single poses.
// x,y is the pen: with a calibrated pen offset (calibration.penOffset) the pen kinematics of
// core/machine/pen_kinematics.hpp. The angles are kinematic (docs/calibration.md).
#include <iostream>
#include <string>

#include "commands.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "machine_arg.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kIkHelp =
    "usage: fivebar ik --machine PRESET|FILE [--mode ++|+-|-+|--]\n"
    "Reads 'x,y' lines (mm, machine frame) on stdin and writes 'theta1,theta2' (degrees, in\n"
    "(-180, 180], 9 decimals) or 'unreachable' per line. --mode defaults to the profile's working\n"
    "mode. Joint limits are not applied: ik reports what the geometry can reach. x,y is the pen\n"
    "(a calibrated pen offset is honoured); the angles are kinematic (a calibrated profile's zero\n"
    "offsets are not subtracted).\n";

constexpr const char* kFkHelp =
    "usage: fivebar fk --machine PRESET|FILE [--assembly +|-]\n"
    "Reads 'theta1,theta2' lines (degrees) on stdin and writes 'x,y' (mm, machine frame,\n"
    "9 decimals) or 'unreachable' per line. --assembly defaults to the profile's assembly mode.\n"
    "x,y is the pen (a calibrated pen offset is honoured); the angles are kinematic.\n";

// Applies `convert` to every stdin line. Stops at the first malformed line (exit 1).
template <typename Convert>
int filterLines(const char* command, const char* expected, Convert convert) {
  std::string line;
  long lineNumber = 0;
  while (std::getline(std::cin, line)) {
    ++lineNumber;
    const auto pair = parseNumberPair(line);
    if (!pair) {
      std::cout.flush();
      std::cerr << "fivebar " << command << ": stdin line " << lineNumber << ": expected "
                << expected << ", got '" << line << "'\n";
      return 1;
    }
    std::cout << convert(*pair) << '\n';
  }
  return 0;
}

struct Parsed {
  MachineProfile profile;
  Options options;
};

// Parses options and the machine; nullopt after printing the problem (exit code in `code`).
std::optional<Parsed> parse(const Args& args, const char* command, const char* modeOption,
                            const char* help, int& code) {
  try {
    Options o(args, {"--machine", modeOption}, {"--help"});
    if (o.flag("--help")) {
      std::cout << help;
      code = 0;
      return std::nullopt;
    }
    if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
    auto profile = loadMachine(o.required("--machine"), command, std::cerr);
    if (!profile) {
      code = 1;
      return std::nullopt;
    }
    return Parsed{std::move(*profile), std::move(o)};
  } catch (const UsageError& e) {
    std::cerr << "fivebar " << command << ": " << e.what() << "\n" << help;
    code = 2;
    return std::nullopt;
  }
}

}  // namespace

int runIk(const Args& args) {
  int code = 0;
  auto parsed = parse(args, "ik", "--mode", kIkHelp, code);
  if (!parsed) return code;
  WorkingMode mode = parsed->profile.defaultMode;
  if (auto text = parsed->options.value("--mode")) {
    auto m = parseWorkingMode(*text);
    if (!m) {
      std::cerr << "fivebar ik: --mode must be one of ++, +-, -+, --, got '" << *text << "'\n";
      return 2;
    }
    mode = *m;
  }
  const Geometry g = parsed->profile.geometry;
  const std::optional<PenOffset> pen = calibratedPenOffset(parsed->profile);
  std::ios::sync_with_stdio(false);
  return filterLines("ik", "x,y", [&](const NumberPair& xy) -> std::string {
    const IkResult r = penInverse(g, pen, Vec2(xy.first, xy.second), mode);
    if (!r.ok()) return "unreachable";
    return poseAngleDeg(r.angles.theta1) + "," + poseAngleDeg(r.angles.theta2);
  });
}

int runFk(const Args& args) {
  int code = 0;
  auto parsed = parse(args, "fk", "--assembly", kFkHelp, code);
  if (!parsed) return code;
  AssemblyMode assembly = parsed->profile.assembly;
  if (auto text = parsed->options.value("--assembly")) {
    auto a = parseAssemblyMode(*text);
    if (!a) {
      std::cerr << "fivebar fk: --assembly must be + or -, got '" << *text << "'\n";
      return 2;
    }
    assembly = *a;
  }
  const Geometry g = parsed->profile.geometry;
  const std::optional<PenOffset> pen = calibratedPenOffset(parsed->profile);
  std::ios::sync_with_stdio(false);
  return filterLines("fk", "theta1,theta2", [&](const NumberPair& q) -> std::string {
    const FkResult r = penForward(g, pen, {radFromDeg(q.first), radFromDeg(q.second)}, assembly);
    if (!r.ok()) return "unreachable";
    return fixed9(r.p.x()) + "," + fixed9(r.p.y());
  });
}

}  // namespace fivebar::cli
