// fivebar calibrate: the calibration commands (issue 13, docs/calibration.md). A tiny dispatcher:
//   calibrate fit ...      cmd_calibrate_fit.cpp
// (calibrate pattern and calibrate scan are added beside it.)
#include <iostream>

#include "commands.hpp"

namespace fivebar::cli {

namespace {
constexpr const char* kHelp =
    "usage: fivebar calibrate fit --machine PRESET|FILE --measured MEASURED.csv -o CALIBRATED.json\n"
    "                             [--report REPORT.json] [--marks MARKS.csv] [--fit-pen-offset]\n"
    "Run 'fivebar calibrate SUBCOMMAND --help' for details (docs/calibration.md).\n";
}

int runCalibrate(const Args& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    (args.empty() ? std::cerr : std::cout) << kHelp;
    return args.empty() ? 2 : 0;
  }
  const Args rest(args.begin() + 1, args.end());
  if (args[0] == "fit") return runCalibrateFit(rest);
  std::cerr << "fivebar calibrate: unknown subcommand '" << args[0] << "' (expected fit)\n" << kHelp;
  return 2;
}

}  // namespace fivebar::cli
