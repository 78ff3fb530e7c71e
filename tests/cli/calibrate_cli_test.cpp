// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar calibrate fit` end to end: the simulated maker-plotter's marks -> a calibrated profile
// and report; outliers named; the distance form; bad input named by file and line, nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "calibration_scenario.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using cli_test::CliResult;
using cli_test::quote;
using cli_test::slurp;
using nlohmann::json;

std::string csvOf(const std::vector<calibration::MarkMeasurement>& marks) {
  std::string s = "id,theta1_deg,theta2_deg,x_mm,y_mm\n";
  char line[200];
  for (const auto& m : marks) {
    std::snprintf(line, sizeof line, "%s,%.4f,%.4f,%.3f,%.3f\n", m.id.c_str(), degFromRad(m.commanded.theta1),
                  degFromRad(m.commanded.theta2), m.paperMm.x(), m.paperMm.y());
    s += line;
  }
  return s;
}

class CalibrateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-calibrate-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  void TearDown() override { fs::remove_all(dir_); }
  CliResult run(const std::vector<std::string>& args) {
    std::string cmd = quote(FIVEBAR_CLI) + " calibrate";
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd += " </dev/null >" + quote((dir_ / "out").string()) + " 2>" + quote((dir_ / "err").string());
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out"), slurp(dir_ / "err")};
  }
  std::string file(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Runs a fit that must fail: exit 1, stderr containing `fragment`, no profile written.
  void expectRefused(const std::string& measured, const std::string& fragment) {
    const CliResult r = run({"fit", "--machine", "maker-plotter", "--measured", measured, "-o", path("out.json")});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.json")));
  }
  fs::path dir_;
};

const MachineProfile& nominal() {
  static const MachineProfile p = *preset("maker-plotter");
  return p;
}

TEST_F(CalibrateCli, FitWritesACalibratedProfileAndAReport) {
  auto marks = test::measuredMarks(nominal(), test::seed(), true);
  marks[12].paperMm += Vec2(0.0, 3.0);  // mark 13 mis-measured by 3 mm
  const std::string measured = file("MEASURED.csv", csvOf(marks));
  const CliResult r = run({"fit", "--machine", "maker-plotter", "--measured", measured, "-o", path("cal.json"),
                           "--report", path("report.json")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("outliers: 13"), std::string::npos) << r.out;
  const ProfileLoad load = loadProfile(path("cal.json"));
  ASSERT_TRUE(load.profile);
  ASSERT_TRUE(load.profile->calibration);
  EXPECT_EQ(load.profile->calibration->fit.outlierIds, std::vector<std::string>{"13"});
  EXPECT_EQ(load.profile->calibration->fit.marksUsed, 24);
  EXPECT_NEAR(degFromRad(load.profile->calibration->zeroOffsetRad1), 1.0, 0.2);
  const calibration::ShapeError after = test::areaShapeError(*load.profile, test::workingArea(nominal()));
  EXPECT_LE(after.maxMm, 0.15);
  const json report = json::parse(slurp(path("report.json")));
  EXPECT_EQ(report["outliers"], json::array({"13"}));
  EXPECT_GT(report["before"]["rmsMm"].get<double>(), 0.5);
  EXPECT_LT(report["after"]["rmsMm"].get<double>(), 0.1);
  EXPECT_EQ(report["paper"]["mirrored"], true);
  EXPECT_EQ(report["parameters"][0]["name"], "a1");
  EXPECT_GT(report["parameters"][0]["stdDev"].get<double>(), 0.0);
  EXPECT_EQ(report["measurements"].size(), 25u);
  EXPECT_EQ(report["measurements"][12]["role"], "outlier");
}

TEST_F(CalibrateCli, DistanceFormNeedsTheMarksAndWorksWithThem) {
  const auto marks = test::measuredMarks(nominal(), test::seed(), false, 0.02);
  std::string marksCsv = "id,theta1_deg,theta2_deg\n", dist = "id_a,id_b,distance_mm\n";
  char line[200];
  for (const auto& m : marks) {
    std::snprintf(line, sizeof line, "%s,%.5f,%.5f\n", m.id.c_str(), degFromRad(m.commanded.theta1),
                  degFromRad(m.commanded.theta2));
    marksCsv += line;
  }
  for (std::size_t i = 0; i < marks.size(); ++i)
    for (std::size_t j = i + 1; j < marks.size(); j += 4) {
      std::snprintf(line, sizeof line, "%s,%s,%.3f\n", marks[i].id.c_str(), marks[j].id.c_str(),
                    (marks[i].paperMm - marks[j].paperMm).norm());
      dist += line;
    }
  const std::string measured = file("DIST.csv", dist);
  expectRefused(measured, "give the marks' angles with --marks");
  const CliResult r = run({"fit", "--machine", "maker-plotter", "--measured", measured, "--marks",
                           file("MARKS.csv", marksCsv), "-o", path("cal.json")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ProfileLoad load = loadProfile(path("cal.json"));
  ASSERT_TRUE(load.profile);
  EXPECT_LE(test::areaShapeError(*load.profile, test::workingArea(nominal())).maxMm, 0.1);
}

TEST_F(CalibrateCli, BadInputIsNamedByFileAndLineAndNothingIsWritten) {
  const std::string good = csvOf(test::measuredMarks(nominal(), test::seed(), false));
  std::string noColumn = good;
  noColumn.replace(0, noColumn.find('\n'), "id,theta1_deg,theta2_deg,x_mm");
  expectRefused(file("a.csv", noColumn), "a.csv:1: the header has no column y_mm");
  expectRefused(file("b.csv", good + "3,10,20,1,2\n"), "b.csv:27: duplicate mark id 3 (first on line 4)");
  expectRefused(file("c.csv", good + "99,10,abc,1,2\n"), "c.csv:27: theta2_deg is not a number: \"abc\"");
  expectRefused(file("d.csv", good + "98,10,20,1\n"), "d.csv:27: missing field y_mm");
  expectRefused(file("e.csv", "id,theta1_deg,theta2_deg,x_mm,y_mm\n1,100,80,0,0\n2,101,80,1,0\n"),
                "no profile written: 2 marks are too few for 10 parameters");
  expectRefused(file("f.csv", ""), "f.csv: the file is empty");
  expectRefused(path("missing.csv"), "cannot open");
}

TEST_F(CalibrateCli, IllConditionedMarksAreRefused) {
  auto marks = test::measuredMarks(nominal(), test::seed(), false);
  // Every mark drawn at nearly the same pose.
  std::vector<calibration::MarkMeasurement> clustered;
  for (int i = 0; i < 12; ++i) {
    calibration::MarkMeasurement m = marks[12];
    m.id = std::string(1, 'c').append(std::to_string(i));
    m.commanded.theta1 += 1e-3 * std::cos(i);
    m.commanded.theta2 += 1e-3 * std::sin(2 * i);
    m.paperMm = *calibration::penPosition(test::trueMakerPlotter(), nominal().assembly, m.commanded);
    clustered.push_back(m);
  }
  expectRefused(file("g.csv", csvOf(clustered)), "ill-conditioned");
}

TEST_F(CalibrateCli, UsageErrors) {
  EXPECT_EQ(run({}).exitCode, 2);
  EXPECT_EQ(run({"nope"}).exitCode, 2);
  const CliResult r = run({"fit", "--machine", "maker-plotter"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("missing required option --measured"), std::string::npos) << r.err;
  EXPECT_EQ(run({"fit", "--help"}).exitCode, 0);
}

}  // namespace
}  // namespace fivebar
