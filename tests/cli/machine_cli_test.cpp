// SPDX-License-Identifier: GPL-3.0-or-later
// The machine commands end to end against fivebar-sim on a pseudo-terminal: send / stream refuse
// what the motion check refuses (nothing reaches the board), reference and home.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "cli_support.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using cli_test::quote;
using cli_test::slurp;
using cli_test::CliResult;

std::string deg3(double rad) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", degFromRad(rad));
  return buf;
}

class MachineCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "fivebar-mcli-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
    profile_ = *preset("maker-plotter");
    // Where this computer remembers each board's position (drivers/protocol/pose_trust.hpp): the test's own.
    ::setenv("FIVEBAR_STATE_DIR", (dir_ / "state").c_str(), 1);
  }
  void TearDown() override {
    stopSim();
    fs::remove_all(dir_);
  }
  // Starts fivebar-sim (instant moves) with extra options; false when its pty did not appear.
  bool startSim(std::vector<std::string> extra) {
    pty_ = (dir_ / "tty").string();
    std::vector<std::string> args{FIVEBAR_SIM_EXE, "--pty", pty_, "--machine", "maker-plotter", "--instant"};
    args.insert(args.end(), extra.begin(), extra.end());
    pid_ = ::fork();
    if (pid_ == 0) {
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      if (!std::freopen("/dev/null", "w", stderr)) ::_exit(127);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    for (int i = 0; i < 250 && !fs::exists(pty_); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (!fs::exists(pty_)) return false;
    // A referenced board is one this computer knows: the maker confirmed its pose once.
    if (std::find(extra.begin(), extra.end(), "--referenced") != extra.end())
      return run({"reference", "--port", pty_, "--machine", "maker-plotter", "--yes"}).exitCode == 0;
    return true;
  }
  void stopSim() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  CliResult run(const std::vector<std::string>& args, const std::string& input = "") {
    std::ofstream(dir_ / "stdin") << input;
    std::string cmd = quote(FIVEBAR_CLI);
    for (const std::string& a : args) cmd.append(" ").append(quote(a));
    cmd += " <" + quote((dir_ / "stdin").string()) + " >" + quote((dir_ / "stdout").string()) + " 2>" +
           quote((dir_ / "stderr").string());
    const int status = std::system(cmd.c_str());
    return CliResult{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "stdout"), slurp(dir_ / "stderr")};
  }
  // The board's status report, asked without a machine (a '?' moves nothing).
  std::string status() { return run({"send", "--port", pty_, "?"}).out; }
  // MPos X and Y (deg) of a fresh status report; NaN when there is none.
  std::array<double, 2> mpos() {
    const std::string s = status();
    const size_t at = s.find("MPos:");
    double x = NAN, y = NAN;
    if (at != std::string::npos) std::sscanf(s.c_str() + at + 5, "%lf,%lf", &x, &y);
    return {x, y};
  }
  double step() const { return 1.0 / profile_.motors.stepsPerDeg1; }
  std::string writeJob(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  std::string homeX() const { return deg3(profile_.homeAngles.theta1); }
  std::string homeY() const { return deg3(profile_.homeAngles.theta2); }

  fs::path dir_;
  std::string pty_;
  pid_t pid_ = -1;
  MachineProfile profile_;
};

TEST_F(MachineCli, SendWithoutMachineRefusesMotionAndPassesTheRest) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  const CliResult moved = run({"send", "--port", pty_, "G0X" + homeX() + "Y40"});
  EXPECT_EQ(moved.exitCode, 1);
  EXPECT_NE(moved.err.find("--machine"), std::string::npos) << moved.err;
  const CliResult info = run({"send", "--port", pty_, "$I"});
  EXPECT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.out.find("[VER:1.1h.20190830:]"), std::string::npos) << info.out;
  EXPECT_NE(status().find("MPos:0.000,0.000,0.000"), std::string::npos) << "nothing moved";
}

