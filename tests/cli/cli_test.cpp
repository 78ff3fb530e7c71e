// SPDX-License-Identifier: GPL-3.0-or-later
// The fivebar CLI end to end: runs the built binary with stdin/stdout/stderr in temporary files.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>

#include "cli_support.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/kinematics/singularity.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using cli_test::quote;
using cli_test::slurp;

struct CliRun {
  int exitCode = -1;
  std::string out, err;
  std::vector<std::string> lines() const {
    std::vector<std::string> v;
    std::istringstream in(out);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
  }
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-cli-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `fivebar args...` with `input` on stdin.
  CliRun run(const std::vector<std::string>& args, const std::string& input = "") {
    std::ofstream(dir_ / "stdin") << input;
    std::string cmd = quote(FIVEBAR_CLI);
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd += " <" + quote((dir_ / "stdin").string()) + " >" + quote((dir_ / "stdout").string()) +
           " 2>" + quote((dir_ / "stderr").string());
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir_ / "stdout");
    r.err = slurp(dir_ / "stderr");
    return r;
  }
  fs::path path(const std::string& name) const { return dir_ / name; }

 private:
  fs::path dir_;
};

std::pair<double, double> parsePair(const std::string& line) {
  const auto comma = line.find(',');
  return {std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1))};
}

const std::regex kNineDecimals(R"(^-?\d+\.\d{9},-?\d+\.\d{9}$)");

// A machine with asymmetric links, saved as a profile file: exercises --machine FILE.
MachineProfile asymmetricProfile() {
  MachineProfile p = *preset("maker-plotter");
  p.name = "asymmetric";
  p.geometry = {60.0, 150.0, 80.0, 170.0, 90.0};
  p.limits = JointLimits{};
  p.homeAngles = {0.0, 0.0};
  return p;
}

TEST_F(Cli, IkThenFkReturnsThePointsInEveryMode) {
  const MachineProfile p = asymmetricProfile();
  const std::string file = path("asym.json").string();
  ASSERT_EQ(saveProfile(p, file), "");
  auto rng = test::rng();
  std::uniform_real_distribution<double> ux(-150, 150), uy(20, 230);
  for (WorkingMode mode : kAllWorkingModes) {
    // Well-conditioned points of this mode, each with its assembly mode from the core.
    std::vector<Vec2> points[2];
    while (points[0].size() + points[1].size() < 120) {
      const Vec2 q(ux(rng), uy(rng));
      const IkResult ik = inverse(p.geometry, q, mode);
      if (!ik.ok()) continue;
      const Pose pose = makePose(p.geometry, ik.angles, q);
      if (singularityMargins(p.geometry, pose).typeII < radFromDeg(5)) continue;
      points[assemblyModeOf(pose) == AssemblyMode::Plus ? 0 : 1].push_back(q);
    }
    for (int a = 0; a < 2; ++a) {
      if (points[a].empty()) continue;
      std::string in;
      char buf[128];
      for (const Vec2& q : points[a]) {
        std::snprintf(buf, sizeof buf, "%.12f,%.12f\n", q.x(), q.y());
        in += buf;
      }
      const CliRun ik = run({"ik", "--machine", file, "--mode", std::string(toString(mode))}, in);
      ASSERT_EQ(ik.exitCode, 0) << ik.err;
      const auto angles = ik.lines();
      ASSERT_EQ(angles.size(), points[a].size());
      for (const std::string& line : angles) {
        ASSERT_TRUE(std::regex_match(line, kNineDecimals)) << line;
        const auto [t1, t2] = parsePair(line);
        EXPECT_TRUE(t1 > -180.0 && t1 <= 180.0 && t2 > -180.0 && t2 <= 180.0) << line;
      }
      const CliRun fk = run({"fk", "--machine", file, "--assembly", a == 0 ? "+" : "-"}, ik.out);
      ASSERT_EQ(fk.exitCode, 0) << fk.err;
      const auto xy = fk.lines();
      ASSERT_EQ(xy.size(), points[a].size());
      for (std::size_t i = 0; i < xy.size(); ++i) {
        ASSERT_TRUE(std::regex_match(xy[i], kNineDecimals)) << xy[i];
        const auto [x, y] = parsePair(xy[i]);
        EXPECT_NEAR(x, points[a][i].x(), 1e-6) << toString(mode) << " line " << i;
        EXPECT_NEAR(y, points[a][i].y(), 1e-6) << toString(mode) << " line " << i;
      }
    }
  }
}

