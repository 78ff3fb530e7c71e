// `fivebar plan` with SVG import: warnings on stderr (exit status unchanged), the point budget,
// and --fill hatch (app/cli/plan_import_options.cpp). Runs the built binary.
#include <gtest/gtest.h>

#include <sys/wait.h>

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

}  // namespace