TEST_F(MachineCli, SendChecksEveryMotionLineFromTheBoardsPose) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  const double beyond = degFromRad(profile_.limits.theta1Max) + 20.0;
  const CliResult far = run({"send", "--port", pty_, "--machine", "maker-plotter", "G1X" + std::to_string(beyond) + "F600"});
  EXPECT_EQ(far.exitCode, 1);
  EXPECT_NE(far.err.find("not sent"), std::string::npos) << far.err;
  const CliResult arc = run({"send", "--port", pty_, "--machine", "maker-plotter", "G2X1Y1I1F100"});
  EXPECT_EQ(arc.exitCode, 1);
  EXPECT_NE(arc.err.find("G2/G3"), std::string::npos) << arc.err;
  const CliResult offset = run({"send", "--port", pty_, "--machine", "maker-plotter", "G92X0Y0"});
  EXPECT_EQ(offset.exitCode, 1);
  EXPECT_NE(offset.err.find("fivebar reference"), std::string::npos) << offset.err;
  EXPECT_NE(status().find("MPos:0.000,0.000,0.000"), std::string::npos) << "nothing moved";
  // A safe move passes, and the next line is checked from where it ends.
  const std::string x2 = deg3(profile_.homeAngles.theta1 + radFromDeg(2.0));
  const CliResult safe = run({"send", "--port", pty_, "--machine", "maker-plotter", "G0X" + x2 + "Y" + homeY(), "G91", "G0X1"});
  EXPECT_EQ(safe.exitCode, 0) << safe.err;
  EXPECT_NEAR(mpos()[0], 3.0, step());
  const CliResult expert = run({"send", "--port", pty_, "--unchecked", "--timeout", "0.5", "G90"});
  EXPECT_NE(expert.err.find("WITHOUT the safety check"), std::string::npos) << expert.err;
  EXPECT_NE(run({"send", "--help"}).out.find("What is checked"), std::string::npos);
}

