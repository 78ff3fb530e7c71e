// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar calibrate pattern` and `fivebar calibrate scan` run as a user would: the pattern's
// files, a synthetic scan of the drawn sheet read back into MEASURED.csv, bad input named with
// nothing written.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "core/calibration/marks_csv.hpp"
#include "synthetic_scan.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

using cli_test::quote;
using cli_test::slurp;
namespace fs = std::filesystem;

cli_test::CliResult run(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = std::string(FIVEBAR_CLI) + " " + args + " >" + quote(out.string()) + " 2>" +
                          quote(err.string());
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

TEST(CalibratePatternScanCli, PatternThenScanGivesTheMeasuredMarks) {
  QTemporaryDir tmp;
  const fs::path dir = tmp.path().toStdString();
  const std::string marks = (dir / "MARKS.csv").string(), gcode = (dir / "P.gcode").string();
  const auto r = run("calibrate pattern --machine maker-plotter -o " + quote(gcode) + " --marks " +
                         quote(marks) + " --svg " + quote((dir / "P.svg").string()),
                     dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("37 marks: 25 for the fit, 4 backlash rows of 3"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(gcode).rfind("; FiveBar Studio job", 0), 0u);
  EXPECT_NE(slurp(dir / "P.svg").find("<svg"), std::string::npos);
  // The same pattern in process: MARKS.csv is what it writes.
  const PatternResult pr = makeCalibrationPattern(*preset("maker-plotter"));
  ASSERT_TRUE(pr.pattern);
  ASSERT_EQ(slurp(marks), marksCsv(*pr.pattern));
  // The drawn sheet, scanned at 600 dpi, turned and mirrored.
  test::SheetOptions o;
  o.dpi = 600;
  o.rotationDeg = 95.0;
  o.mirrored = true;
  o.blurSigmaPx = 1.2;
  o.noiseSigma = 6.0;
  o.seed = test::seed();
  const test::Sheet sheet = test::renderSheet(*pr.pattern, o);
  const std::string png = (dir / "SCAN.png").string(), measured = (dir / "MEASURED.csv").string();
  ASSERT_TRUE(sheet.image.save(QString::fromStdString(png)));
  const auto s = run("calibrate scan --marks " + quote(marks) + " --image " + quote(png) +
                         " --dpi 600 -o " + quote(measured) + " --reversed " + quote((dir / "REV.csv").string()),
                     dir);
  ASSERT_EQ(s.exitCode, 0) << s.err;
  EXPECT_NE(s.out.find("37 of 37 marks found"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("mirrored"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("backlash: motor 1 0.0"), std::string::npos) << s.out;  // none drawn
  const MeasuredLoad m = parseMeasuredCsv(slurp(measured), "MEASURED.csv");
  ASSERT_TRUE(m.ok()) << m.error;
  const MeasuredLoad rev = parseMeasuredCsv(slurp(dir / "REV.csv"), "REV.csv");
  ASSERT_TRUE(rev.ok()) << rev.error;
  EXPECT_EQ(m.marks.size(), 33u);  // every mark reached with both motors moving up
  EXPECT_EQ(rev.marks.size(), 4u);  // the rows' middle marks
  const MarksLoad ml = parseMarksCsv(slurp(marks), "MARKS.csv");
  for (const MeasuredMark& x : m.marks) {
    EXPECT_LT((x.measuredMm - sheet.truePaperMm.at(x.id)).norm(), 0.05) << "mark " << x.id;
    const PatternMark& pm = ml.marks[static_cast<size_t>(x.id - 1)].mark;
    EXPECT_NEAR(x.theta1Deg, degFromRad(pm.q.theta1), 1e-9);
    EXPECT_NEAR(x.theta2Deg, degFromRad(pm.q.theta2), 1e-9);
  }
}

// pattern -> synthetic scan with --reversed -> fit with --marks and --reversed: the profile carries
// the estimated backlash (none drawn: close to 0) and the report names it; --reversed without
// --marks, or with a REVERSED.csv missing a row's mark, is refused with nothing written.
TEST(CalibratePatternScanCli, FitWithReversedWritesTheBacklash) {
  QTemporaryDir tmp;
  const fs::path dir = tmp.path().toStdString();
  const std::string marks = (dir / "MARKS.csv").string(), gcode = (dir / "P.gcode").string();
  ASSERT_EQ(run("calibrate pattern --machine maker-plotter -o " + quote(gcode) + " --marks " + quote(marks), dir).exitCode, 0);
  const PatternResult pr = makeCalibrationPattern(*preset("maker-plotter"));
  ASSERT_TRUE(pr.pattern);
  test::SheetOptions o;
  o.dpi = 600;
  o.rotationDeg = -20.0;
  o.blurSigmaPx = 1.0;
  o.noiseSigma = 4.0;
  o.seed = test::seed();
  const std::string png = (dir / "SCAN.png").string(), measured = (dir / "MEASURED.csv").string(),
                    reversed = (dir / "REV.csv").string();
  ASSERT_TRUE(test::renderSheet(*pr.pattern, o).image.save(QString::fromStdString(png)));
  ASSERT_EQ(run("calibrate scan --marks " + quote(marks) + " --image " + quote(png) + " --dpi 600 -o " +
                    quote(measured) + " --reversed " + quote(reversed), dir).exitCode, 0);
  const std::string profile = (dir / "CAL.json").string(), report = (dir / "REPORT.json").string();
  const auto f = run("calibrate fit --machine maker-plotter --measured " + quote(measured) + " --marks " +
                         quote(marks) + " --reversed " + quote(reversed) + " -o " + quote(profile) +
                         " --report " + quote(report), dir);
  ASSERT_EQ(f.exitCode, 0) << f.err << f.out;
  EXPECT_NE(f.out.find("backlash: motor 1 "), std::string::npos) << f.out;
  const nlohmann::json p = nlohmann::json::parse(slurp(profile));
  ASSERT_TRUE(p.contains("calibration")) << p.dump(2);
  const nlohmann::json& c = p["calibration"];
  ASSERT_TRUE(c.contains("backlashDeg1") && c.contains("backlashDeg2")) << c.dump(2);  // rad in core, deg in the file
  for (const char* k : {"backlashDeg1", "backlashDeg2"}) {
    const double deg = c[k].get<double>();
    EXPECT_GE(deg, 0.0) << k;
    EXPECT_LT(deg, 0.05) << k;  // the synthetic sheet was drawn without play
  }
  const nlohmann::json rep = nlohmann::json::parse(slurp(report));
  ASSERT_TRUE(rep.contains("backlash")) << rep.dump(2);
  EXPECT_EQ(rep["backlash"]["rowsMotor1"].get<int>() + rep["backlash"]["rowsMotor2"].get<int>(), 4);
  EXPECT_LT(std::abs(rep["backlash"]["motor1Deg"].get<double>()), 0.05);
  EXPECT_LT(std::abs(rep["backlash"]["motor2Deg"].get<double>()), 0.05);
  // --reversed without --marks: refused, nothing written.
  const std::string none = (dir / "NONE.json").string();
  auto r = run("calibrate fit --machine maker-plotter --measured " + quote(measured) + " --reversed " +
                   quote(reversed) + " -o " + quote(none), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("give --marks MARKS.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(none));
  // A REVERSED.csv missing a row's middle mark: named, nothing written.
  const std::string revText = slurp(reversed);
  const std::string cut = revText.substr(0, revText.rfind('\n', revText.size() - 2) + 1);
  const std::string shortRev = (dir / "SHORT.csv").string();
  { std::ofstream(shortRev) << cut; }
  r = run("calibrate fit --machine maker-plotter --measured " + quote(measured) + " --marks " + quote(marks) +
              " --reversed " + quote(shortRev) + " -o " + quote(none), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(shortRev + ": incomplete backlash rows"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(none));
  // An unreadable REVERSED.csv.
  r = run("calibrate fit --machine maker-plotter --measured " + quote(measured) + " --marks " + quote(marks) +
              " --reversed " + quote((dir / "nosuch.csv").string()) + " -o " + quote(none), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("nosuch.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(none));
}

// The same path with play: the sheet drawn by a machine with 0.5 deg of play on motor 1 and 0.3 deg
// on motor 2 (each mark approached with a motor moving down stands that motor's play further on,
// the play model of core/calibration/backlash.hpp), scanned at 300 dpi turned and noisy: the fitted
// profile carries each motor's play within 0.03 deg.
TEST(CalibratePatternScanCli, FitWithReversedFindsEachMotorsPlay) {
  QTemporaryDir tmp;
  const fs::path dir = tmp.path().toStdString();
  const std::string marks = (dir / "MARKS.csv").string(), gcode = (dir / "P.gcode").string();
  ASSERT_EQ(run("calibrate pattern --machine maker-plotter -o " + quote(gcode) + " --marks " + quote(marks), dir).exitCode, 0);
  const MachineProfile machine = *preset("maker-plotter");
  const PatternResult pr = makeCalibrationPattern(machine);
  ASSERT_TRUE(pr.pattern);
  const double play1Rad = radFromDeg(0.5), play2Rad = radFromDeg(0.3);
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 12.0;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 5.0;
  o.seed = test::seed();
  int reversedMarks = 0;
  for (const PatternMark& m : pr.pattern->marks) {
    JointAngles arm = m.q;
    if (m.approach1 == Approach::Minus) arm.theta1 += play1Rad;
    if (m.approach2 == Approach::Minus) arm.theta2 += play2Rad;
    const FkResult fk = forward(machine.geometry, arm, machine.assembly);
    ASSERT_TRUE(fk.ok());
    o.displacementMm[m.id] = fk.p - m.nominalMm;
    reversedMarks += (fk.p - m.nominalMm).norm() > 0.1 ? 1 : 0;
  }
  ASSERT_EQ(reversedMarks, 4);  // the middle mark of each backlash row
  const std::string png = (dir / "SCAN.png").string(), measured = (dir / "MEASURED.csv").string(),
                    reversed = (dir / "REV.csv").string(), profile = (dir / "CAL.json").string();
  ASSERT_TRUE(test::renderSheet(*pr.pattern, o).image.save(QString::fromStdString(png)));
  ASSERT_EQ(run("calibrate scan --marks " + quote(marks) + " --image " + quote(png) + " --dpi 300 -o " +
                    quote(measured) + " --reversed " + quote(reversed), dir).exitCode, 0);
  const auto f = run("calibrate fit --machine maker-plotter --measured " + quote(measured) + " --marks " +
                         quote(marks) + " --reversed " + quote(reversed) + " -o " + quote(profile), dir);
  ASSERT_EQ(f.exitCode, 0) << f.err << f.out;
  const nlohmann::json c = nlohmann::json::parse(slurp(profile))["calibration"];
  std::printf("play 0.5 / 0.3 deg drawn: fitted %.4f / %.4f deg\n", c["backlashDeg1"].get<double>(),
              c["backlashDeg2"].get<double>());
  EXPECT_NEAR(c["backlashDeg1"].get<double>(), 0.5, 0.03);
  EXPECT_NEAR(c["backlashDeg2"].get<double>(), 0.3, 0.03);
}

TEST(CalibratePatternScanCli, BadInputIsNamedAndNothingIsWritten) {
  QTemporaryDir tmp;
  const fs::path dir = tmp.path().toStdString();
  const std::string marks = (dir / "MARKS.csv").string(), out = (dir / "MEASURED.csv").string();
  ASSERT_EQ(run("calibrate pattern --machine maker-plotter -o " + quote((dir / "P.gcode").string()) +
                    " --marks " + quote(marks), dir).exitCode, 0);
  // An unreadable image.
  const std::string junk = (dir / "junk.png").string();
  { std::FILE* f = std::fopen(junk.c_str(), "wb"); std::fputs("junk", f); std::fclose(f); }
  auto r = run("calibrate scan --marks " + quote(marks) + " --image " + quote(junk) + " --dpi 600 -o " + quote(out), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(junk + ": cannot read the image"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // The wrong dpi.
  const PatternResult pr = makeCalibrationPattern(*preset("maker-plotter"));
  test::SheetOptions o;
  o.dpi = 300;
  const std::string png = (dir / "SCAN.png").string();
  ASSERT_TRUE(test::renderSheet(*pr.pattern, o).image.save(QString::fromStdString(png)));
  r = run("calibrate scan --marks " + quote(marks) + " --image " + quote(png) + " --dpi 600 -o " + quote(out), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(png + ": no marks found at 600 dpi"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A broken MARKS.csv names its line.
  const std::string bad = (dir / "BAD.csv").string();
  { std::FILE* f = std::fopen(bad.c_str(), "wb"); std::fputs((std::string(kMarksCsvHeader) + "\n1,x,2,3,4,grid,+,+,0,0,2.5\n").c_str(), f); std::fclose(f); }
  r = run("calibrate scan --marks " + quote(bad) + " --image " + quote(png) + " --dpi 300 -o " + quote(out), dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(bad + ":2: theta1_deg: 'x' is not a number"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // Usage errors.
  r = run("calibrate scan --marks " + quote(marks) + " --image " + quote(png) + " --dpi abc -o " + quote(out), dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--dpi needs a positive number, got 'abc'"), std::string::npos) << r.err;
  r = run("calibrate pattern --machine nosuchpreset -o x.gcode --marks m.csv", dir);
  EXPECT_EQ(r.exitCode, 1);
  r = run("calibrate pattern --machine maker-plotter --marks m.csv", dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("missing required option -o"), std::string::npos) << r.err;
  r = run("calibrate frobnicate", dir);
  EXPECT_EQ(r.exitCode, 2);
}

}  // namespace
}  // namespace fivebar