// A calibrated pen offset: ik puts the pen (not P) on the point, fk returns the pen.
TEST_F(Cli, IkAndFkHonourTheCalibratedPenOffset) {
  MachineProfile p = *preset("maker-plotter");
  p.calibration.emplace();
  p.calibration->penOffset = PenOffset{5.0, -3.0};
  const std::string file = path("pen.json").string();
  ASSERT_EQ(saveProfile(p, file), "");
  const std::vector<Vec2> points{Vec2(-30, 150), Vec2(20, 190), Vec2(45, 130)};
  std::string in;
  for (const Vec2& q : points) in += std::to_string(q.x()) + "," + std::to_string(q.y()) + "\n";
  const CliRun ik = run({"ik", "--machine", file}, in);
  ASSERT_EQ(ik.exitCode, 0) << ik.err;
  const auto angles = ik.lines();
  ASSERT_EQ(angles.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [t1, t2] = parsePair(angles[i]);
    const IkResult core = penInverse(p, points[i], p.defaultMode);
    ASSERT_TRUE(core.ok());
    EXPECT_NEAR(t1, degFromRad(core.angles.theta1), 1e-8) << i;
    EXPECT_NEAR(t2, degFromRad(core.angles.theta2), 1e-8) << i;
    // P's angles differ by far more than the printed precision.
    const IkResult atP = inverse(p.geometry, points[i], p.defaultMode);
    EXPECT_GT(std::abs(t1 - degFromRad(atP.angles.theta1)) + std::abs(t2 - degFromRad(atP.angles.theta2)), 0.5) << i;
  }
  const CliRun fk = run({"fk", "--machine", file}, ik.out);
  ASSERT_EQ(fk.exitCode, 0) << fk.err;
  const auto xy = fk.lines();
  ASSERT_EQ(xy.size(), points.size());
  for (std::size_t i = 0; i < xy.size(); ++i) {
    const auto [x, y] = parsePair(xy[i]);
    EXPECT_NEAR(x, points[i].x(), 1e-6) << i;
    EXPECT_NEAR(y, points[i].y(), 1e-6) << i;
  }
}

TEST_F(Cli, IkAnglesAreNormalisedAndMatchTheCore) {
  // theta1 = 180 deg exactly: the output must read 180, never -180.
  const Geometry g = preset("hoang2015")->geometry;
  const FkResult fk = forward(g, {kPi, radFromDeg(60.0)}, AssemblyMode::Plus);
  ASSERT_TRUE(fk.ok());
  char line[128];
  std::snprintf(line, sizeof line, "%.15f,%.15f\n", fk.p.x(), fk.p.y());
  const Pose pose = makePose(g, {kPi, radFromDeg(60.0)}, fk.p);
  const WorkingMode mode = workingModeOf(g, pose);
  const CliRun r = run({"ik", "--machine", "hoang2015", "--mode", std::string(toString(mode))}, line);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto [t1, t2] = parsePair(r.lines().at(0));
  EXPECT_NEAR(t1, 180.0, 1e-7) << r.out;
  EXPECT_NEAR(t2, 60.0, 1e-7) << r.out;
  EXPECT_EQ(r.out.find("-180"), std::string::npos) << r.out;
}

TEST_F(Cli, UnreachableInputsSayUnreachable) {
  const CliRun ik = run({"ik", "--machine", "hoang2015", "--mode", "++"}, "1000,0\n0,150\n0,0\n");
  ASSERT_EQ(ik.exitCode, 0) << ik.err;
  const auto lines = ik.lines();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "unreachable");
  EXPECT_TRUE(std::regex_match(lines[1], kNineDecimals)) << lines[1];
  EXPECT_EQ(lines[2], "unreachable");  // |P - Mi| = 125 < |a - b| = 130
  // dai2022 with both arms pointing outward: the elbows are 450 mm apart, b1 + b2 = 270.
  const CliRun fk = run({"fk", "--machine", "dai2022"}, "180,0\n90,90\n");
  ASSERT_EQ(fk.exitCode, 0) << fk.err;
  EXPECT_EQ(fk.lines().at(0), "unreachable");
  EXPECT_TRUE(std::regex_match(fk.lines().at(1), kNineDecimals));
}

TEST_F(Cli, MalformedLinesNameTheLineNumber) {
  const CliRun r = run({"ik", "--machine", "hoang2015"}, "0,150\n\n0;150\n");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("stdin line 2: expected x,y"), std::string::npos) << r.err;
  EXPECT_EQ(r.lines().size(), 1u);  // the good line before it was answered
  const CliRun fk = run({"fk", "--machine", "hoang2015"}, "90,90\n90,abc\n");
  EXPECT_EQ(fk.exitCode, 1);
  EXPECT_NE(fk.err.find("stdin line 2: expected theta1,theta2"), std::string::npos) << fk.err;
  const CliRun inf = run({"ik", "--machine", "hoang2015"}, "nan,1\n");
  EXPECT_NE(inf.err.find("stdin line 1"), std::string::npos) << inf.err;
}

