// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar: the command-line tool on the FiveBar Studio core.
#include <cstring>
#ifdef FIVEBAR_HAVE_QT
#include <QLocale>
#endif
#include <exception>
#include <iostream>
#include <string_view>

#include "commands.hpp"
#include "options.hpp"

namespace {

struct Command {
  std::string_view name;
  std::string_view summary;
  int (*run)(const fivebar::cli::Args&);
};

constexpr Command kCommands[] = {
    {"ik", "inverse kinematics: x,y lines on stdin -> theta1,theta2 (deg)", fivebar::cli::runIk},
    {"fk", "forward kinematics: theta1,theta2 lines on stdin -> x,y (mm)", fivebar::cli::runFk},
    {"workspace", "workspace areas, inscribed rectangle, overlay image", fivebar::cli::runWorkspace},
    {"design", "link lengths for a paper size: search, trade-off, profile", fivebar::cli::runDesign},
    {"profile", "machine profiles: check FILE", fivebar::cli::runProfile},
    {"plan", "SVG drawing -> GRBL G-code job and report", fivebar::cli::runPlan},
    {"text", "text in a single-stroke Hershey font -> SVG of paths in mm; --list-fonts", fivebar::cli::runText},
    {"grbl-settings", "the GRBL $ settings a machine profile expects", fivebar::cli::runGrblSettings},
    {"calibrate", "calibration: pattern (G-code, MARKS.csv), scan (MEASURED.csv), fit -> calibrated profile", fivebar::cli::runCalibrate},
#ifdef FIVEBAR_HAVE_DRIVERS
    {"stream", "stream a G-code job to a GRBL board (character counting, resume)", fivebar::cli::runStream},
    {"send", "send one-off lines or settings to a GRBL board", fivebar::cli::runSend},
    {"reference", "declare the machine's current pose its home pose (G10 L20)", fivebar::cli::runReference},
    {"home", "home the machine ($H, or a checked move to the home pose)", fivebar::cli::runHome},
    {"frame", "trace a job's outline pen up (checked moves) to see where it lands", fivebar::cli::runFrame},
    {"setup", "compare a GRBL board's settings with a profile; --write applies them", fivebar::cli::runSetup},
#endif
};

void usage(std::ostream& out) {
  out << "usage: fivebar COMMAND [OPTIONS]\n\ncommands:\n";
  for (const Command& c : kCommands) out << "  " << c.name << "\t" << c.summary << "\n";
  out << "\nRun 'fivebar COMMAND --help' for a command's options; 'fivebar --version' prints the\n"
         "version.\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    usage(argc < 2 ? std::cerr : std::cout);
    return argc < 2 ? 2 : 0;
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    std::cout << "fivebar " FIVEBAR_VERSION "\n";
    return 0;
  }
#ifdef FIVEBAR_HAVE_QT
  // Numbers in the images the CLI paints (workspace/design --png) keep the decimal point, as
  // all its output does, whatever the user's locale.
  QLocale::setDefault(QLocale::c());
#endif
  const fivebar::cli::Args args(argv + 2, argv + argc);
  for (const Command& c : kCommands) {
    if (c.name != argv[1]) continue;
    try {
      return c.run(args);
    } catch (const fivebar::cli::UsageError& e) {  // a command that does not catch its own
      std::cerr << "fivebar " << c.name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "fivebar " << c.name << ": " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "fivebar: unknown command '" << argv[1] << "'\n\n";
  usage(std::cerr);
  return 2;
}
