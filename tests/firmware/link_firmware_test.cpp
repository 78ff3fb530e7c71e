// SPDX-License-Identifier: GPL-3.0-or-later
// The machine link against the REAL GRBL 1.1h firmware (../shared/tools/grbl-sim), driven by the
// built `fivebar` CLI as a user would (issue 10's checks): a job on a stock board ($10=1: no Bf:
// field) with executed progress and an ETA; a power cut mid-job, then a resume after a status
// query; a soft reset mid-job, then a resume; a line the firmware answers with error:N, then the
// fixed file resumed. From the firmware's motor step traces: nothing drawn off the drawing (every
// pen-down sample within the tolerance plus one step of it) and nothing missing (every point of
// the drawing drawn by some pen-down sample of the runs together).
// Skipped when ../shared or the built simulator is absent (scripts/test.sh builds it).
#include <fcntl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cmath>
#include <optional>
#include <regex>

#include "core/kinematics/singularity.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "firmware_support.hpp"

namespace fivebar {
namespace {

using firmware::Board;
using firmware::CliRun;
using firmware::Sample;
namespace fs = std::filesystem;

constexpr double kToleranceMm = 0.05;
const Vec2 kCentreMm(0.0, 170.0);  // machine frame
constexpr double kHalfSideMm = 30.0, kCircleRMm = 20.0;

// The drawing (work frame, centred on the origin): a 60 mm square, its diagonals, a circle.
std::vector<std::vector<Vec2>> drawingPaths() {
  const double h = kHalfSideMm;
  std::vector<std::vector<Vec2>> paths = {{{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}},
                                          {{-h, -h}, {h, h}}, {{-h, h}, {h, -h}}};
  std::vector<Vec2> circle;
  const int n = 180;  // chord error 0.006 mm
  for (int i = 0; i <= n; ++i) {
    const double a = 2.0 * kPi * i / n;
    circle.emplace_back(kCircleRMm * std::cos(a), kCircleRMm * std::sin(a));
  }
  paths.push_back(circle);
  return paths;
}

Drawing drawing() {
  Layer l;
  l.id = l.name = "ink";
  for (const auto& p : drawingPaths()) {
    Polyline pl;
    pl.points = p;
    l.paths.push_back(pl);
  }
  Drawing d;
  d.widthMm = d.heightMm = 2.0 * kHalfSideMm;
  d.layers.push_back(l);
  return d;
}

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + u * ab)).norm();
}

double distanceToDrawing(const Vec2& machine) {
  const Vec2 p = machine - kCentreMm;
  double d = 1e9;
  for (const auto& path : drawingPaths())
    for (size_t i = 0; i + 1 < path.size(); ++i) d = std::min(d, segmentDistance(p, path[i], path[i + 1]));
  return d;
}

// A piece of the pen's path drawn with the pen down, in the machine frame (the reference puts
// step 0 at the home pose): from one trace sample to the next, when the first is pen-down.
// (The trace prints no sample while the last segments of a block run after the planner has
// dropped it, and prints the block's end once the next one starts: at a stroke's end that is
// after M5, so the last stretch of a stroke only shows as the step to the next sample.)
struct PenSegment {
  Vec2 a, b;
  double slackMm;  // one motor step at a, in mm
};

std::vector<PenSegment> penDownSegments(const MachineProfile& p, const std::vector<Sample>& trace) {
  const double step1 = radFromDeg(1.0 / p.motors.stepsPerDeg1), step2 = radFromDeg(1.0 / p.motors.stepsPerDeg2);
  const auto xy = [&](const Sample& s) -> std::optional<Vec2> {
    const FkResult fk = forward(p.geometry, {p.homeAngles.theta1 + s.s1 * step1, p.homeAngles.theta2 + s.s2 * step2},
                                p.assembly);
    if (!fk.ok()) return std::nullopt;
    return fk.p;
  };
  std::vector<PenSegment> out;
  for (size_t i = 0; i + 1 < trace.size(); ++i) {
    if (trace[i].spindle == 0) continue;
    const auto a = xy(trace[i]), b = xy(trace[i + 1]);
    if (!a || !b) continue;
    const JointAngles q{p.homeAngles.theta1 + trace[i].s1 * step1, p.homeAngles.theta2 + trace[i].s2 * step2};
    const auto jac = cartesianJacobian(p.geometry, makePose(p.geometry, q, *a));
    const double slack = jac ? (jac->col(0) * step1).norm() + (jac->col(1) * step2).norm() : 1.0;
    out.push_back({*a, *b, slack});
  }
  return out;
}

