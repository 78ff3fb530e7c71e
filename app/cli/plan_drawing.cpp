// SPDX-License-Identifier: GPL-3.0-or-later
// The steps of `fivebar plan`, shared with `fivebar frame`. Contract: plan_drawing.hpp.
#include "plan_drawing.hpp"

#include <iostream>

#include "core/kinematics/units.hpp"
#include "machine_arg.hpp"
#include "plan_import_options.hpp"
#include "plan_words.hpp"

#ifdef FIVEBAR_HAVE_IMPORT
#include <QCoreApplication>
#include <clocale>

#include "job/job_source.hpp"
#endif

namespace fivebar::cli {

const char* const kPlacementHelp =
    "  --mode auto|++|+-|-+|--   working mode (auto: the feasible one with the best margin)\n"
    "  --at X,Y                  put the drawing's bbox centre at machine point X,Y (mm), true\n"
    "                            size times --scale; without --at the drawing is drawn at true\n"
    "                            size (scaled down only when it does not fit), centred in the\n"
    "                            largest singularity-free rectangle of the chosen mode\n"
    "  --scale S                 scale factor with --at (default 1)\n"
    "  --rotate DEG              rotate the drawing counter-clockwise (default 0)\n"
    "  --fit                     scale the drawing up or down to fill that rectangle\n"
    "  --tolerance MM            max distance of the drawn line from the drawing (default 0.1)\n"
    "  --no-optimise             keep the drawing's stroke order and direction\n";

std::set<std::string> withPlacementValuedOptions(std::set<std::string> valued) {
  valued.insert({"--machine", "--mode", "--at", "--scale", "--rotate", "--tolerance"});
  return withImportValuedOptions(std::move(valued));
}

std::set<std::string> withPlacementFlags(std::set<std::string> flags) {
  flags.insert({"--fit", "--no-optimise"});
  return withImportFlags(std::move(flags));
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

bool isProjectFile(const std::string& path) {
  const std::string tail = ".fivebar";
  return path.size() >= tail.size() && path.compare(path.size() - tail.size(), tail.size(), tail) == 0;
}

void printPlanProblems(const std::string& command, const std::string& file, const PlanResult& r) {
  std::cerr << "fivebar " << command << ": " << file << ": " << r.message << "\n";
  const auto& problems = r.report.problems;
  for (size_t i = 0; i < problems.size() && i < 5; ++i)
    std::cerr << "  " << problems[i].path << ": " << problems[i].why << "\n";
  if (problems.size() > 5) std::cerr << "  ... " << problems.size() - 5 << " more in the report\n";
  if (!problems.empty())
    for (const PlanFix& fix : problems.front().fixes) std::cerr << "  fix: " << fixWords(fix) << "\n";
}

std::optional<PlannedDrawing> planDrawing(const Options& o, const std::optional<MachineProfile>& machine,
                                          const std::string& command, StageTimes* times) {
  const std::string file = o.positional().at(0);
  const std::string prefix = "fivebar " + command + ": ";
  if (isProjectFile(file))
    for (const char* option : {"--mode", "--at", "--scale", "--rotate", "--tolerance", "--text-font"})
      if (o.value(option)) throw UsageError(std::string(option) + " does not apply to a project (it has its own)");
  if (isProjectFile(file) && o.flag("--fit"))
    throw UsageError("--fit does not apply to a project (it has its own placement)");
  PlanOptions opt = planOptionsFrom(o);
  PlanImportSettings importSettings = planImportSettingsFrom(o);
#ifdef FIVEBAR_HAVE_IMPORT
  int argc = 1;
  char name[] = "fivebar";
  char* argv[] = {name, nullptr};
  std::optional<QCoreApplication> app;  // the import's worker process needs one
  if (!QCoreApplication::instance()) app.emplace(argc, argv);
  std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; output keeps the decimal point
  StageTimes ownTimes;
  StageTimes& stages = times ? *times : ownTimes;
  StageClock clock(stages);
  // The same steps as the studio (job/job_source.hpp): import, place, plan (importing again
  // more finely when the placement enlarges the drawing).
  job::JobError error;
  // The points budget stops the import itself as soon as it is passed (a runaway file is never
  // flattened whole); withinPointBudget checks it again after hatching.
  auto loaded = job::loadJob(QString::fromStdString(file), machine, opt, error, importSettings.fill,
                             importSettings.hatch, importSettings.maxPoints, importSettings.solidDashes,
                             importSettings.textFont);
  if (!loaded && error.pointBudgetExceeded()) {
    std::cerr << prefix << error.text << "; nothing planned. Raise it with --max-points N if the "
                 "drawing is meant to be this big\n";
    return std::nullopt;
  }
  if (!loaded) {
    std::cerr << prefix << error.text << "\n";
    return std::nullopt;
  }
  for (const Message& w : loaded->warnings) std::cerr << prefix << file << ": warning: " << w << "\n";
  if (!withinPointBudget(file, loaded->drawing, importSettings)) return std::nullopt;
  clock.lap("import and placement");
  if (!loaded->note.empty()) std::cerr << prefix << file << ": " << loaded->note << "\n";
  if (o.flag("--timings")) std::cerr << "  placement scale " << loaded->options.scale << "\n";
  PlanResult r = job::planRefining(loaded->drawing, loaded->source, loaded->profile, loaded->options, error);
  stages.append(r.timings);
  if (!error.empty()) {
    std::cerr << prefix << error.text << "\n";
    return std::nullopt;
  }
  return PlannedDrawing{std::move(r), loaded->profile};
#else
  (void)opt;
  (void)machine;
  (void)times;
  (void)importSettings;
  std::cerr << prefix << file << ": this build has no SVG import (configured with FIVEBAR_BUILD_GUI=OFF)\n";
  return std::nullopt;
#endif
}

}  // namespace fivebar::cli