TEST_F(Cli, BadOptionsAndMachinesAreNamed) {
  const CliRun unknown = run({"ik", "--machine", "hoang2016"});
  EXPECT_NE(unknown.exitCode, 0);
  EXPECT_NE(unknown.err.find("hoang2016"), std::string::npos) << unknown.err;
  for (const std::string& n : presetNames()) EXPECT_NE(unknown.err.find(n), std::string::npos);
  const CliRun option = run({"fk", "--machine", "dai2022", "--speed", "3"});
  EXPECT_EQ(option.exitCode, 2);
  EXPECT_NE(option.err.find("unknown option --speed"), std::string::npos) << option.err;
  const CliRun mode = run({"ik", "--machine", "dai2022", "--mode", "+*"});
  EXPECT_EQ(mode.exitCode, 2);
  EXPECT_NE(mode.err.find("'+*'"), std::string::npos) << mode.err;
  const CliRun missing = run({"ik"});
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find("--machine"), std::string::npos) << missing.err;
  const CliRun noFile = run({"fk", "--machine", path("none.json").string()});
  EXPECT_EQ(noFile.exitCode, 1);
  EXPECT_NE(noFile.err.find("none.json"), std::string::npos) << noFile.err;
  // A number option takes the whole text: "10s" is not 10 (refused before any port is opened).
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"send", "--timeout", "10s", "?"},
        std::vector<std::string>{"reference", "--machine", "maker-plotter", "--timeout", "10s"}}) {
    std::vector<std::string> withPort = args;
    withPort.insert(withPort.begin() + 1, {"--port", path("no-port").string()});
    const std::string command = args.front();
    const CliRun timeout = run(withPort);
    EXPECT_EQ(timeout.exitCode, 2) << command << ": " << timeout.err;
    EXPECT_NE(timeout.err.find("--timeout needs a positive number, got '10s'"), std::string::npos)
        << command << ": " << timeout.err;
  }
}

TEST_F(Cli, ProfileCheckReportsEachIssueWithFileAndField) {
  nlohmann::json j = nlohmann::json::parse(toJson(*preset("hoang2015")));
  j["geometry"]["a1"] = -3;
  j["motors"]["stepsPerDegree1"] = 10;
  const std::string bad = path("bad.json").string();
  std::ofstream(bad) << j.dump(2);
  const CliRun r = run({"profile", "check", bad});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.out.find(bad + ": geometry.a1: geometry.a1 must be positive, got -3"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find(bad + ": motors.stepsPerDegree1:"), std::string::npos) << r.out;

  const std::string broken = path("broken.json").string();
  std::ofstream(broken) << "{\n  \"schema\": \"fivebar-profile\"\n  \"version\": 1\n}\n";
  const CliRun b = run({"profile", "check", broken});
  EXPECT_EQ(b.exitCode, 1);
  EXPECT_NE(b.out.find(broken + ":3:"), std::string::npos) << b.out;

  const CliRun shown = run({"profile", "show", "dai2022"});
  ASSERT_EQ(shown.exitCode, 0) << shown.err;
  const std::string good = path("good.json").string();
  std::ofstream(good) << shown.out;
  const CliRun ok = run({"profile", "check", good});
  EXPECT_EQ(ok.exitCode, 0) << ok.out;
  EXPECT_EQ(nlohmann::json::parse(shown.out)["geometry"]["a1"], 135.0);
  const CliRun sub = run({"profile", "frobnicate"});
  EXPECT_EQ(sub.exitCode, 2);
  EXPECT_NE(sub.err.find("frobnicate"), std::string::npos) << sub.err;
}

TEST_F(Cli, WorkspaceReportsAreasAndRectangle) {
  const std::string json = path("ws.json").string();
  const CliRun r = run({"workspace", "--machine", "hoang2015", "--mode", "++", "--cells", "200",
                     "--aspect", "110:90", "--json", json});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("reachable area:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("largest rectangle:"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(j["workingMode"], "++");
  EXPECT_GT(j["reachableAreaMm2"].get<double>(), 0.0);
  EXPECT_LE(j["singularityFreeAreaMm2"].get<double>(), j["reachableAreaMm2"].get<double>());
  EXPECT_GE(j["largestRectangle"]["widthMm"].get<double>(), 110.0);
  EXPECT_GE(j["largestRectangle"]["heightMm"].get<double>(), 90.0);
  const CliRun bad = run({"workspace", "--machine", "hoang2015", "--cells", "ten"});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--cells"), std::string::npos) << bad.err;
}

TEST_F(Cli, WorkspacePngIsWrittenOrExplainedUnavailable) {
  const std::string png = path("ws.png").string();
  const CliRun r = run({"workspace", "--machine", "article5r", "--cells", "128", "--png", png});
#ifdef FIVEBAR_CLI_HAS_PNG
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string bytes = slurp(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
#else
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--png is unavailable"), std::string::npos) << r.err;
#endif
}

}  // namespace
}  // namespace fivebar
