// fivebar calibrate: the calibration commands (docs/calibration-pattern.md).
//   calibrate pattern   the calibration pattern: G-code, MARKS.csv, optional SVG
//   calibrate scan      marks found in a scanned sheet -> MEASURED.csv
#include <iostream>

#include "commands.hpp"

namespace fivebar::cli {

int runCalibrate(const Args& args) {
  constexpr const char* kHelp =
      "usage: fivebar calibrate pattern|scan [OPTIONS]\n"
      "  pattern   draw the calibration pattern: G-code, MARKS.csv, optional SVG\n"
      "  scan      find the pattern's marks in a scanned sheet: MEASURED.csv\n"
      "Run 'fivebar calibrate SUBCOMMAND --help' for its options.\n";
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    (args.empty() ? std::cerr : std::cout) << kHelp;
    return args.empty() ? 2 : 0;
  }
  const Args rest(args.begin() + 1, args.end());
  if (args[0] == "pattern") return runCalibratePattern(rest);
  if (args[0] == "scan") return runCalibrateScan(rest);
  std::cerr << "fivebar calibrate: unknown subcommand '" << args[0] << "'\n" << kHelp;
  return 2;
}

}  // namespace fivebar::cli
