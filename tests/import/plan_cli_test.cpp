// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar plan` with SVG import: warnings on stderr (exit status unchanged), the point budget,
// and --fill hatch (app/cli/plan_import_options.cpp). Runs the built binary.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct PlanRun {
  int exitCode = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class PlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-plan-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  PlanRun plan(const fs::path& svg, const std::string& extra) {
    const std::string cmd = std::string("QT_QPA_PLATFORM=offscreen '") + FIVEBAR_CLI + "' plan '" +
                            svg.string() + "' --machine maker-plotter -o '" + (dir_ / "job.gcode").string() +
                            "' " + extra + " >'" + (dir_ / "out").string() + "' 2>'" + (dir_ / "err").string() + "'";
    const int status = std::system(cmd.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out"), slurp(dir_ / "err")};
  }
  fs::path dir_;
};

std::string doc(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40mm\" height=\"40mm\" viewBox=\"0 0 40 40\">\n" +
         body + "</svg>\n";
}

double penDownMm(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("pen down (\\d+) mm"))) return -1.0;
  return std::stod(m[1]);
}

TEST_F(PlanCli, ImportWarningsGoToStderrWithFileLineElementAndTheExitStaysZero) {
  const fs::path svg = write("warn.svg", doc("<path id=\"bad\" d=\"M5 5 L35 5 L35 q\" stroke=\"black\" fill=\"none\"/>\n"
                                              "<image href=\"x.png\" width=\"5\" height=\"5\"/>\n"));
  const PlanRun r = plan(svg, "");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("fivebar plan: " + svg.string() +
                       ": warning: line 2: <path id=\"bad\"> attribute d: invalid path data"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(": warning: <image> element removed (1x, first at line 3)"), std::string::npos) << r.err;
  // Printed once, although the drawing is imported twice when the fit enlarges it.
  EXPECT_EQ(r.err.find("invalid path data"), r.err.rfind("invalid path data")) << r.err;
}

TEST_F(PlanCli, ThePointBudgetStopsRunawayDrawingsUnlessRaised) {
  const fs::path svg = write("circle.svg", doc("<circle cx=\"20\" cy=\"20\" r=\"15\" stroke=\"black\" fill=\"none\"/>"));
  const PlanRun small = plan(svg, "--max-points 20");
  EXPECT_EQ(small.exitCode, 1);
  // The import itself stops at the budget (the file is not flattened whole first).
  EXPECT_NE(small.err.find("more than 20 points after flattening (the points budget): reading stopped there"),
            std::string::npos) << small.err;
  EXPECT_NE(small.err.find("Raise it with --max-points"), std::string::npos) << small.err;
  EXPECT_FALSE(fs::exists(dir_ / "job.gcode"));
  EXPECT_EQ(plan(svg, "").exitCode, 0);
  EXPECT_EQ(plan(svg, "--max-points 0").exitCode, 2);
}

TEST_F(PlanCli, HatchFillDrawsTheLinesTheAreaNeeds) {
  const fs::path svg = write("square.svg", doc("<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"black\"/>"));
  const PlanRun outline = plan(svg, "");
  ASSERT_EQ(outline.exitCode, 0) << outline.err;
  const PlanRun hatch = plan(svg, "--fill hatch --hatch-spacing 1 --hatch-angle 0");
  ASSERT_EQ(hatch.exitCode, 0) << hatch.err;
  // Outline 80 mm; hatch adds 20 lines of 20 mm and 19 joins of 1 mm: (80 + 419) / 80.
  const double ratio = penDownMm(hatch.out) / penDownMm(outline.out);
  EXPECT_NEAR(ratio, 499.0 / 80.0, 0.02 * 499.0 / 80.0) << outline.out << hatch.out;
  const PlanRun bad = plan(svg, "--fill solid");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--fill must be outline, hatch or none, got 'solid'"), std::string::npos) << bad.err;
  EXPECT_EQ(plan(svg, "--hatch-spacing 1").exitCode, 2);  // needs --fill hatch
}

