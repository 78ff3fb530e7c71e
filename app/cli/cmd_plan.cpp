// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar plan: SVG drawing -> GRBL G-code (+ REPORT.json) for a five-bar machine.
// fivebar grbl-settings: the $ lines a profile expects.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "commands.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "machine_arg.hpp"
#include "options.hpp"
#include "plan_words.hpp"
#include "plan_drawing.hpp"
#include "plan_import_options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kPlanHelp =
    "usage: fivebar plan DRAWING.svg --machine PRESET|FILE -o JOB.gcode [options]\n"
    "       fivebar plan PROJECT.fivebar [--machine PRESET|FILE] -o JOB.gcode\n";

constexpr const char* kPlanOutputHelp =
    "  -o, --output JOB.gcode    G-code output file\n"
    "  --report REPORT.json      planning report (also written when the job is infeasible)\n"
    "  --timings                 print the wall-clock and CPU time of each stage to stderr\n"
    "A project (saved by the studio) brings its drawing, placement, layers, mode, tolerance and\n"
    "machine; --machine replaces the machine. The G-code is byte-identical to the studio's.\n"
    "Exits 1 when the job is infeasible, naming the first offending path and the reason.\n";

constexpr const char* kSettingsHelp =
    "usage: fivebar grbl-settings --machine PRESET|FILE\n"
    "Prints the GRBL $ settings the profile expects, one per line (send them once).\n";

// Writes PATH.part next to `path` with `fill`, then renames it over `path`: an interrupted or
// failed write never leaves a truncated file under the output's name.
template <typename Fill>
bool writeAtomically(const std::string& path, const Fill& fill) {
  const std::string part = path + ".part";
  bool ok = false;
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    try {
      fill(out);
      out.flush();
      ok = static_cast<bool>(out);
    } catch (const std::exception& e) {
      std::cerr << "fivebar plan: " << e.what() << "\n";
    }
  }
  if (ok && std::rename(part.c_str(), path.c_str()) == 0) return true;
  std::remove(part.c_str());
  std::cerr << "fivebar plan: cannot write '" << path << "'\n";
  return false;
}

bool writeFile(const std::string& path, const std::string& text) {
  return writeAtomically(path, [&](std::ofstream& out) { out << text; });
}

// The G-code, streamed piece by piece (a large job is never whole in memory as text).
bool writeGcodeFile(const std::string& path, const PlannedJob& job, const MachineProfile& profile) {
  return writeAtomically(path, [&](std::ofstream& out) {
    writeGcode(job, profile, [&](std::string_view piece) {
      out.write(piece.data(), static_cast<std::streamsize>(piece.size()));
    });
  });
}

int plan(const Options& o) {
  if (o.positional().size() != 1) throw UsageError("plan needs exactly one DRAWING.svg or PROJECT.fivebar");
  const std::string file = o.positional()[0];
  const std::string output = o.required("--output");
  const bool project = isProjectFile(file);
  std::optional<MachineProfile> machine;
  if (!project || o.value("--machine")) {
    machine = loadMachine(o.required("--machine"), "plan", std::cerr);
    if (!machine) return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  StageTimes times;
  auto planned = planDrawing(o, machine, "plan", &times);
  if (!planned) return 1;
  StageClock clock(times);
  const PlanResult& r = planned->result;
  if (const auto report = o.value("--report"); report && !writeFile(*report, reportToJson(r.report, fixText)))
    return 1;
  if (!r.ok()) {
    printPlanProblems("plan", file, r);
    return 1;
  }
  if (!writeGcodeFile(output, r.job, planned->profile)) return 1;
  clock.lap("G-code");
  const double wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PlanReport& rep = r.report;
  std::cout << output << ": mode " << toString(rep.mode) << ", " << rep.segments << " segments, "
            << "pen down " << std::lround(rep.penDownMm) << " mm, travel "
            << std::lround(rep.travelMm) << " mm, estimated " << std::lround(rep.estimatedTimeS)
            << " s, scale " << fixed9(r.placementScale * 100.0).substr(0, 5) << " %, max deviation "
            << fixed9(rep.maxDeviationMm).substr(0, 6) << " mm, margin "
            << fixed9(rep.minSingularityMarginDeg).substr(0, 5) << " deg (planned in "
            << std::lround(wallS * 1000) << " ms)\n";
  if (o.flag("--timings"))
    for (const StageTime& stage : times.stages)
      std::cerr << "  " << stage.name << ": " << std::lround(stage.wallS * 1000) << " ms (cpu "
                << std::lround(stage.cpuS * 1000) << " ms)\n";
  return 0;
}

}  // namespace

int runPlan(const Args& args) {
  try {
    Args normalized = args;
    for (std::string& a : normalized)
      if (a == "-o") a = "--output";
    const Options o(normalized, withPlacementValuedOptions({"--output", "--report"}),
                    withPlacementFlags({"--timings", "--help"}));
    if (o.flag("--help")) {
      std::cout << kPlanHelp << kPlacementHelp << kPlanOutputHelp << kPlanImportHelp;
      return 0;
    }
    return plan(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar plan: " << e.what() << "\n\n" << kPlanHelp << kPlacementHelp << kPlanOutputHelp
              << kPlanImportHelp;
    return 2;
  }
}

int runGrblSettings(const Args& args) {
  try {
    const Options o(args, {"--machine"}, {"--help"});
    if (o.flag("--help")) {
      std::cout << kSettingsHelp;
      return 0;
    }
    if (!o.positional().empty()) throw UsageError("unexpected argument " + o.positional()[0]);
    const auto machine = loadMachine(o.required("--machine"), "grbl-settings", std::cerr);
    if (!machine) return 1;
    std::cout << grblSettings(*machine);
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "fivebar grbl-settings: " << e.what() << "\n\n" << kSettingsHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
