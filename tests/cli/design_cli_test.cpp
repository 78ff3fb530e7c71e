// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar design` end to end: the issue's brief, the JSON and profile files, an impossible
// brief, usage errors and --machine evaluation.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using cli_test::quote;
using cli_test::slurp;
using cli_test::CliResult;

class DesignCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-design-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
  }
  void TearDown() override { fs::remove_all(dir_); }
  CliResult run(const std::vector<std::string>& args) {
    std::string cmd = quote(FIVEBAR_CLI) + " design";
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd += " </dev/null >" + quote((dir_ / "out").string()) + " 2>" + quote((dir_ / "err").string());
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir_ / "out");
    r.err = slurp(dir_ / "err");
    return r;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  fs::path dir_;
};

TEST_F(DesignCli, GoalBriefWritesJsonAndProfile) {
  const CliResult r = run({"--rect", "110x90", "--max-link", "200", "--max-base", "250", "--clearance", "10",
                     "--type2-margin", "15", "--json", path("d.json"), "--profile-out", path("p.json")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(path("d.json")));
  for (const char* k : {"a1", "b1", "a2", "b2", "w"}) EXPECT_TRUE(j["geometry"][k].is_number()) << k;
  const auto g = j["geometry"];
  EXPECT_LE(g["b1"].get<double>(), 200.0);
  EXPECT_LE(g["w"].get<double>(), 250.0);
  EXPECT_GE(g["w"].get<double>(), g["a1"].get<double>() + g["a2"].get<double>() + 10.0 - 1e-9);
  EXPECT_TRUE(parseWorkingMode(j["workingMode"].get<std::string>()));
  const auto rect = j["rectangle"];
  EXPECT_NEAR(rect["xMaxMm"].get<double>() - rect["xMinMm"].get<double>(), 110.0, 1e-6);
  EXPECT_NEAR(rect["yMaxMm"].get<double>() - rect["yMinMm"].get<double>(), 90.0, 1e-6);
  EXPECT_LE(j["measures"]["worstConditionNumber"].get<double>(), 2.2);
  EXPECT_GE(j["measures"]["typeIIMarginDeg"].get<double>(), 15.0);
  EXPECT_FALSE(j["measures"]["armsCanCollide"].get<bool>());
  EXPECT_GE(j["pareto"]["designs"].size(), 2u);
  EXPECT_TRUE(j["found"].get<bool>());
  const ProfileLoad p = loadProfile(path("p.json"));
  ASSERT_TRUE(p.profile) << (p.issues.empty() ? "" : p.issues[0].message);
  EXPECT_DOUBLE_EQ(p.profile->geometry.a1, g["a1"].get<double>());
  EXPECT_NE(r.out.find("worst condition number"), std::string::npos) << r.out;
}

TEST_F(DesignCli, ImpossibleBriefSaysWhichConstraintBinds) {
  const CliResult r = run({"--rect", "400x300", "--max-link", "100", "--mode", "++"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no design meets the brief"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("reach binds"), std::string::npos) << r.err;
  const CliResult c = run({"--rect", "100x80", "--min-link", "120", "--max-base", "200"});
  EXPECT_EQ(c.exitCode, 1);
  EXPECT_NE(c.err.find("clearance binds"), std::string::npos) << c.err;
}

TEST_F(DesignCli, BadOptionsAreUsageErrors) {
  CliResult r = run({"--rect", "110by90"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--rect must be WxH"), std::string::npos) << r.err;
  r = run({"--rect", "110x90", "--objective", "speed"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--objective must be"), std::string::npos) << r.err;
  r = run({"--rect", "110x90", "--min-link", "150", "--max-link", "100"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("shortest link"), std::string::npos) << r.err;
  r = run({"--max-link", "100"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--rect"), std::string::npos) << r.err;
}

TEST_F(DesignCli, MachineEvaluatesHoang2015) {
  const CliResult r = run({"--rect", "110x90", "--machine", "hoang2015", "--json", path("h.json")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(path("h.json")));
  EXPECT_EQ(j["geometry"]["a1"].get<double>(), 70.0);
  const double kappa = j["measures"]["worstConditionNumber"].get<double>();
  EXPECT_GT(kappa, 6.0);
  EXPECT_LE(kappa, 12.1);
}

TEST_F(DesignCli, MixObjectiveWithWeights) {
  const CliResult r = run({"--rect", "110x90", "--mode", "+-", "--objective", "mix", "--weights", "1,0,0.5",
                           "--json", path("m.json")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(path("m.json")));
  EXPECT_EQ(j["objective"], "mix");
  EXPECT_EQ(j["weights"]["condition"].get<double>(), 1.0);
  EXPECT_EQ(j["weights"]["resolution"].get<double>(), 0.0);
  EXPECT_EQ(j["weights"]["footprint"].get<double>(), 0.5);
  EXPECT_GE(j["measures"]["normalisedFootprint"].get<double>(), 1.0);
  EXPECT_FALSE(j["rectangleRotated"].get<bool>());
  EXPECT_NE(r.out.find("objective mix (weights 1.00,0.00,0.50)"), std::string::npos) << r.out;
  CliResult e = run({"--rect", "110x90", "--objective", "mix", "--weights", "1,0"});
  EXPECT_EQ(e.exitCode, 2);
  EXPECT_NE(e.err.find("--weights must be C,R,F"), std::string::npos) << e.err;
  e = run({"--rect", "110x90", "--objective", "mix", "--weights", "0,0,0"});
  EXPECT_EQ(e.exitCode, 2);
  EXPECT_NE(e.err.find("not all be zero"), std::string::npos) << e.err;
  e = run({"--rect", "110x90", "--objective", "mix", "--weights", "1,-2,0"});
  EXPECT_EQ(e.exitCode, 2);
  e = run({"--rect", "110x90", "--weights", "1,0,0"});
  EXPECT_EQ(e.exitCode, 2);
  EXPECT_NE(e.err.find("--weights needs --objective mix"), std::string::npos) << e.err;
}

// A tall rectangle on Hoang's wide machine: turned, it fits better; the bounds in the machine
// frame are the turned ones.
TEST_F(DesignCli, AllowRotationTurnsTheRectangle) {
  const CliResult plain = run({"--rect", "40x100", "--machine", "hoang2015", "--json", path("p.json")});
  const CliResult turned =
      run({"--rect", "40x100", "--machine", "hoang2015", "--allow-rotation", "--json", path("t.json")});
  ASSERT_EQ(turned.exitCode, 0) << turned.err;
  const nlohmann::json p = nlohmann::json::parse(slurp(path("p.json")));
  const nlohmann::json t = nlohmann::json::parse(slurp(path("t.json")));
  EXPECT_FALSE(p["rectangleRotated"].get<bool>());
  EXPECT_NEAR(p["rectangle"]["xMaxMm"].get<double>() - p["rectangle"]["xMinMm"].get<double>(), 40.0, 1e-6);
  ASSERT_TRUE(t["rectangleRotated"].get<bool>());
  EXPECT_NEAR(t["rectangle"]["xMaxMm"].get<double>() - t["rectangle"]["xMinMm"].get<double>(), 100.0, 1e-6);
  EXPECT_NEAR(t["rectangle"]["yMaxMm"].get<double>() - t["rectangle"]["yMinMm"].get<double>(), 40.0, 1e-6);
  EXPECT_TRUE(t["feasible"].get<bool>());
  EXPECT_LT(t["measures"]["worstConditionNumber"].get<double>(), p["measures"]["worstConditionNumber"].get<double>());
  EXPECT_NE(turned.out.find("(turned)"), std::string::npos) << turned.out;
}

#ifdef FIVEBAR_CLI_HAS_PNG
TEST_F(DesignCli, AtlasPngIsWritten) {
  const CliResult r = run({"--rect", "110x90", "--machine", "hoang2015", "--png", path("a.png")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string png = slurp(path("a.png"));
  ASSERT_GT(png.size(), 10000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}
#endif

}  // namespace
}  // namespace fivebar
