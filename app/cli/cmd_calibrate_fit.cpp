// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar calibrate fit: measured marks -> a calibrated profile and a report (docs/calibration.md).
#include <algorithm>
#include <ctime>
#include <map>
#include <optional>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/calibration/backlash.hpp"
#include "core/calibration/calibrate.hpp"
#include "core/calibration/fit.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/measurements.hpp"
#include "machine_arg.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

using namespace fivebar::calibration;
using nlohmann::json;

constexpr const char* kHelp =
    "usage: fivebar calibrate fit --machine PRESET|FILE --measured MEASURED.csv -o CALIBRATED.json\n"
    "                             [--report REPORT.json] [--marks MARKS.csv] [--reversed REVERSED.csv]\n"
    "                             [--fit-pen-offset]\n"
    "Fits the machine's link lengths and motor zero offsets to measured marks and writes the\n"
    "complete calibrated profile (docs/calibration.md).\n"
    "  --machine PRESET|FILE   the profile the marks were drawn with\n"
    "  --measured FILE         CSV: id,theta1_deg,theta2_deg,x_mm,y_mm (theta = commanded angles as\n"
    "                          sent in G-code; x, y in any paper frame, mirrored or not), or\n"
    "                          id_a,id_b,distance_mm (ruler distances; needs --marks)\n"
    "  --marks FILE            CSV: id,theta1_deg,theta2_deg of the marks (the distance form), or\n"
    "                          the full MARKS.csv of `fivebar calibrate pattern` (needed by --reversed)\n"
    "  --reversed FILE         the backlash rows' middle marks (`calibrate scan --reversed`, same paper\n"
    "                          frame as --measured): estimates each motor's backlash (clamped >= 0)\n"
    "                          into the profile's calibration section\n"
    "  -o, --output FILE       the calibrated profile (nothing is written when the fit fails)\n"
    "  --report FILE           JSON: before/after errors, parameters with standard deviations,\n"
    "                          outliers, conditioning, every mark's residual\n"
    "  --fit-pen-offset        also fit the pen's offset from the distal joint\n";

