// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar calibrate pattern --machine PRESET|FILE -o PATTERN.gcode --marks MARKS.csv [--svg FILE]
#include <iostream>

#include "calibrate_files.hpp"
#include "commands.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/pattern.hpp"
#include "core/output/fixed_decimal.hpp"
#include "core/output/gcode.hpp"
#include "machine_arg.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kHelp =
    "usage: fivebar calibrate pattern --machine PRESET|FILE -o PATTERN.gcode --marks MARKS.csv\n"
    "                                 [--svg PATTERN.svg]\n"
    "Plans the calibration pattern for the machine: numbered marks (a dot in a ring) over the\n"
    "working area, edge included, each reached last with both motors moving up; rows of three\n"
    "marks whose middle one is reached with one motor moving down (backlash); Hoang's accuracy\n"
    "pattern (10 lines of 40 mm, 10 mm apart) where it fits. Every move is checked like any job.\n"
    "  -o, --output PATTERN.gcode   the G-code to draw\n"
    "  --marks MARKS.csv            the marks: id, commanded angles (deg), nominal x, y (mm), ...\n"
    "  --svg PATTERN.svg            a picture of the pattern (machine frame, mm)\n"
    "Then draw it, scan it (fivebar calibrate scan) or measure the marks by hand.\n";

int run(const Options& o) {
  if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
  const std::string output = o.value("--output").value_or("");
  if (output.empty()) throw UsageError("missing required option -o PATTERN.gcode");
  const std::string marksPath = o.required("--marks");
  const auto profile = loadMachine(o.required("--machine"), "calibrate pattern", std::cerr);
  if (!profile) return 1;
  const PatternResult pr = makeCalibrationPattern(*profile);
  if (!pr.pattern) {
    std::cerr << "fivebar calibrate pattern: " << profile->name << ": " << pr.error << "\n";
    return 1;
  }
  const PlanResult plan = planCalibrationPattern(*pr.pattern, *profile);
  if (!plan.ok()) {
    std::cerr << "fivebar calibrate pattern: " << profile->name << ": " << plan.message << "\n";
    return 1;
  }
  std::vector<std::pair<std::string, std::string>> files{{output, writeGcode(plan.job, *profile)},
                                                         {marksPath, marksCsv(*pr.pattern)}};
  if (const auto svg = o.value("--svg")) files.push_back({*svg, patternSvg(*pr.pattern)});
  if (!writeAllFiles(files, "calibrate pattern")) return 1;
  int grid = 0, rows = 0;
  for (const PatternMark& m : pr.pattern->marks) (m.kind == MarkKind::Grid ? grid : rows) += 1;
  std::cout << pr.pattern->marks.size() << " marks: " << grid << " for the fit, " << rows / 3
            << " backlash rows of 3; accuracy pattern: "
            << (pr.pattern->accuracy ? "10 lines of 40 mm" : "does not fit") << "; working mode "
            << toString(pr.pattern->mode) << "; estimated time " << fixedDecimal(plan.report.estimatedTimeS, 0)
            << " s\n";
  return 0;
}

}  // namespace

int runCalibratePattern(const Args& args) {
  try {
    Args named = args;
    for (std::string& a : named)
      if (a == "-o") a = "--output";  // the short form of --output
    const Options o(named, {"--machine", "--output", "--marks", "--svg"}, {"--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    return run(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar calibrate pattern: " << e.what() << "\n" << kHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
