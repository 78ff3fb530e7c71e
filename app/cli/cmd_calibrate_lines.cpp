// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar calibrate lines --image SCAN.png --dpi 600 [-o LINES.csv]: Hoang's accuracy lines measured
// in a scan of the drawn sheet (core/calibration/scan/scan_lines.hpp).
#include <QGuiApplication>
#include <cmath>
#include <iostream>
#include <sstream>

#include "calibrate_files.hpp"
#include "commands.hpp"
#include "core/calibration/scan/scan_lines.hpp"
#include "core/output/fixed_decimal.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kHelp =
    "usage: fivebar calibrate lines --image SCAN.png --dpi 600 [-o LINES.csv]\n"
    "Measures Hoang's accuracy lines (10 parallel lines of 40 mm, drawn by 'fivebar calibrate\n"
    "pattern' or the studio's calibration wizard) in a scan of the drawn sheet (PNG or JPEG at\n"
    "the given dpi; the sheet may lie turned or mirrored; other ink such as marks is ignored).\n"
    "Prints each line's length (between the ends of the pen's centre path) and straightness (the\n"
    "largest distance of its centre from the best-fit line), and the worst and RMS figures.\n"
    "  -o, --output LINES.csv  line,length_mm,length_error_mm,straightness_mm,x0_mm,y0_mm,x1_mm,y1_mm\n"
    "                          (ends in mm from the image's lower left corner, y up)\n";

std::string linesCsv(const LineScanOutcome& scan) {
  std::ostringstream out;
  out << "line,length_mm,length_error_mm,straightness_mm,x0_mm,y0_mm,x1_mm,y1_mm\n";
  for (size_t i = 0; i < scan.lines.size(); ++i) {
    const ScannedLine& l = scan.lines[i];
    const LineAccuracy& f = scan.figures->lines[i];
    out << i + 1 << ',' << fixedDecimal(f.lengthMm, 4) << ',' << fixedDecimal(f.lengthErrorMm, 4) << ','
        << fixedDecimal(f.straightnessMm, 4) << ',' << fixedDecimal(l.startMm.x(), 4) << ','
        << fixedDecimal(l.startMm.y(), 4) << ',' << fixedDecimal(l.endMm.x(), 4) << ','
        << fixedDecimal(l.endMm.y(), 4) << '\n';
  }
  return out.str();
}

int run(const Options& o) {
  if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
  const std::string imagePath = o.required("--image");
  const double dpi = numberArg(o.required("--dpi"), "--dpi", true);
  int argc = 1;
  char name[] = "fivebar";
  char* argv[] = {name, nullptr};
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  const QGuiApplication app(argc, argv);  // image format plugins
  const LineScanOutcome scan = scanAccuracyLinesFile(imagePath, dpi);
  if (!scan.ok() || !scan.figures) {
    std::cerr << "fivebar calibrate lines: "
              << (scan.ok() ? std::string(imagePath + ": a line is too short to measure") : scan.error.text()) << "\n";
    return 1;
  }
  if (const auto out = o.value("--output"))
    if (!writeAllFiles({{*out, linesCsv(scan)}}, "calibrate lines")) return 1;
  const AccuracyFigures& f = *scan.figures;
  std::cout << scan.lines.size() << " accuracy lines found in " << imagePath << " (along "
            << fixedDecimal(scan.directionDeg, 1) << " deg in the image)\n";
  for (size_t i = 0; i < f.lines.size(); ++i)
    std::cout << "line " << i + 1 << ": length " << fixedDecimal(f.lines[i].lengthMm, 3) << " mm ("
              << (f.lines[i].lengthErrorMm >= 0 ? "+" : "") << fixedDecimal(f.lines[i].lengthErrorMm, 3)
              << "), straightness " << fixedDecimal(f.lines[i].straightnessMm, 3) << " mm\n";
  std::cout << "worst length error " << fixedDecimal(f.maxAbsLengthErrorMm, 3) << " mm (rms "
            << fixedDecimal(f.rmsLengthErrorMm, 3) << "), worst straightness " << fixedDecimal(f.maxStraightnessMm, 3)
            << " mm (rms " << fixedDecimal(f.rmsStraightnessMm, 3) << ")\n";
  return 0;
}

}  // namespace

int runCalibrateLines(const Args& args) {
  try {
    Args named = args;
    for (std::string& a : named)
      if (a == "-o") a = "--output";  // the short form of --output
    const Options o(named, {"--image", "--dpi", "--output"}, {"--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    return run(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar calibrate lines: " << e.what() << "\n" << kHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
