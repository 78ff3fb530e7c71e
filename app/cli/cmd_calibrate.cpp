// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar calibrate: the calibration commands (issue 13). A tiny dispatcher:
//   calibrate pattern ...  cmd_calibrate_pattern.cpp (docs/calibration-pattern.md)
//   calibrate scan ...     cmd_calibrate_scan.cpp (Qt builds only)
//   calibrate lines ...    cmd_calibrate_lines.cpp (Qt builds only)
//   calibrate fit ...      cmd_calibrate_fit.cpp (docs/calibration.md)
#include <iostream>

#include "commands.hpp"

namespace fivebar::cli {

namespace {
constexpr const char* kHelp =
    "usage: fivebar calibrate pattern --machine PRESET|FILE -o PATTERN.gcode --marks MARKS.csv\n"
    "                                 [--svg PATTERN.svg]\n"
#ifdef FIVEBAR_HAVE_QT
    "       fivebar calibrate scan --marks MARKS.csv --image SCAN.png --dpi 600 -o MEASURED.csv\n"
    "       fivebar calibrate lines --image SCAN.png --dpi 600 [-o LINES.csv]\n"
#endif
    "       fivebar calibrate fit --machine PRESET|FILE --measured MEASURED.csv -o CALIBRATED.json\n"
    "                             [--report REPORT.json] [--marks MARKS.csv] [--fit-pen-offset]\n"
    "Run 'fivebar calibrate SUBCOMMAND --help' for details (docs/calibration-pattern.md,\n"
    "docs/calibration.md).\n";
}

int runCalibrate(const Args& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    (args.empty() ? std::cerr : std::cout) << kHelp;
    return args.empty() ? 2 : 0;
  }
  const Args rest(args.begin() + 1, args.end());
  if (args[0] == "pattern") return runCalibratePattern(rest);
#ifdef FIVEBAR_HAVE_QT
  if (args[0] == "scan") return runCalibrateScan(rest);
  if (args[0] == "lines") return runCalibrateLines(rest);
#endif
  if (args[0] == "fit") return runCalibrateFit(rest);
  std::cerr << "fivebar calibrate: unknown subcommand '" << args[0] << "' (expected pattern, "
#ifdef FIVEBAR_HAVE_QT
            << "scan, lines, "
#endif
            << "fit)\n" << kHelp;
  return 2;
}

}  // namespace fivebar::cli