// Nothing drawn off the drawing.
void expectNoStrayInk(const std::vector<PenSegment>& segs, const std::string& what) {
  double worst = -1.0;
  for (const PenSegment& q : segs)
    worst = std::max({worst, distanceToDrawing(q.a) - kToleranceMm - q.slackMm,
                      distanceToDrawing(q.b) - kToleranceMm - q.slackMm});
  EXPECT_LE(worst, 0.0) << what << ": a pen-down sample off the drawing by " << worst << " mm more than allowed";
}

// Every point of the drawing (every 0.5 mm) drawn: a pen-down segment within 0.15 mm (the
// tolerance and one step).
void expectDrawingComplete(const std::vector<PenSegment>& segs) {
  int missing = 0;
  Vec2 firstMissing(0, 0);
  for (const auto& path : drawingPaths()) {
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      const int n = std::max(1, int(std::ceil((path[i + 1] - path[i]).norm() / 0.5)));
      for (int k = 0; k <= n; ++k) {
        const Vec2 c = kCentreMm + path[i] + (path[i + 1] - path[i]) * (double(k) / n);
        const bool drawn = std::any_of(segs.begin(), segs.end(), [&](const PenSegment& q) {
          return (q.a - c).squaredNorm() < 100.0 && segmentDistance(c, q.a, q.b) < 0.15;
        });
        if (!drawn && missing++ == 0) firstMissing = c;
      }
    }
  }
  EXPECT_EQ(missing, 0) << "points of the drawing never drawn, the first at (" << firstMissing.x() << ", "
                        << firstMissing.y() << ")";
}

int progressField(const fs::path& file, const std::string& name) {
  std::smatch m;
  const std::string text = firmware::readText(file);
  if (std::regex_search(text, m, std::regex("\"" + name + "\"\\s*:\\s*([0-9]+)"))) return std::stoi(m[1]);
  return -1;
}

