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
#include "plan_import_options.hpp"

#ifdef FIVEBAR_HAVE_IMPORT
#include <QCoreApplication>
#include <clocale>

#include "job/job_source.hpp"
#endif

namespace fivebar::cli {
namespace {

constexpr const char* kPlanHelp =
    "usage: fivebar plan DRAWING.svg --machine PRESET|FILE -o JOB.gcode [options]\n"
    "       fivebar plan PROJECT.fivebar [--machine PRESET|FILE] -o JOB.gcode\n"
    "  --mode auto|++|+-|-+|--   working mode (auto: the feasible one with the best margin)\n"
    "  --at X,Y                  put the drawing's bbox centre at machine point X,Y (mm), true\n"
    "                            size times --scale; without --at the drawing is drawn at true\n"
    "                            size (scaled down only when it does not fit), centred in the\n"
    "                            largest singularity-free rectangle of the chosen mode\n"
    "  --scale S                 scale factor with --at (default 1)\n"
    "  --rotate DEG              rotate the drawing counter-clockwise (default 0)\n"
    "  --fit                     scale the drawing up or down to fill that rectangle\n"
    "  --tolerance MM            max distance of the drawn line from the drawing (default 0.1)\n"
    "  --no-optimise             keep the drawing's stroke order and direction\n"
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

PlanOptions planOptionsFrom(const Options& o) {
  PlanOptions p;
  const std::string mode = o.value("--mode").value_or("auto");
  if (mode != "auto") {
    p.mode = parseWorkingMode(mode);
    if (!p.mode) throw UsageError("--mode must be auto, ++, +-, -+ or --, got '" + mode + "'");
  }
  if (const auto at = o.value("--at")) {
    const auto pair = parseNumberPair(*at);
    if (!pair) throw UsageError("--at needs X,Y in mm, got '" + *at + "'");
    p.atMm = Vec2(pair->first, pair->second);
  }
  if (const auto s = o.value("--scale")) p.scale = numberArg(*s, "--scale");
  if (!(p.scale > 0.0)) throw UsageError("--scale must be positive");
  if (const auto r = o.value("--rotate")) p.rotationRad = radFromDeg(numberArg(*r, "--rotate"));
  if (const auto t = o.value("--tolerance")) p.toleranceMm = numberArg(*t, "--tolerance");
  if (!(p.toleranceMm > 0.0)) throw UsageError("--tolerance must be positive");
  p.fit = o.flag("--fit");
  p.optimise = !o.flag("--no-optimise");
  return p;
}

void printProblems(const std::string& file, const PlanResult& r) {
  std::cerr << "fivebar plan: " << file << ": " << r.message << "\n";
  const auto& problems = r.report.problems;
  for (size_t i = 0; i < problems.size() && i < 5; ++i)
    std::cerr << "  " << problems[i].path << ": " << problems[i].why << "\n";
  if (problems.size() > 5) std::cerr << "  ... " << problems.size() - 5 << " more in the report\n";
  if (!problems.empty())
    for (const PlanFix& fix : problems.front().fixes) std::cerr << "  fix: " << fixWords(fix) << "\n";
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

int plan(const Options& o) {
  if (o.positional().size() != 1) throw UsageError("plan needs exactly one DRAWING.svg or PROJECT.fivebar");
  const std::string file = o.positional()[0];
  const std::string output = o.required("--output");
  const bool project = endsWith(file, ".fivebar");
  std::optional<MachineProfile> machine;
  if (!project || o.value("--machine")) {
    machine = loadMachine(o.required("--machine"), "plan", std::cerr);
    if (!machine) return 1;
  }
  if (project)
    for (const char* option : {"--mode", "--at", "--scale", "--rotate", "--tolerance", "--text-font"})
      if (o.value(option)) throw UsageError(std::string(option) + " does not apply to a project (it has its own)");
  if (project && o.flag("--fit")) throw UsageError("--fit does not apply to a project (it has its own placement)");
  PlanOptions opt = planOptionsFrom(o);
  PlanImportSettings importSettings = planImportSettingsFrom(o);
#ifdef FIVEBAR_HAVE_IMPORT
  int argc = 1;
  char name[] = "fivebar";
  char* argv[] = {name, nullptr};
  std::optional<QCoreApplication> app;  // the import's worker process needs one
  if (!QCoreApplication::instance()) app.emplace(argc, argv);
  std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; output keeps the decimal point
  const auto start = std::chrono::steady_clock::now();
  StageTimes times;
  StageClock clock(times);
  // The same steps as the studio (job/job_source.hpp): import, place, plan (importing again
  // more finely when the placement enlarges the drawing).
  job::JobError error;
  // The points budget stops the import itself as soon as it is passed (a runaway file is never
  // flattened whole); withinPointBudget checks it again after hatching.
  auto loaded = job::loadJob(QString::fromStdString(file), machine, opt, error, importSettings.fill,
                              importSettings.hatch, importSettings.maxPoints, importSettings.solidDashes,
                              importSettings.textFont);
  if (!loaded && error.pointBudgetExceeded()) {
    std::cerr << "fivebar plan: " << error.text << "; nothing planned. Raise it with --max-points N if the "
                 "drawing is meant to be this big\n";
    return 1;
  }
  if (!loaded) {
    std::cerr << "fivebar plan: " << error.text << "\n";
    return 1;
  }
  for (const Message& w : loaded->warnings) std::cerr << "fivebar plan: " << file << ": warning: " << w << "\n";
  if (!withinPointBudget(file, loaded->drawing, importSettings)) return 1;
  clock.lap("import and placement");
  if (!loaded->note.empty()) std::cerr << "fivebar plan: " << file << ": " << loaded->note << "\n";
  if (o.flag("--timings")) std::cerr << "  placement scale " << loaded->options.scale << "\n";
  PlanResult r = job::planRefining(loaded->drawing, loaded->source, loaded->profile, loaded->options, error);
  times.append(r.timings);
  clock.restart();
  if (!error.empty()) {
    std::cerr << "fivebar plan: " << error.text << "\n";
    return 1;
  }
  if (const auto report = o.value("--report"); report && !writeFile(*report, reportToJson(r.report, fixText)))
    return 1;
  if (!r.ok()) {
    printProblems(file, r);
    return 1;
  }
  if (!writeGcodeFile(output, r.job, loaded->profile)) return 1;
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
#else
  (void)opt;
  std::cerr << "fivebar plan: " << file << ": this build has no SVG import (configured with "
               "FIVEBAR_BUILD_GUI=OFF)\n";
  return 1;
#endif
}

}  // namespace

int runPlan(const Args& args) {
  try {
    Args normalized = args;
    for (std::string& a : normalized)
      if (a == "-o") a = "--output";
    const Options o(normalized,
                    withImportValuedOptions({"--machine", "--mode", "--at", "--scale", "--rotate",
                                             "--tolerance", "--output", "--report"}),
                    withImportFlags({"--fit", "--no-optimise", "--timings", "--help"}));
    if (o.flag("--help")) {
      std::cout << kPlanHelp << kPlanImportHelp;
      return 0;
    }
    return plan(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar plan: " << e.what() << "\n\n" << kPlanHelp << kPlanImportHelp;
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
