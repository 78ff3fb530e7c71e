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
#include "plan_import_options.hpp"

#ifdef FIVEBAR_HAVE_IMPORT
#include <QCoreApplication>

#include "core/import/svg_import.hpp"
#endif

namespace fivebar::cli {
namespace {

constexpr const char* kPlanHelp =
    "usage: fivebar plan DRAWING.svg --machine PRESET|FILE -o JOB.gcode [options]\n"
    "  --mode auto|++|+-|-+|--   working mode (auto: the feasible one with the best margin)\n"
    "  --at X,Y                  put the drawing's bbox centre at machine point X,Y (mm), true\n"
    "                            size times --scale; without --at the drawing is fitted into\n"
    "                            the mode's largest singularity-free rectangle\n"
    "  --scale S                 scale factor with --at (default 1)\n"
    "  --rotate DEG              rotate the drawing counter-clockwise (default 0)\n"
    "  --fit                     fit into the singularity-free rectangle even with --at\n"
    "  --tolerance MM            max distance of the drawn line from the drawing (default 0.1)\n"
    "  --no-optimise             keep the drawing's stroke order and direction\n"
    "  -o, --output JOB.gcode    G-code output file\n"
    "  --report REPORT.json      planning report (also written when the job is infeasible)\n"
    "  --timings                 print the wall-clock and CPU time of each stage to stderr\n"
    "Exits 1 when the job is infeasible, naming the first offending path and the reason.\n";

constexpr const char* kSettingsHelp =
    "usage: fivebar grbl-settings --machine PRESET|FILE\n"
    "Prints the GRBL $ settings the profile expects, one per line (send them once).\n";

double parseNumber(const std::string& text, const std::string& option) {
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw UsageError(option + " needs a number, got '" + text + "'");
  return v;
}

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
  if (const auto s = o.value("--scale")) p.scale = parseNumber(*s, "--scale");
  if (!(p.scale > 0.0)) throw UsageError("--scale must be positive");
  if (const auto r = o.value("--rotate")) p.rotationRad = radFromDeg(parseNumber(*r, "--rotate"));
  if (const auto t = o.value("--tolerance")) p.toleranceMm = parseNumber(*t, "--tolerance");
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
    for (const std::string& fix : problems.front().fixes) std::cerr << "  fix: " << fix << "\n";
}

// The SVG in the work frame, flattened within toleranceMm; errors and warnings go to stderr
// (plan_import_options.hpp: warnings, fills, the point budget).
std::optional<Drawing> importDrawing(const std::string& file, double toleranceMm,
                                     PlanImportSettings& importSettings) {
  return importForPlan(file, toleranceMm, importSettings);
}

int plan(const Options& o) {
  if (o.positional().size() != 1) throw UsageError("plan needs exactly one DRAWING.svg");
  const std::string file = o.positional()[0];
  const std::string output = o.required("--output");
  const auto machine = loadMachine(o.required("--machine"), "plan", std::cerr);
  if (!machine) return 1;
  PlanOptions opt = planOptionsFrom(o);
  PlanImportSettings importSettings = planImportSettingsFrom(o);
#ifdef FIVEBAR_HAVE_IMPORT
  int argc = 1;
  char name[] = "fivebar";
  char* argv[] = {name, nullptr};
  std::optional<QCoreApplication> app;  // the import's worker process needs one
  if (!QCoreApplication::instance()) app.emplace(argc, argv);
#endif
  const auto start = std::chrono::steady_clock::now();
  StageTimes times;
  StageClock clock(times);
  // Flatten with the tolerance's share, in work-frame mm (the placement scales it).
  const double share = kFlatteningShare * opt.toleranceMm;
  double importTol = share / (opt.atMm && !opt.fit ? opt.scale : 1.0);
  auto drawing = importDrawing(file, importTol, importSettings);
  if (!drawing) return 1;
  clock.lap("import");
  // Fitting may enlarge the drawing: flatten again, finer, before planning.
  const std::optional<double> scale = largestPlacementScale(*drawing, *machine, opt);
  clock.lap("placement and mode screening");
  if (o.flag("--timings") && scale) std::cerr << "  placement scale " << *scale << "\n";
  if (scale && *scale * importTol > share * 1.000001) {
    importTol = share / *scale;
    drawing = importDrawing(file, importTol, importSettings);
    if (!drawing) return 1;
    clock.lap("import");
  }
  opt.flatteningToleranceMm = importTol;
  PlanResult r = planJob(*drawing, *machine, opt);
  times.append(r.timings);
  clock.restart();
  if (const auto report = o.value("--report"); report && !writeFile(*report, reportToJson(r.report)))
    return 1;
  if (!r.ok()) {
    printProblems(file, r);
    return 1;
  }
  if (!writeGcodeFile(output, r.job, *machine)) return 1;
  clock.lap("G-code");
  const double wallS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PlanReport& rep = r.report;
  std::cout << output << ": mode " << toString(rep.mode) << ", " << rep.segments << " segments, "
            << "pen down " << std::lround(rep.penDownMm) << " mm, travel "
            << std::lround(rep.travelMm) << " mm, estimated " << std::lround(rep.estimatedTimeS)
            << " s, max deviation " << fixed9(rep.maxDeviationMm).substr(0, 6) << " mm, margin "
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