// One simulated board with the maker-plotter set up and referenced, and the planned job.
class FirmwareLink : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!firmware::firmwareAvailable())
      GTEST_SKIP() << "no ../shared/tools/grbl-sim or no built simulator (" << firmware::simulatorExe() << ")";
    profile_ = *preset("maker-plotter");
    dir_ = fs::temp_directory_path() / ("fivebar-link-fw-" + std::to_string(getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Where this computer remembers the board's position (drivers/protocol/pose_trust.hpp): the test's own.
    ::setenv("FIVEBAR_STATE_DIR", (dir_ / "host").c_str(), 1);
    pty_ = dir_ / "grblpty";
    job_ = dir_ / "job.gcode";
    ASSERT_TRUE(saveProfile(profile_, (dir_ / "profile.json").string()).empty());
    PlanOptions o;
    o.atMm = kCentreMm;
    o.toleranceMm = kToleranceMm;
    o.flatteningToleranceMm = 0.4 * kToleranceMm;
    const PlanResult r = planJob(drawing(), profile_, o);
    ASSERT_TRUE(r.ok()) << r.message;
    std::ofstream(job_) << writeGcode(r.job, profile_);
    jobLines_ = int(std::count(std::istreambuf_iterator<char>(std::ifstream(job_).rdbuf()),
                               std::istreambuf_iterator<char>(), '\n'));
    powerOn();
    ASSERT_TRUE(board_->up()) << "the firmware did not start";
    ASSERT_EQ(cli("setup" + port() + machine() + " --write --backup " + (dir_ / "backup.txt").string(), 60), 0);
    ASSERT_EQ(cli("reference" + port() + machine() + " --yes", 20), 0);
  }
  void TearDown() override {
    board_.reset();
    if (!HasFailure() && !dir_.empty()) fs::remove_all(dir_);
  }

  void powerOn() {
    ++powerUps_;
    board_ = std::make_unique<Board>(pty_, dir_ / "state", trace(powerUps_), std::vector<std::string>{},
                                     speedup());
  }
  // What these tests check is what is drawn and resumed, not how long it takes: the machine runs
  // 3x the wall clock, except where the time is the point (the ETA).
  static int speedup() {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    return name == "JobOnAStockBoardShowsExecutedProgressAndEta" ? 1 : 3;
  }
  fs::path trace(int n) const { return dir_ / ("steps" + std::to_string(n) + ".txt"); }
  std::string port() const { return " --port " + pty_.string(); }
  std::string machine() const { return " --machine " + (dir_ / "profile.json").string(); }
  std::string stream(const std::string& extra = "") const {
    return "stream " + job_.string() + port() + machine() + extra;
  }
  int cli(const std::string& args, double timeoutS, std::string* out = nullptr) {
    return firmware::runCli(args, dir_ / ("cli" + std::to_string(++runs_) + ".log"), timeoutS, out);
  }
  fs::path progressFile() const { return fs::path(job_.string() + ".progress"); }
  // The job's last X/Y target (deg), from its G-code.
  std::optional<std::array<double, 2>> lastTargetDeg() const {
    std::optional<std::array<double, 2>> last;
    std::ifstream in(job_);
    const std::regex xy("^G[01].*X(-?[0-9.]+) ?Y(-?[0-9.]+)");
    std::smatch m;
    for (std::string l; std::getline(in, l);)
      if (std::regex_search(l, m, xy)) last = std::array<double, 2>{std::stod(m[1]), std::stod(m[2])};
    return last;
  }
  // Waits until the firmware's step trace shows the spindle on (the pen down, drawing).
  bool waitForPenDown(int powerUp, double timeoutS) const {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    while (std::chrono::steady_clock::now() < end) {
      const auto t = firmware::readTrace(trace(powerUp));
      if (t.size() > 50 && t.back().spindle != 0) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }
  // Waits (while `run` streams) until the saved progress has a pen-down point at least `share`
  // of the way through the job; false when the job got there no other way.
  bool waitForProgress(double share, double timeoutS) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    while (std::chrono::steady_clock::now() < end) {
      if (progressField(progressFile(), "lastPenDownLine") >= share * jobLines_) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  std::vector<PenSegment> allPenDown() const {
    std::vector<PenSegment> all;
    for (int n = 1; n <= powerUps_; ++n) {
      const auto pts = penDownSegments(profile_, firmware::readTrace(trace(n)));
      expectNoStrayInk(pts, "power-up " + std::to_string(n));
      all.insert(all.end(), pts.begin(), pts.end());
    }
    return all;
  }

  MachineProfile profile_;
  fs::path dir_, pty_, job_;
  int jobLines_ = 0;
  int powerUps_ = 0;
  int runs_ = 0;
  std::unique_ptr<Board> board_;
};

TEST_F(FirmwareLink, JobOnAStockBoardShowsExecutedProgressAndEta) {
  // A stock board's status report ($10=1): no Bf: field.
  ASSERT_EQ(cli("send" + port() + " '$10=1'", 10), 0);
  std::string out;
  ASSERT_EQ(cli(stream(), 120, &out), 0) << out;
  EXPECT_NE(out.find("done:"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(progressFile())) << "the finished job's progress file stays";
  // Executed progress and an ETA while running, without Bf:.
  std::smatch m;
  EXPECT_TRUE(std::regex_search(out, m, std::regex("running \\(machine Run\\): [0-9]+/[0-9]+ lines acknowledged, "
                                                   "([1-9][0-9]*) executed, ETA [0-9]+ s")))
      << out;
  const auto pts = allPenDown();
  EXPECT_GT(pts.size(), 1000u);
  expectDrawingComplete(pts);
}

TEST_F(FirmwareLink, PowerCutMidJobThenResumeAfterAStatusQuery) {
  ASSERT_EQ(cli("send" + port() + " '$10=1'", 10), 0);  // a stock board: progress without Bf:
  {
    CliRun run(stream(), dir_ / "stream1.log");
    ASSERT_TRUE(waitForProgress(0.35, 60)) << firmware::readText(dir_ / "stream1.log");
    board_->powerOff();  // the plug pulled mid-job
    EXPECT_EQ(run.wait(30), 1);
  }
  const std::string cut = firmware::readText(dir_ / "stream1.log");
  EXPECT_NE(cut.find("vanished"), std::string::npos) << cut;
  EXPECT_NE(cut.find("--resume"), std::string::npos) << cut;
  const int resumeLine = progressField(progressFile(), "lastPenDownLine");
  EXPECT_GT(resumeLine, 0) << "no resume point after the cut: the resume would redraw from line 1";

  // Power back: MPos 0,0 (the arms' counters restart), the G54 offset kept in the EEPROM, so
  // the board reports exactly the home pose wherever the arms stand.
  powerOn();
  ASSERT_TRUE(board_->up());
  std::string status;
  ASSERT_EQ(cli("send" + port() + " '?'", 10, &status), 0) << status;
  EXPECT_NE(status.find("<Idle|MPos:0.000,0.000,0.000"), std::string::npos) << status;
  // The resume refuses: the position is not known. Nothing moves.
  std::string refused;
  EXPECT_EQ(cli(stream(" --resume"), 60, &refused), 1) << refused;
  EXPECT_NE(refused.find("position is not known"), std::string::npos) << refused;
  EXPECT_NE(refused.find("fivebar reference"), std::string::npos) << refused;
  const auto still = firmware::readTrace(trace(2));
  EXPECT_TRUE(std::all_of(still.begin(), still.end(), [](const Sample& x) { return x.s1 == 0 && x.s2 == 0; }))
      << "a motor moved although the resume was refused";
  // The maker puts the arms in the home pose and says so; then the resume finishes the job.
  std::string ref;
  ASSERT_EQ(cli("reference" + port() + machine() + " --yes", 20, &ref), 0) << ref;
  std::string resumed;
  ASSERT_EQ(cli(stream(" --resume"), 120, &resumed), 0) << resumed;
  EXPECT_FALSE(fs::exists(progressFile()));
  // It ends at the job's last target (the board's own report: the reference put MPos 0,0 at the
  // home pose), after its last drawn point.
  std::string at;
  ASSERT_EQ(cli("send" + port() + " '?'", 10, &at), 0) << at;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(at, m, std::regex("MPos:(-?[0-9.]+),(-?[0-9.]+)"))) << at;
  const auto last = lastTargetDeg();
  ASSERT_TRUE(last.has_value());
  const double homeX = degFromRad(profile_.homeAngles.theta1), homeY = degFromRad(profile_.homeAngles.theta2);
  EXPECT_NEAR(homeX + std::stod(m[1]), (*last)[0], 1.5 / profile_.motors.stepsPerDeg1) << at;
  EXPECT_NEAR(homeY + std::stod(m[2]), (*last)[1], 1.5 / profile_.motors.stepsPerDeg2) << at;
  const auto end = firmware::readTrace(trace(2));
  const auto lastInk = std::find_if(end.rbegin(), end.rend(), [](const Sample& x) { return x.spindle != 0; });
  ASSERT_NE(lastInk, end.rend()) << "the resume drew nothing";

  const auto before = penDownSegments(profile_, firmware::readTrace(trace(1)));
  const auto after = penDownSegments(profile_, firmware::readTrace(trace(2)));
  ASSERT_FALSE(before.empty());
  ASSERT_FALSE(after.empty());
  // The resume starts drawing where the first run had drawn already (never a gap), not at the
  // job's first point.
  const Vec2 restart = after.front().a;
  EXPECT_TRUE(std::any_of(before.begin(), before.end(),
                          [&](const PenSegment& q) { return segmentDistance(restart, q.a, q.b) < 0.1; }))
      << "the resume put the pen down at a point the first run had not drawn";
  EXPECT_GT((restart - before.front().a).norm(), 5.0) << "the resume started over from the job's start";
  expectDrawingComplete(allPenDown());
}

TEST_F(FirmwareLink, SoftResetMidJobThenResume) {
  {
    CliRun run(stream(), dir_ / "stream1.log");
    ASSERT_TRUE(waitForProgress(0.4, 60)) << firmware::readText(dir_ / "stream1.log");
    // The board resets mid-job (its reset button): 0x18 on the wire, from another opener of the pty.
    const int fd = ::open(pty_.c_str(), O_WRONLY | O_NOCTTY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::write(fd, "\x18", 1), 1);
    ::close(fd);
    EXPECT_EQ(run.wait(30), 1);
  }
  const std::string stopped = firmware::readText(dir_ / "stream1.log");
  EXPECT_NE(stopped.find("reset"), std::string::npos) << stopped;
  EXPECT_TRUE(fs::exists(progressFile()));
  // A reset in motion (ALARM:3): the motors may have lost steps, so the position is not known.
  std::string refused;
  EXPECT_EQ(cli(stream(" --resume"), 60, &refused), 1) << refused;
  EXPECT_NE(refused.find("position is not known"), std::string::npos) << refused;
  EXPECT_NE(refused.find("reset"), std::string::npos) << refused;
  // These motors lost none (the simulator's counters are the arms): the maker confirms the pose.
  std::string kept;
  ASSERT_EQ(cli("reference" + port() + machine() + " --keep --yes", 20, &kept), 0) << kept;
  std::string resumed;
  ASSERT_EQ(cli(stream(" --resume"), 120, &resumed), 0) << resumed;
  expectDrawingComplete(allPenDown());
}

TEST_F(FirmwareLink, ErrorLineStopsTheJobAndTheFixedFileResumes) {
  // A line the motion check passes (no motion) but GRBL 1.1h refuses: M7 (mist is not compiled
  // in: error:20), put in the middle of the job.
  std::vector<std::string> lines;
  {
    std::ifstream in(job_);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  const size_t at = lines.size() / 2;
  lines.insert(lines.begin() + long(at), "M7");
  const auto writeJob = [&] {
    std::ofstream out(job_);
    for (const std::string& l : lines) out << l << "\n";
  };
  writeJob();
  std::string out;
  EXPECT_EQ(cli(stream(), 120, &out), 1) << out;
  const std::string lineNo = "line " + std::to_string(at + 1);
  EXPECT_NE(out.find(lineNo), std::string::npos) << out;
  EXPECT_NE(out.find("error:20"), std::string::npos) << out;
  ASSERT_TRUE(fs::exists(progressFile())) << out;
  EXPECT_LE(progressField(progressFile(), "lastPenDownLine"), int(at)) << "the resume point lies beyond the refused line";

  lines[at] = "; M7 removed";  // the fix: same line numbers, another hash
  writeJob();
  std::string resumed;
  ASSERT_EQ(cli(stream(" --resume"), 120, &resumed), 0) << resumed;
  expectDrawingComplete(allPenDown());
}

// Steps per degree 7x off, written behind the studio's back: the stream refuses before the
// first move and names the setting.
TEST_F(FirmwareLink, ChangedSettingsRefuseTheStreamBeforeTheFirstMove) {
  ASSERT_EQ(cli("send" + port() + " '$100=250'", 10), 0);
  std::string out;
  EXPECT_EQ(cli(stream(), 60, &out), 1) << out;
  EXPECT_NE(out.find("$100 (motor 1 steps/deg) is 250 on the board, the profile wants 35.5556"), std::string::npos) << out;
  EXPECT_NE(out.find("fivebar setup"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(progressFile())) << "nothing ran";
  const auto t = firmware::readTrace(trace(1));
  EXPECT_TRUE(std::all_of(t.begin(), t.end(), [](const Sample& x) { return x.s1 == 0 && x.s2 == 0 && x.spindle == 0; }))
      << "the machine moved";
}

// Ctrl+C during a pen-down stroke: the CLI stops the machine (hold, reset with the position kept,
// pen up), says so within 5 s, and the job resumes to the end.
TEST_F(FirmwareLink, CtrlCDuringAStrokeStopsWithThePenUpAndResumes) {
  std::string startOut;
  {
    CliRun run(stream(), dir_ / "stream1.log");
    ASSERT_TRUE(waitForProgress(0.3, 60)) << firmware::readText(dir_ / "stream1.log");
    ASSERT_TRUE(waitForPenDown(1, 20)) << "no pen-down stroke";
    const auto asked = std::chrono::steady_clock::now();
    run.signal(SIGINT);
    EXPECT_EQ(run.wait(5.0), 1) << "did not stop within 5 s";
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count(), 5.0);
  }
  const std::string out = firmware::readText(dir_ / "stream1.log");
  EXPECT_NE(out.find("stopped on request after line"), std::string::npos) << out;
  EXPECT_NE(out.find("The pen is up"), std::string::npos) << out;
  EXPECT_NE(out.find("--resume"), std::string::npos) << out;
  ASSERT_TRUE(fs::exists(progressFile()));
  // Not moving, the pen up in the board's own parser state.
  const auto before = firmware::readTrace(trace(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto after = firmware::readTrace(trace(1));
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.back().s1, before.back().s1);
  EXPECT_EQ(after.back().s2, before.back().s2);
  std::string status, parser;
  ASSERT_EQ(cli("send" + port() + " '?'", 10, &status), 0) << status;
  EXPECT_NE(status.find("<Idle"), std::string::npos) << status;
  ASSERT_EQ(cli("send" + port() + " '$G'", 10, &parser), 0) << parser;
  EXPECT_NE(parser.find(" M5 "), std::string::npos) << parser;
  // The stop kept the position: the resume needs nothing else and completes the drawing.
  std::string resumed;
  ASSERT_EQ(cli(stream(" --resume"), 120, &resumed), 0) << resumed;
  expectDrawingComplete(allPenDown());
}

}  // namespace
}  // namespace fivebar