// A 30 mm line dashed "4 2": five dashes of 4 mm (20 mm drawn); --dashes solid draws all 30 mm.
TEST_F(PlanCli, DashesAreDrawnAsDashesUnlessSolidIsAsked) {
  const fs::path svg = write("dashed.svg", doc("<path d=\"M5 20 L35 20\" stroke=\"black\" fill=\"none\" "
                                                "stroke-dasharray=\"4 2\"/>"));
  const PlanRun dashed = plan(svg, "");
  ASSERT_EQ(dashed.exitCode, 0) << dashed.err;
  EXPECT_NEAR(penDownMm(dashed.out), 20.0, 1.0) << dashed.out;
  const PlanRun solid = plan(svg, "--dashes solid");
  ASSERT_EQ(solid.exitCode, 0) << solid.err;
  EXPECT_NEAR(penDownMm(solid.out), 30.0, 1.0) << solid.out;
  const PlanRun bad = plan(svg, "--dashes dotted");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--dashes must be dashed or solid, got 'dotted'"), std::string::npos) << bad.err;
}

double scalePercent(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("scale ([0-9.]+) %"))) return -1.0;
  return std::stod(m[1]);
}

// True size by default; --fit enlarges to the largest singularity-free rectangle; a drawing too
// big is scaled down to that same rectangle and says so on stderr (only then). Numbers are
// checked against each other, not against fixed figures.
TEST_F(PlanCli, TrueSizeByDefaultFitOnRequestScaledDownWithANote) {
  const std::string square = "<rect x=\"2\" y=\"2\" width=\"36\" height=\"36\" stroke=\"black\" fill=\"none\"/>";
  const fs::path small = write("small.svg", doc(square));
  std::string big = doc(square);
  big.replace(big.find("width=\"40mm\" height=\"40mm\""), 26, "width=\"1000mm\" height=\"1000mm\"");
  const fs::path large = write("large.svg", big);

  const PlanRun trueSize = plan(small, "");
  ASSERT_EQ(trueSize.exitCode, 0) << trueSize.err;
  EXPECT_DOUBLE_EQ(scalePercent(trueSize.out), 100.0) << trueSize.out;
  EXPECT_NEAR(penDownMm(trueSize.out), 4 * 36.0, 1.0) << trueSize.out;  // drawn at its own size
  EXPECT_EQ(trueSize.err.find("scaled to"), std::string::npos) << trueSize.err;

  const PlanRun fitted = plan(small, "--fit");
  ASSERT_EQ(fitted.exitCode, 0) << fitted.err;
  EXPECT_GT(scalePercent(fitted.out), 150.0) << fitted.out;  // enlarged only on request
  EXPECT_EQ(fitted.err.find("scaled to"), std::string::npos) << fitted.err;

  const PlanRun shrunk = plan(large, "");
  ASSERT_EQ(shrunk.exitCode, 0) << shrunk.err;
  const double percent = scalePercent(shrunk.out);
  EXPECT_LT(percent, 100.0) << shrunk.out;
  const std::string note = "fivebar plan: " + large.string() + ": scaled to " +
                           std::to_string(static_cast<int>(std::lround(percent))) + " % to fit the workspace";
  EXPECT_NE(shrunk.err.find(note), std::string::npos) << shrunk.err;
  // The same rectangle as --fit: the same drawn length.
  EXPECT_NEAR(penDownMm(shrunk.out), penDownMm(fitted.out), 1.0) << shrunk.out << fitted.out;
  // --fit on the big drawing also fits it (no note: the user asked for it).
  const PlanRun bigFit = plan(large, "--fit");
  ASSERT_EQ(bigFit.exitCode, 0) << bigFit.err;
  EXPECT_NEAR(penDownMm(bigFit.out), penDownMm(fitted.out), 1.0) << bigFit.out;
  EXPECT_EQ(bigFit.err.find("scaled to"), std::string::npos) << bigFit.err;
}

}  // namespace