TEST_F(MachineCli, ReferenceThenHomeByACheckedMove) {
  ASSERT_TRUE(startSim({"--set-up"}));  // powered up at the home pose, no reference yet
  const CliResult asked = run({"reference", "--port", pty_, "--machine", "maker-plotter"}, "n\n");
  EXPECT_EQ(asked.exitCode, 1);
  EXPECT_NE(asked.err.find("not confirmed"), std::string::npos) << asked.err;
  const CliResult ref = run({"reference", "--port", pty_, "--machine", "maker-plotter", "--yes"});
  ASSERT_EQ(ref.exitCode, 0) << ref.err;
  EXPECT_NE(ref.out.find("reference set"), std::string::npos) << ref.out;
  // Away from home by a checked move, then home: a checked pen-up travel back.
  const std::string x = deg3(profile_.homeAngles.theta1 + radFromDeg(5.0));
  ASSERT_EQ(run({"send", "--port", pty_, "--machine", "maker-plotter", "G0X" + x + "Y" + homeY()}).exitCode, 0);
  const CliResult home = run({"home", "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(home.exitCode, 0) << home.err;
  EXPECT_NE(home.out.find("at the home pose"), std::string::npos) << home.out;
  EXPECT_NEAR(mpos()[0], 0.0, step());
  EXPECT_NEAR(mpos()[1], 0.0, step());
}

TEST_F(MachineCli, HomeRefusesAnUnreferencedBoardWhosePoseIsUnsafe) {
  ASSERT_TRUE(startSim({"--set-up"}));
  // Work X/Y 0,0: a board fresh from power-up. Either refused as unsafe or no safe travel.
  const CliResult home = run({"home", "--port", pty_, "--machine", "maker-plotter"});
  if (home.exitCode != 0) {
    EXPECT_NE(home.err.find("fivebar"), std::string::npos) << home.err;
  }
  EXPECT_NE(run({"home", "--help"}).out.find("checked"), std::string::npos);
}

// fivebar frame: the job's outline traced pen up by checked moves from the board's known pose,
// ending at its first corner (the hull point with the lowest x); refused while the pose is unknown.
TEST_F(MachineCli, FrameTracesTheJobsOutlinePenUpFromAKnownPose) {
  const fs::path drawn = dir_ / "drawn.csv";
  ASSERT_TRUE(startSim({"--set-up", "--drawn", drawn.string()}));
  const double h1 = degFromRad(profile_.homeAngles.theta1), h2 = degFromRad(profile_.homeAngles.theta2);
  const std::array<std::array<double, 2>, 3> cornersDeg{{{h1 + 2, h2}, {h1 + 6, h2 + 1}, {h1 + 4, h2 + 5}}};
  std::string text = "; profile: maker-plotter\nG21 G90\n";
  char line[96];
  std::snprintf(line, sizeof line, "G0X%.3fY%.3f\nM3S1000\nG4P0.15\n", cornersDeg[0][0], cornersDeg[0][1]);
  text += line;
  for (int i : {1, 2, 0}) {
    std::snprintf(line, sizeof line, "G1X%.3fY%.3fF600\n", cornersDeg[i][0], cornersDeg[i][1]);
    text += line;
  }
  text += "M5\n";
  const std::string job = writeJob("triangle.gcode", text);
  const CliResult unknown = run({"frame", job, "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.err.find("position is not known"), std::string::npos) << unknown.err;
  EXPECT_NE(status().find("MPos:0.000,0.000,0.000"), std::string::npos) << "nothing moved";
  ASSERT_EQ(run({"reference", "--port", pty_, "--machine", "maker-plotter", "--yes"}).exitCode, 0);
  const CliResult framed = run({"frame", job, "--port", pty_, "--machine", "maker-plotter"});
  ASSERT_EQ(framed.exitCode, 0) << framed.err;
  EXPECT_NE(framed.out.find("pen up"), std::string::npos) << framed.out;
  EXPECT_NE(framed.out.find("framed"), std::string::npos) << framed.out;
  // The first corner: the lowest x of the three (machine frame).
  std::size_t first = 0;
  double lowestX = 1e9;
  for (std::size_t i = 0; i < cornersDeg.size(); ++i) {
    const FkResult fk = forward(profile_.geometry, {radFromDeg(cornersDeg[i][0]), radFromDeg(cornersDeg[i][1])},
                                profile_.assembly);
    ASSERT_TRUE(fk.ok());
    if (fk.p.x() < lowestX) { lowestX = fk.p.x(); first = i; }
  }
  EXPECT_NEAR(mpos()[0], cornersDeg[first][0] - h1, 2 * step());
  EXPECT_NEAR(mpos()[1], cornersDeg[first][1] - h2, 2 * step());
  // A drawing is planned as fivebar plan plans it, with its placement options.
  const fs::path svg = dir_ / "box.svg";
  std::ofstream(svg) << "<svg xmlns='http://www.w3.org/2000/svg' width='20mm' height='10mm' viewBox='0 0 20 10'>"
                        "<rect x='0' y='0' width='20' height='10' fill='none' stroke='black'/></svg>\n";
  const CliResult box = run({"frame", svg.string(), "--port", pty_, "--machine", "maker-plotter", "--at", "0,170",
                             "--shape", "box"});
  EXPECT_EQ(box.exitCode, 0) << box.err;
  EXPECT_NE(box.out.find("(20.0 x 10.0 mm"), std::string::npos) << box.out;
  EXPECT_EQ(run({"frame", job, "--port", pty_, "--machine", "maker-plotter", "--at", "0,170"}).exitCode, 2);
  EXPECT_NE(run({"frame", "--help"}).out.find("pen UP"), std::string::npos);
  // Pen up throughout: the simulated pen drew nothing.
  stopSim();
  const std::string drawnText = slurp(drawn);
  EXPECT_EQ(drawnText.find('\n'), drawnText.size() - 1) << "only the header: " << drawnText;
}

TEST_F(MachineCli, StreamRefusesUnsafeJobsBeforeTheFirstByte) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  const std::string start = "G0X" + homeX() + "Y" + homeY() + "\n";
  const std::string arcJob = writeJob("arc.gcode", "G21 G90\n" + start + "G2X1Y1I1F100\n");
  const CliResult arc = run({"stream", arcJob, "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(arc.exitCode, 1);
  EXPECT_NE(arc.err.find("line 3"), std::string::npos) << arc.err;
  EXPECT_NE(arc.err.find("nothing was sent"), std::string::npos) << arc.err;
  const std::string other = writeJob("other.gcode", "; profile: desk-plotter\nG21 G90\n" + start);
  const CliResult foreign = run({"stream", other, "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(foreign.exitCode, 1);
  EXPECT_NE(foreign.err.find("planned for the profile 'desk-plotter'"), std::string::npos) << foreign.err;
  EXPECT_EQ(run({"stream", other, "--port", pty_, "--machine", "maker-plotter", "--force-profile"}).exitCode, 0);
  const CliResult noMachine = run({"stream", writeJob("plain.gcode", "G21 G90\n" + start), "--port", pty_});
  EXPECT_EQ(noMachine.exitCode, 1);
  EXPECT_NE(noMachine.err.find("--machine"), std::string::npos) << noMachine.err;
  EXPECT_NE(status().find("MPos:0.000,0.000,0.000"), std::string::npos) << "nothing moved";
}

TEST_F(MachineCli, StreamApproachesTheJobsStartFromTheRealPose) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  const std::string x = deg3(profile_.homeAngles.theta1 + radFromDeg(4.0));
  const std::string job = writeJob("job.gcode", "; start pose X" + x + " Y" + homeY() + "\nG21 G90\nG1X" + x +
                                                    "Y" + deg3(profile_.homeAngles.theta2 + radFromDeg(2.0)) + "F600\n");
  const CliResult r = run({"stream", job, "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("approach"), std::string::npos) << r.err;
  EXPECT_NEAR(mpos()[0], 4.0, step());
  EXPECT_NEAR(mpos()[1], 2.0, step());
}

// `fivebar setup` shows each setting with its unit and meaning (GRBL 1.1h; X and Y are the
// motor angles, in degrees).
TEST_F(MachineCli, SetupNamesEachSettingWithItsUnitAndMeaning) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  const CliResult r = run({"setup", "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const auto row = [&](const std::string& id) {
    const std::size_t at = r.out.find("\n" + id + " ");
    return at == std::string::npos ? std::string() : r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(r.out.find("unit"), std::string::npos) << r.out;
  EXPECT_NE(row("$100").find("steps/deg  Motor 1 (X) steps per degree"), std::string::npos) << r.out;
  EXPECT_NE(row("$111").find("deg/min    Motor 2 (Y) maximum rate"), std::string::npos) << r.out;
  EXPECT_NE(row("$120").find("deg/s^2    Motor 1 (X) acceleration"), std::string::npos) << r.out;
  EXPECT_NE(row("$20").find("Soft limits (on/off)"), std::string::npos) << r.out;
}

// With the board's soft limits on, send and stream refuse a target outside its travel (machine
// coordinates) before a byte is sent; unchecked, the same line raises ALARM:2 on the board.
TEST_F(MachineCli, SendAndStreamRefuseTargetsOutsideTheBoardsSoftLimits) {
  ASSERT_TRUE(startSim({"--set-up", "--referenced"}));
  // Homing and soft limits on, 1 deg of travel below the reference (home = machine 0,0).
  const CliResult on = run({"send", "--port", pty_, "$22=1", "$20=1", "$130=1", "$131=1"});
  ASSERT_EQ(on.exitCode, 0) << on.err;
  const std::string up = "G1X" + deg3(profile_.homeAngles.theta1 + radFromDeg(0.5)) + "Y" + homeY() + "F600";
  const CliResult refused = run({"send", "--port", pty_, "--machine", "maker-plotter", up});
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("not sent"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("ALARM:2"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("$130=1.000"), std::string::npos) << refused.err;
  const std::string jog = "$J=G90X" + homeX() + "Y" + deg3(profile_.homeAngles.theta2 + radFromDeg(0.5)) + "F600";
  const CliResult jogRefused = run({"send", "--port", pty_, "--machine", "maker-plotter", jog});
  EXPECT_EQ(jogRefused.exitCode, 1);
  EXPECT_NE(jogRefused.err.find("error:15"), std::string::npos) << jogRefused.err;
  const std::string job = writeJob("up.gcode", "G21 G90\nG0X" + homeX() + "Y" + homeY() + "\n" + up + "\n");
  // The settings differ from the profile ($20, $22, $130, $131): refused, naming them...
  const CliResult differs = run({"stream", job, "--port", pty_, "--machine", "maker-plotter"});
  EXPECT_EQ(differs.exitCode, 1);
  EXPECT_NE(differs.err.find("$130 (motor 1 travel, deg) is 1 on the board"), std::string::npos) << differs.err;
  EXPECT_NE(differs.err.find("fivebar setup"), std::string::npos) << differs.err;
  // ...and with the expert's override, the board's soft limits are still checked.
  const CliResult stream =
      run({"stream", job, "--port", pty_, "--machine", "maker-plotter", "--ignore-settings"});
  EXPECT_EQ(stream.exitCode, 1);
  EXPECT_NE(stream.err.find("ALARM:2"), std::string::npos) << stream.err;
  EXPECT_NE(stream.err.find("nothing was sent"), std::string::npos) << stream.err;
  std::string s = status();
  EXPECT_NE(s.find("<Idle"), std::string::npos) << "no alarm: " << s;
  EXPECT_NE(s.find("MPos:0.000,0.000,0.000"), std::string::npos) << "nothing moved: " << s;
  // Inside the travel the line passes; unchecked, the refused line really raises ALARM:2.
  const std::string down = "G1X" + deg3(profile_.homeAngles.theta1 - radFromDeg(0.5)) + "Y" + homeY() + "F600";
  const CliResult inside = run({"send", "--port", pty_, "--machine", "maker-plotter", down});
  EXPECT_EQ(inside.exitCode, 0) << inside.err;
  const CliResult expert = run({"send", "--port", pty_, "--unchecked", "--timeout", "1", up});
  EXPECT_NE(expert.out.find("ALARM:2"), std::string::npos) << expert.out << expert.err;
}

TEST(FivebarSim, HelpWorks) {
  const int status = std::system((quote(FIVEBAR_SIM_EXE) + " --help >/dev/null").c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace
}  // namespace fivebar
