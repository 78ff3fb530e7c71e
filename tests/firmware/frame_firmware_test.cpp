// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar frame` on the REAL GRBL 1.1h firmware (../shared/tools/grbl-sim, every motor step each
// millisecond, issue 26): a planned 80 x 60 mm rectangle with a circle inside, framed after
// `fivebar setup --write` and `fivebar reference`. From the firmware's step trace: the spindle
// stayed off all along (the pen up: maker-plotter's pen servo lifts with M5), and from the moment
// the pen reached the outline's first corner the trace's bounding box in joint space matches
// that of the job's outline (its convex hull, the rectangle, walked as straight lines on the
// paper) within one motor step.
// Skipped when ../shared or the built simulator is absent (scripts/test.sh builds it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/kinematics/units.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "firmware_support.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;

constexpr double kWMm = 80.0, kHMm = 60.0;
const Vec2 kCentreMm(0.0, 170.0);  // machine frame

Drawing rectangleAndCircle() {
  Layer l;
  l.id = l.name = "ink";
  l.paths.push_back({{{0, 0}, {kWMm, 0}, {kWMm, kHMm}, {0, kHMm}, {0, 0}}, true});
  Polyline circle;
  for (int i = 0; i <= 72; ++i) {
    const double a = 2.0 * kPi * i / 72;
    circle.points.emplace_back(kWMm / 2 + 20.0 * std::cos(a), kHMm / 2 + 20.0 * std::sin(a));
  }
  circle.closed = true;
  l.paths.push_back(circle);
  Drawing d;
  d.widthMm = kWMm;
  d.heightMm = kHMm;
  d.layers.push_back(l);
  return d;
}

// Work coordinates (deg, what GRBL counts) of the pen at xy in `mode`, near `nearDeg`.
std::array<double, 2> workDegAt(const MachineProfile& p, const Vec2& xy, WorkingMode mode,
                                const std::array<double, 2>& nearDeg) {
  const IkResult ik = penInverse(p, xy, mode);
  EXPECT_TRUE(ik.ok()) << xy.transpose();
  const JointAngles q = commandedFromKinematic(p.calibration, ik.angles);
  return {degFromRad(unwrapNear(q.theta1, radFromDeg(nearDeg[0]))),
          degFromRad(unwrapNear(q.theta2, radFromDeg(nearDeg[1])))};
}

TEST(FirmwareFrame, TracesTheOutlinePenUpWithinAStepOfItsJointSpaceBox) {
  if (!firmware::firmwareAvailable())
    GTEST_SKIP() << "no ../shared/tools/grbl-sim or no built simulator (" << firmware::simulatorExe() << ")";
  const MachineProfile p = *preset("maker-plotter");
  PlanOptions o;
  o.atMm = kCentreMm;
  const PlanResult r = planJob(rectangleAndCircle(), p, o);
  ASSERT_TRUE(r.ok()) << r.message;

  const fs::path dir = fs::temp_directory_path() / ("fivebar-frame-fw-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ::setenv("FIVEBAR_STATE_DIR", (dir / "host").c_str(), 1);
  const fs::path profile = dir / "profile.json", job = dir / "job.gcode", steps = dir / "steps.txt";
  ASSERT_TRUE(saveProfile(p, profile.string()).empty());
  std::ofstream(job) << writeGcode(r.job, p);
  const fs::path pty = dir / "grblpty";
  std::string out;
  {
    firmware::Board board(pty, dir / "state", steps, {}, 3);
    ASSERT_TRUE(board.up());
    const std::string port = " --port " + pty.string() + " --machine " + profile.string();
    ASSERT_EQ(firmware::runCli("setup" + port + " --write --backup " + (dir / "backup.txt").string(),
                               dir / "setup.log", 60), 0);
    ASSERT_EQ(firmware::runCli("reference" + port + " --yes", dir / "reference.log", 20), 0);
    ASSERT_EQ(firmware::runCli("frame " + job.string() + port, dir / "frame.log", 120, &out), 0) << out;
  }
  EXPECT_NE(out.find("pen up"), std::string::npos) << out;
  const std::vector<firmware::Sample> trace = firmware::readTrace(steps);
  ASSERT_GT(trace.size(), 100u) << "no step trace in " << dir;

  // The pen stayed up: the spindle never came on.
  for (const firmware::Sample& s : trace) ASSERT_EQ(s.spindle, 0) << "at t " << s.t;

  // The outline in joint space: the rectangle's edges (the hull of the job's pen-down points)
  // sampled every 0.05 mm on the paper, in the job's working mode.
  const std::array<double, 2> homeDeg{degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2)};
  const double w = kWMm / 2, h = kHMm / 2;
  const std::array<Vec2, 4> corners{kCentreMm + Vec2(-w, -h), kCentreMm + Vec2(w, -h), kCentreMm + Vec2(w, h),
                                    kCentreMm + Vec2(-w, h)};
  std::array<double, 2> lo{1e9, 1e9}, hi{-1e9, -1e9};
  for (int e = 0; e < 4; ++e) {
    const Vec2 a = corners[e], b = corners[(e + 1) % 4];
    const int n = int(std::ceil((b - a).norm() / 0.05));
    for (int i = 0; i <= n; ++i) {
      const auto q = workDegAt(p, a + (b - a) * (double(i) / n), r.report.mode, homeDeg);
      for (int k = 0; k < 2; ++k) { lo[k] = std::min(lo[k], q[k]); hi[k] = std::max(hi[k], q[k]); }
    }
  }
  // The frame starts at the hull's first point (lowest x, then lowest y: a left corner, which of
  // the two depends on the G-code's rounding): the first time the trace stands on a corner.
  std::array<std::array<double, 2>, 4> cornerDeg;
  for (int c = 0; c < 4; ++c) cornerDeg[c] = workDegAt(p, corners[c], r.report.mode, homeDeg);
  const double perStep[2] = {1.0 / p.motors.stepsPerDeg1, 1.0 / p.motors.stepsPerDeg2};
  const auto degOf = [&](const firmware::Sample& s, int k) { return homeDeg[k] + (k == 0 ? s.s1 : s.s2) * perStep[k]; };
  const auto arrived = std::find_if(trace.begin(), trace.end(), [&](const firmware::Sample& s) {
    return std::any_of(cornerDeg.begin(), cornerDeg.end(), [&](const std::array<double, 2>& c) {
      return std::abs(degOf(s, 0) - c[0]) <= 1.01 * perStep[0] && std::abs(degOf(s, 1) - c[1]) <= 1.01 * perStep[1];
    });
  });
  ASSERT_NE(arrived, trace.end()) << "the pen never reached the first corner";
  std::array<double, 2> tlo{1e9, 1e9}, thi{-1e9, -1e9};
  for (auto it = arrived; it != trace.end(); ++it)
    for (int k = 0; k < 2; ++k) { tlo[k] = std::min(tlo[k], degOf(*it, k)); thi[k] = std::max(thi[k], degOf(*it, k)); }
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(tlo[k], lo[k], perStep[k]) << "motor " << k + 1 << " low";
    EXPECT_NEAR(thi[k], hi[k], perStep[k]) << "motor " << k + 1 << " high";
  }
  std::printf("outline box %.3f..%.3f, %.3f..%.3f deg; trace %.3f..%.3f, %.3f..%.3f deg\n", lo[0], hi[0], lo[1],
              hi[1], tlo[0], thi[0], tlo[1], thi[1]);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace fivebar
