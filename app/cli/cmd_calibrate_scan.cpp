// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar calibrate scan --marks MARKS.csv --image SCAN.png --dpi 600 -o MEASURED.csv
#include <QGuiApplication>
#include <cmath>
#include <iostream>
#include <map>

#include "calibrate_files.hpp"
#include "commands.hpp"
#include "core/calibration/backlash.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/scan/scan.hpp"
#include "core/output/fixed_decimal.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kHelp =
    "usage: fivebar calibrate scan --marks MARKS.csv --image SCAN.png --dpi 600 -o MEASURED.csv\n"
    "                              [--reversed REVERSED.csv]\n"
    "Finds the pattern's marks (a dot in a ring) in a scan of the drawn sheet (PNG or JPEG at the\n"
    "given dpi; the sheet may lie turned or mirrored) and numbers them by matching the pattern.\n"
    "  -o, --output MEASURED.csv  id, theta1_deg, theta2_deg (commanded), x_mm, y_mm (measured,\n"
    "                             mm from the image's lower left corner, y up) of every mark\n"
    "                             reached with both motors moving up: the input of\n"
    "                             'fivebar calibrate fit'\n"
    "  --reversed REVERSED.csv    the same for the backlash rows' middle marks\n"
    "Prints each motor's backlash measured by the backlash rows.\n";

int run(const Options& o) {
  if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
  const std::string output = o.value("--output").value_or("");
  if (output.empty()) throw UsageError("missing required option -o MEASURED.csv");
  const std::string marksPath = o.required("--marks");
  const std::string imagePath = o.required("--image");
  const double dpi = numberArg(o.required("--dpi"), "--dpi", true);
  const MarksLoad marks = loadMarksCsv(marksPath);
  if (!marks.ok()) {
    std::cerr << "fivebar calibrate scan: " << marks.error << "\n";
    return 1;
  }
  int argc = 1;
  char name[] = "fivebar";
  char* argv[] = {name, nullptr};
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  const QGuiApplication app(argc, argv);  // image format plugins
  const ScanOutcome scan = scanFile(imagePath, dpi, marks.marks);
  if (!scan.ok()) {
    std::cerr << "fivebar calibrate scan: " << scan.error << "\n";
    return 1;
  }
  std::map<int, const PatternMark*> byId;
  std::vector<PatternMark> pattern;
  for (const MarkRecord& r : marks.marks) pattern.push_back(r.mark);
  for (const PatternMark& m : pattern) byId[m.id] = &m;
  std::vector<MeasuredMark> forward, reversed;
  std::map<int, Vec2> measuredById;
  for (const MeasuredMark& m : scan.measured) {
    const PatternMark& pm = *byId.at(m.id);
    measuredById[m.id] = m.measuredMm;
    (pm.approach1 == Approach::Plus && pm.approach2 == Approach::Plus ? forward : reversed).push_back(m);
  }
  std::vector<std::pair<std::string, std::string>> files{{output, measuredCsv(forward)}};
  if (const auto r = o.value("--reversed")) files.push_back({*r, measuredCsv(reversed)});
  if (!writeAllFiles(files, "calibrate scan")) return 1;
  std::cout << scan.measured.size() << " of " << marks.marks.size() << " marks found in " << imagePath
            << " (sheet turned " << fixedDecimal(scan.rotationDeg, 1) << " deg"
            << (scan.mirrored ? ", mirrored" : "") << "; " << fixedDecimal(scan.rmsMm, 2)
            << " mm rms from the nominal marks before calibration)\n";
  if (!scan.missingIds.empty()) {
    std::cout << "missing marks:";
    for (int id : scan.missingIds) std::cout << " " << id;
    std::cout << "\n";
  }
  const BacklashEstimate b = estimateBacklash(pattern, measuredById);
  if (b.ok()) {
    std::cout << "backlash: motor 1 " << fixedDecimal(degFromRad(b.play.motor1Rad), 3) << " deg ("
              << b.rowsMotor1 << " rows), motor 2 " << fixedDecimal(degFromRad(b.play.motor2Rad), 3) << " deg ("
              << b.rowsMotor2 << " rows)\n";
  }
  return 0;
}

}  // namespace

int runCalibrateScan(const Args& args) {
  try {
    Args named = args;
    for (std::string& a : named)
      if (a == "-o") a = "--output";  // the short form of --output
    const Options o(named, {"--marks", "--image", "--dpi", "--output", "--reversed"}, {"--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    return run(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar calibrate scan: " << e.what() << "\n" << kHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