std::string nowIso() {
  const std::time_t t = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

const char* roleName(Role r) {
  switch (r) {
    case Role::Fitted: return "fitted";
    case Role::HeldOut: return "held-out";
    case Role::Outlier: return "outlier";
  }
  return "fitted";
}

json reportOf(const CalibrationFit& f, const MachineProfile& nominal, const std::string& measured, bool distances,
              const std::optional<BacklashEstimate>& backlash) {
  json j;
  j["schema"] = "fivebar-calibration-report";
  j["version"] = 1;
  j["machine"] = nominal.name;
  j["measured"] = measured;
  j["form"] = distances ? "distances" : "marks";
  j["before"] = {{"rmsMm", f.beforeRmsMm}, {"maxMm", f.beforeMaxMm}};
  j["after"] = {{"rmsMm", f.afterRmsMm}, {"maxMm", f.afterMaxMm}};
  j["heldOut"] = {{"count", f.heldOut}, {"beforeRmsMm", f.heldOutBeforeRmsMm}, {"rmsMm", f.heldOutRmsMm},
                  {"maxMm", f.heldOutMaxMm}};
  j["used"] = f.used;
  j["conditionNumber"] = f.conditionNumber;
  j["residualSigmaMm"] = f.residualSigmaMm;
  j["outliers"] = f.outlierIds;
  const MachineParameters nominalParameters = parametersOf(nominal);
  const double nominalValues[] = {nominal.geometry.a1, nominal.geometry.b1, nominal.geometry.a2, nominal.geometry.b2,
                                  nominal.geometry.w, degFromRad(nominalParameters.zeroOffsetRad1),
                                  degFromRad(nominalParameters.zeroOffsetRad2)};
  j["parameters"] = json::array();
  for (std::size_t i = 0; i < f.estimates.size(); ++i) {
    const ParameterEstimate& e = f.estimates[i];
    json p = {{"name", e.name}, {"unit", e.unit}, {"value", e.value}, {"stdDev", e.stdDev}, {"machine", e.machine}};
    if (i < 7) p["nominal"] = nominalValues[i];
    j["parameters"].push_back(p);
  }
  if (f.paper) j["paper"] = {{"mirrored", f.paper->mirrored}, {"rotationDeg", degFromRad(f.paper->rotationRad)},
                             {"xMm", f.paper->translationMm.x()}, {"yMm", f.paper->translationMm.y()}};
  j["measurements"] = json::array();
  for (const MeasurementResidual& r : f.residuals) {
    json m = {{"id", r.id}, {"role", roleName(r.role)}, {"residualMm", r.residualMm}};
    if (!distances) m["residualXMm"] = r.residualVecMm.x(), m["residualYMm"] = r.residualVecMm.y();
    j["measurements"].push_back(m);
  }
  j["functionEvaluations"] = f.functionEvaluations;
  if (backlash) {
    j["backlash"] = {{"motor1Deg", degFromRad(backlash->play.motor1Rad)},
                     {"motor2Deg", degFromRad(backlash->play.motor2Rad)},
                     {"rowsMotor1", backlash->rowsMotor1},
                     {"rowsMotor2", backlash->rowsMotor2},
                     {"rows", json::array()}};
    for (const BacklashRowEstimate& r : backlash->rows)
      j["backlash"]["rows"].push_back({{"group", r.group}, {"motor", r.motor}, {"playDeg", degFromRad(r.playRad)}});
  }
  return j;
}

void printSummary(const CalibrationFit& f) {
  std::cout << std::fixed << std::setprecision(3);
  std::cout << "before: rms " << f.beforeRmsMm << " mm, max " << f.beforeMaxMm << " mm (nominal profile)\n";
  std::cout << "after:  rms " << f.afterRmsMm << " mm, max " << f.afterMaxMm << " mm (" << f.used << " used)\n";
  if (f.heldOut > 0)
    std::cout << "held-out: rms " << f.heldOutRmsMm << " mm, max " << f.heldOutMaxMm << " mm (" << f.heldOut
              << " left out of a first fit; nominal " << f.heldOutBeforeRmsMm << " mm)\n";
  std::cout << "outliers: " << (f.outlierIds.empty() ? "none" : "");
  for (std::size_t i = 0; i < f.outlierIds.size(); ++i) std::cout << (i ? ", " : "") << f.outlierIds[i];
  std::cout << "\ncondition number: " << std::setprecision(0) << f.conditionNumber << std::setprecision(4) << "\n";
  for (const ParameterEstimate& e : f.estimates)
    if (e.machine) std::cout << "  " << std::left << std::setw(16) << e.name << std::right << std::setw(12) << e.value
                             << " +- " << e.stdDev << " " << e.unit << "\n";
}

// The backlash rows of MEASURED.csv + REVERSED.csv and the full MARKS.csv into `input` (the door
// estimates the play); false with an error message naming the file when something is missing or
// unreadable.
bool backlashRowsOf(const std::string& marksPath, const std::string& measuredPath,
                    const std::string& measuredText, const std::string& reversedPath,
                    CalibrationInput& input, std::string& error) {
  std::string marksText, reversedText;
  Message why;
  if (!readTextFile(marksPath, marksText, why) || !readTextFile(reversedPath, reversedText, why)) {
    error = why.text();
    return false;
  }
  const MarksLoad marks = parseMarksCsv(marksText, marksPath);
  if (!marks.ok()) {
    error = marks.error.text() + " (--reversed needs the full MARKS.csv of `fivebar calibrate pattern`)";
    return false;
  }
  std::map<int, Vec2> measuredById;
  for (const auto& [path, text] : {std::pair{measuredPath, measuredText}, std::pair{reversedPath, reversedText}}) {
    const MeasuredLoad m = parseMeasuredCsv(text, path);
    if (!m.ok()) {
      error = m.error.text();
      return false;
    }
    for (const MeasuredMark& x : m.marks) measuredById[x.id] = x.measuredMm;
  }
  std::vector<PatternMark> pattern;
  std::vector<int> missing;
  for (const MarkRecord& r : marks.marks) {
    pattern.push_back(r.mark);
    if (r.mark.kind == MarkKind::Backlash && !measuredById.count(r.mark.id)) missing.push_back(r.mark.id);
  }
  if (!missing.empty()) {
    error = reversedPath + ": incomplete backlash rows: mark";
    for (std::size_t i = 0; i < missing.size(); ++i) error += (i ? ", " : " ") + std::to_string(missing[i]);
    error += " of " + marksPath + " not measured in " + measuredPath + " or " + reversedPath;
    return false;
  }
  input.patternMarks = std::move(pattern);
  input.measuredById = std::move(measuredById);
  return true;
}

int fit(const Options& o) {
  const std::string measuredPath = o.required("--measured"), output = o.required("--output");
  const auto nominal = loadMachine(o.required("--machine"), "calibrate fit", std::cerr);
  if (!nominal) return 1;
  auto fail = [](const std::string& message) {
    std::cerr << "fivebar calibrate fit: " << message << "\n";
    return 1;
  };
  std::string text, error;
  if (Message why; !readTextFile(measuredPath, text, why)) return fail(why.text());
  const MeasurementRead read = readMeasurements(text, measuredPath);
  if (!read.ok()) return fail(read.error.text());
  CalibrationInput input;
  input.nominal = *nominal;
  input.options.fitPenOffset = o.flag("--fit-pen-offset");
  input.dateIso = nowIso();
  const auto reversedPath = o.value("--reversed");
  if (reversedPath) {
    const auto marksPath = o.value("--marks");
    if (!marksPath) return fail("--reversed " + *reversedPath + " needs the pattern's marks: give --marks MARKS.csv");
    if (read.form != MeasurementForm::Marks) return fail("--reversed needs marks measured on the sheet, but " + measuredPath + " holds distances");
    if (!backlashRowsOf(*marksPath, measuredPath, text, *reversedPath, input, error))
      return fail(error + "; no profile written");
  }
  const bool distances = read.form == MeasurementForm::Distances;
  if (distances) {
    const auto marksPath = o.value("--marks");
    if (!marksPath) return fail(measuredPath + " holds distances: give the marks' angles with --marks MARKS.csv");
    std::string marksText;
    if (Message why; !readTextFile(*marksPath, marksText, why)) return fail(why.text());
    const MarkPosesRead marks = readMarkPoses(marksText, *marksPath);
    if (!marks.ok()) return fail(marks.error.text());
    input.poses = marks.marks;
    input.distances = read.distances;
  } else {
    input.marks = read.marks;
  }
  const CalibrationOutcome outcome = calibrate(input, /*backlashRequired=*/true);
  const CalibrationFit& result = outcome.fit;
  const std::optional<BacklashEstimate>& backlash = outcome.backlash;
  switch (outcome.stage) {
    case CalibrationStage::Backlash:
      return fail(*reversedPath + ": " + outcome.error.text() + "; no profile written");
    case CalibrationStage::Fit:
      if (distances && result.status == FitStatus::BadInput && result.reason.text().rfind("line ", 0) == 0)
        return fail(measuredPath + ":" + result.reason.text().substr(5));
      return fail(measuredPath + ": no profile written: " + result.reason.text());
    case CalibrationStage::Validation:
      return fail("the fitted profile is not valid (" + outcome.error.text() + "); no profile written");
    case CalibrationStage::Calibrated: break;
  }
  const MachineProfile& calibrated = *outcome.profile;
  if (const auto reportPath = o.value("--report")) {
    std::ofstream report(*reportPath, std::ios::binary);
    if (!(report << reportOf(result, *nominal, measuredPath, distances, backlash).dump(2) << "\n"))
      return fail("cannot write " + *reportPath);
  }
  if (const std::string saveError = saveProfile(calibrated, output); !saveError.empty()) return fail(saveError);
  printSummary(result);
  if (backlash) {
    std::cout << "backlash: motor 1 " << std::setprecision(3) << degFromRad(calibrated.calibration->backlashRad1)
              << " deg (" << backlash->rowsMotor1 << " rows), motor 2 "
              << degFromRad(calibrated.calibration->backlashRad2) << " deg (" << backlash->rowsMotor2 << " rows)\n";
    for (int k = 1; k <= 2; ++k) {
      const double rad = k == 1 ? backlash->play.motor1Rad : backlash->play.motor2Rad;
      if (rad < 0.0)
        std::cout << "note: motor " << k << "'s backlash estimate was negative (" << std::setprecision(3)
                  << degFromRad(rad) << " deg, measurement noise); written as 0\n";
    }
  }
  std::cout << "wrote " << output << "\n";
  return 0;
}

}  // namespace

int runCalibrateFit(const Args& args) {
  try {
    Args normalized = args;
    for (std::string& a : normalized)
      if (a == "-o") a = "--output";
    const Options o(normalized, {"--machine", "--measured", "--output", "--report", "--marks", "--reversed"},
                    {"--fit-pen-offset", "--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    if (!o.positional().empty()) throw UsageError("unexpected argument " + o.positional()[0]);
    return fit(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar calibrate fit: " << e.what() << "\n" << kHelp;
    return 2;
  }
}

}  // namespace fivebar::cli
