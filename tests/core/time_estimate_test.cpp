// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL time model against an INDEPENDENT numerical integration: a point driven along the blocks
// with small time steps, accelerating at each block's limit unless it must brake for a junction
// or the end of the look-ahead window; junction speeds recomputed here from GRBL's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/planning/time_estimate.hpp"
#include "test_support.hpp"
#include "time_estimate_oracle.hpp"

namespace fivebar {
namespace {

struct SimBlock {
  double length, nominal, accel, junction;  // junction: max entry speed
  bool syncBefore;
  double dwellBefore;
};

double axisLimited(const Eigen::Vector3d& maxima, const Eigen::Vector3d& unit) {
  double v = 1e300;
  for (int i = 0; i < 3; ++i) if (unit[i] != 0.0) v = std::min(v, maxima[i] / std::abs(unit[i]));
  return v;
}

std::vector<SimBlock> simBlocks(const std::vector<GrblBlockInput>& inputs, const GrblTimeModel& m,
                                double& dwellTail) {
  std::vector<SimBlock> out;
  Eigen::Vector3d prev = Eigen::Vector3d::Zero();
  bool sync = true;
  double dwell = 0.0;
  double prevNominal = 0.0;
  for (const GrblBlockInput& in : inputs) {
    if (in.sync) { sync = true; dwell += in.dwellS; continue; }
    const double len = in.delta.norm();
    if (len < 1e-9) continue;
    const Eigen::Vector3d u = in.delta / len;
    SimBlock b{len, std::min(in.feedPerS, axisLimited(m.maxRatePerS, u)),
               axisLimited(m.accelPerS2, u), 0.0, sync, dwell};
    if (!sync) {
      // GRBL: v^2 = a_j * delta * sin(theta/2) / (1 - sin(theta/2)), theta = angle between the
      // reversed previous direction and the new one.
      const double cosTheta = -prev.dot(u);
      const double sinHalf = std::sqrt(std::max(0.0, 0.5 * (1 - cosTheta)));
      const double aj = axisLimited(m.accelPerS2, (u - prev).normalized());
      double v2 = sinHalf >= 1 - 1e-12 ? 1e300 : aj * m.junctionDeviation * sinHalf / (1 - sinHalf);
      if (cosTheta > 0.999999) v2 = 0;
      b.junction = std::sqrt(std::min(v2, std::pow(std::min(prevNominal, b.nominal), 2)));
    }
    out.push_back(b);
    prev = u;
    prevNominal = b.nominal;
    sync = false;
    dwell = 0.0;
  }
  dwellTail = dwell;
  return out;
}

// Time-stepped execution: in block k the speed may not exceed what still allows meeting every
// junction ahead inside the window (and stopping at the window's end or a sync).
double integrate(const std::vector<GrblBlockInput>& inputs, const GrblTimeModel& m, double dt) {
  double tail = 0.0;
  const std::vector<SimBlock> blocks = simBlocks(inputs, m, tail);
  double t = 0.0, v = 0.0;
  for (size_t k = 0; k < blocks.size(); ++k) {
    if (blocks[k].syncBefore) { t += blocks[k].dwellBefore; v = 0.0; }
    // Exit limit of block k from the window k .. k+W-1 (stop at its end or at a sync).
    size_t end = k + 1;
    while (end < blocks.size() && end < k + static_cast<size_t>(m.lookaheadBlocks) &&
           !blocks[end].syncBefore)
      ++end;
    double w = 0.0;  // speed allowed at the end of block end-1
    for (size_t j = end - 1; j > k; --j)
      w = std::min(blocks[j].junction, std::sqrt(w * w + 2 * blocks[j].accel * blocks[j].length));
    const SimBlock& b = blocks[k];
    double s = 0.0;
    while (s < b.length) {
      const double brake = std::sqrt(w * w + 2 * b.accel * std::max(0.0, b.length - s));
      const double target = std::min({b.nominal, brake, v + b.accel * dt});
      const double vNew = std::max(target, 1e-9);
      const double ds = 0.5 * (v + vNew) * dt;
      if (s + ds >= b.length) {  // finish the block within this step
        t += (b.length - s) / std::max(0.5 * (v + vNew), 1e-12);
        v = vNew;
        break;
      }
      s += ds;
      v = vNew;
      t += dt;
    }
  }
  return t + tail;
}

double total(const std::vector<GrblBlockTiming>& timings) {
  double t = 0.0;
  for (const auto& b : timings) t += b.durationS;
  return t;
}

TEST(TimeEstimate, SingleBlockIsATrapezoid) {
  GrblTimeModel m;
  m.maxRatePerS = {100, 100, 10};
  m.accelPerS2 = {200, 200, 100};
  GrblBlockInput in;
  in.delta = {90, 0, 0};
  in.feedPerS = 60;
  // Accelerate 0 -> 60 over 9 deg (0.3 s), cruise 72 deg (1.2 s), brake 9 deg (0.3 s).
  EXPECT_NEAR(total(estimateBlocks({in}, m)), 1.8, 1e-9);
  in.delta = {0, 4, 0};  // triangle: peak sqrt(200 * 4) = 28.28 deg/s
  EXPECT_NEAR(total(estimateBlocks({in}, m)), 2 * std::sqrt(800.0) / 200.0, 1e-9);
}

TEST(TimeEstimate, AgreesWithIndependentIntegrationOnRandomJobs) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> d(-1, 1), len(0.01, 5), feed(5, 200), u01(0, 1);
  GrblTimeModel m;
  m.maxRatePerS = {150, 120, 10};
  m.accelPerS2 = {400, 250, 100};
  m.junctionDeviation = 0.02;
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<GrblBlockInput> inputs;
    Eigen::Vector3d dir(1, 0.3, 0);
    for (int i = 0; i < 300; ++i) {
      GrblBlockInput in;
      if (u01(rng) < 0.03) {
        in.sync = true;
        in.dwellS = 0.1 * u01(rng);
      } else {
        dir = (dir + 0.4 * Eigen::Vector3d(d(rng), d(rng), 0)).normalized();  // smooth turns
        in.delta = len(rng) * (trial % 2 ? dir : Eigen::Vector3d(d(rng), d(rng), 0).normalized());
        in.feedPerS = feed(rng);
      }
      inputs.push_back(in);
    }
    const double model = total(estimateBlocks(inputs, m));
    const double sim = integrate(inputs, m, 1e-5);
    EXPECT_NEAR(model, sim, 0.02 * sim) << "trial " << trial;
  }
}

TEST(TimeEstimate, LookAheadWindowLimitsSpeedOnManyTinyBlocks) {
  // 2000 collinear blocks of 0.01 deg: the planner must be able to stop within the 15 blocks it
  // holds, so cruise is about sqrt(2 a * 15 * 0.01) instead of the programmed 100 deg/s.
  GrblTimeModel m;
  m.maxRatePerS = {1000, 1000, 10};
  m.accelPerS2 = {100, 100, 100};
  std::vector<GrblBlockInput> inputs(2000);
  for (auto& in : inputs) { in.delta = {0.01, 0, 0}; in.feedPerS = 100; }
  const double cruise = std::sqrt(2 * 100 * 14 * 0.01);  // window of 15, current block moving
  const double t = total(estimateBlocks(inputs, m));
  EXPECT_NEAR(t, 20.0 / cruise, 0.08 * 20.0 / cruise);
  EXPECT_NEAR(t, integrate(inputs, m, 1e-5), 0.02 * t);
  m.lookaheadBlocks = 1000000;  // unlimited look-ahead: one triangle over the 20 deg
  EXPECT_NEAR(total(estimateBlocks(inputs, m)), 2 * std::sqrt(100 * 20.0) / 100, 1e-6);
}

TEST(TimeEstimate, SyncsStopAndDwellsAdd) {
  GrblTimeModel m;
  m.maxRatePerS = {100, 100, 10};
  m.accelPerS2 = {200, 200, 100};
  GrblBlockInput a;
  a.delta = {90, 0, 0};
  a.feedPerS = 60;
  GrblBlockInput dwell;
  dwell.sync = true;
  dwell.dwellS = 0.25;
  // Two collinear blocks joined run through; with a sync between they stop (1.8 s each).
  EXPECT_NEAR(total(estimateBlocks({a, a}, m)), 180.0 / 60 + 0.3, 1e-9);
  EXPECT_NEAR(total(estimateBlocks({a, dwell, a}, m)), 1.8 + 0.25 + 1.8, 1e-9);
}

TEST(TimeEstimate, JobTimesFillMovesInOrder) {
  PlannedJob job;
  MachineProfile p;
  job.start = {0, 0};
  JobMove m1;
  m1.kind = JobMoveKind::Travel;
  m1.target = {radFromDeg(10), radFromDeg(5)};
  m1.jointFeedRadPerS = radFromDeg(30);
  JobMove down;
  down.kind = JobMoveKind::PenDown;
  down.target = m1.target;
  down.dwellS = 0.15;
  job.moves = {m1, down};
  estimateJobTime(job, p);
  EXPECT_DOUBLE_EQ(job.moves[0].startTimeS, 0.0);
  EXPECT_GT(job.moves[0].durationS, std::hypot(10.0, 5.0) / 30.0);  // accelerating costs time
  EXPECT_DOUBLE_EQ(job.moves[1].startTimeS, job.moves[0].durationS);
  EXPECT_DOUBLE_EQ(job.moves[1].durationS, 0.15);
  EXPECT_DOUBLE_EQ(job.summary.estimatedTimeS, job.moves[0].durationS + 0.15);
}


// --- Same figures as the reference model (time_estimate_oracle.hpp) to 1e-9 relative ---

bool closeRelative(double actual, double expected) {
  return actual == expected ||
         std::abs(actual - expected) <= 1e-9 * std::max(std::abs(actual), std::abs(expected));
}

void expectSameTimings(const std::vector<GrblBlockTiming>& actual,
                       const std::vector<GrblBlockTiming>& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  int reported = 0;
  for (size_t i = 0; i < actual.size() && reported < 5; ++i) {
    const GrblBlockTiming &a = actual[i], &e = expected[i];
    const bool same = closeRelative(a.lengthUnits, e.lengthUnits) &&
                      closeRelative(a.entryPerS, e.entryPerS) &&
                      closeRelative(a.nominalPerS, e.nominalPerS) &&
                      closeRelative(a.exitPerS, e.exitPerS) &&
                      closeRelative(a.accelPerS2, e.accelPerS2) &&
                      closeRelative(a.durationS, e.durationS);
    if (!same) {
      ADD_FAILURE() << what << ", input " << i << ": duration " << a.durationS << " vs "
                    << e.durationS << ", entry " << a.entryPerS << " vs " << e.entryPerS
                    << ", exit " << a.exitPerS << " vs " << e.exitPerS;
      ++reported;
    }
  }
}

// Random planner inputs: runs of smooth or random directions, straight runs (no junction limit,
// so the look-ahead window decides), reversals, Z blocks, empty and tiny blocks, zero feeds,
// synchronising commands with and without dwell.
std::vector<GrblBlockInput> randomInputs(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  std::vector<GrblBlockInput> inputs;
  Eigen::Vector3d dir(1, 0, 0);
  int style = 0;
  for (int i = 0; i < n; ++i) {
    if (u(rng) < 0.05) style = static_cast<int>(u(rng) * 4);
    GrblBlockInput in;
    const double pick = u(rng);
    if (pick < 0.03) {
      in.sync = true;
      in.dwellS = u(rng) < 0.5 ? 0.0 : 0.2 * u(rng);
    } else if (pick < 0.05) {
      in.delta = Eigen::Vector3d(1e-10, 0, 0);  // empty: below GRBL's step resolution
      in.feedPerS = 50;
    } else if (pick < 0.08) {
      in.delta = Eigen::Vector3d(0, 0, 5.0 * s(rng));  // a Z-axis pen move
      in.feedPerS = 10;
    } else {
      if (style == 0) dir = (dir + 0.2 * Eigen::Vector3d(s(rng), s(rng), 0)).normalized();
      if (style == 1) dir = Eigen::Vector3d(s(rng), s(rng), 0).normalized();
      if (style == 3 && u(rng) < 0.3) dir = -dir;  // reversal
      const double length = u(rng) < 0.1 ? 1e-6 * u(rng) + 1e-9 : 0.01 + 3.0 * u(rng);
      in.delta = length * dir;
      in.feedPerS = u(rng) < 0.05 ? 0.0 : 5.0 + 300.0 * u(rng);
    }
    inputs.push_back(in);
  }
  return inputs;
}

TEST(TimeEstimate, BlocksMatchTheReferenceModel) {
  auto rng = test::rng();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int window : {1, 2, 3, 15, 40, 1000000}) {
    for (int trial = 0; trial < 4; ++trial) {
      GrblTimeModel m;
      m.maxRatePerS = {50 + 300 * u(rng), 50 + 300 * u(rng), 5 + 20 * u(rng)};
      m.accelPerS2 = {100 + 2000 * u(rng), 100 + 2000 * u(rng), 100};
      m.junctionDeviation = 0.001 + 0.05 * u(rng);
      m.minJunctionSpeedPerS = trial % 2 ? 0.0 : 2.0 * u(rng);
      m.lookaheadBlocks = window;
      const std::vector<GrblBlockInput> inputs = randomInputs(rng, 3000);
      expectSameTimings(estimateBlocks(inputs, m), oracle::estimateBlocks(inputs, m),
                        "window " + std::to_string(window) + " trial " + std::to_string(trial));
    }
  }
}

// A job like a drawing: strokes of small joint steps between travels, with the tool commands of
// the given tool kind, dwells and pauses.
PlannedJob randomDrawingJob(std::mt19937_64& rng, int strokes) {
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  PlannedJob job;
  job.start = {radFromDeg(100 * s(rng)), radFromDeg(100 * s(rng))};
  JointAngles at = job.start;
  double heading = 0.0;
  auto add = [&](JobMoveKind kind, double feedDegPerS) {
    JobMove m;
    m.kind = kind;
    m.target = at;
    m.jointFeedRadPerS = radFromDeg(feedDegPerS);
    m.dwellS = u(rng) < 0.2 ? 0.0 : 0.15;
    m.toolValue = kind == JobMoveKind::PenDown ? -0.5 + u(rng) : 4.0;
    job.moves.push_back(m);
  };
  for (int k = 0; k < strokes; ++k) {
    at = {at.theta1 + radFromDeg(10 * s(rng)), at.theta2 + radFromDeg(10 * s(rng))};
    add(JobMoveKind::Travel, 150);
    add(JobMoveKind::PenDown, 0);
    const int n = 5 + static_cast<int>(u(rng) * 60);
    for (int i = 0; i < n; ++i) {
      heading += 0.4 * s(rng);
      const double stepDeg = u(rng) < 0.05 ? 0.0 : 0.02 + 0.3 * u(rng);  // some empty moves
      at = {at.theta1 + radFromDeg(stepDeg * std::cos(heading)),
            at.theta2 + radFromDeg(stepDeg * std::sin(heading))};
      add(JobMoveKind::Draw, 10 + 80 * u(rng));
    }
    add(JobMoveKind::PenUp, 0);
    if (u(rng) < 0.05) add(JobMoveKind::Dwell, 0);
    if (u(rng) < 0.02) add(JobMoveKind::Pause, 0);
  }
  return job;
}

void expectSameMoveTimes(const PlannedJob& actual, const PlannedJob& expected, const std::string& what) {
  EXPECT_TRUE(closeRelative(actual.summary.estimatedTimeS, expected.summary.estimatedTimeS))
      << what << ": " << actual.summary.estimatedTimeS << " vs " << expected.summary.estimatedTimeS;
  ASSERT_EQ(actual.moves.size(), expected.moves.size());
  for (size_t i = 0; i < actual.moves.size(); ++i) {
    ASSERT_TRUE(closeRelative(actual.moves[i].durationS, expected.moves[i].durationS) &&
                closeRelative(actual.moves[i].startTimeS, expected.moves[i].startTimeS))
        << what << ", move " << i << ": " << actual.moves[i].startTimeS << " + "
        << actual.moves[i].durationS << " vs " << expected.moves[i].startTimeS << " + "
        << expected.moves[i].durationS;
  }
}

// Small jobs run in one part; large ones (over 20000 moves) in two, cut at a synchronising move
// near the middle (a pen servo's M3/M5, or a dwell or pause for the other tools).
TEST(TimeEstimate, JobTimesMatchTheReferenceModelForEveryTool) {
  auto rng = test::rng();
  for (int strokes : {300, 900}) {
    for (ToolKind tool : {ToolKind::PenServo, ToolKind::ZAxis, ToolKind::Laser}) {
      MachineProfile p = *preset("maker-plotter");
      p.tool.kind = tool;
      const PlannedJob job = randomDrawingJob(rng, strokes);
      if (strokes > 300) {
        ASSERT_GT(job.moves.size(), 20000u);
      }
      PlannedJob expected = job, actual = job, filled = job;
      const auto expectedTimings = oracle::estimateJobTime(expected, p);
      const auto actualTimings = estimateJobTime(actual, p);
      fillJobTimes(filled, p);
      const std::string what = std::to_string(job.moves.size()) + " moves, tool " +
                               std::to_string(static_cast<int>(tool));
      EXPECT_GT(actual.summary.estimatedTimeS, 1.0) << what;
      expectSameTimings(actualTimings, expectedTimings, what);
      expectSameMoveTimes(actual, expected, what);
      expectSameMoveTimes(filled, expected, what + " (fillJobTimes)");
    }
  }
}

TEST(TimeEstimate, InputsOfAJobMatchTheReference) {
  auto rng = test::rng();
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = ToolKind::ZAxis;
  const PlannedJob job = randomDrawingJob(rng, 20);
  const auto actual = grblInputsOf(job, p), expected = oracle::grblInputsOf(job, p);
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].delta, expected[i].delta) << i;
    EXPECT_EQ(actual[i].feedPerS, expected[i].feedPerS) << i;
    EXPECT_EQ(actual[i].sync, expected[i].sync) << i;
    EXPECT_EQ(actual[i].dwellS, expected[i].dwellS) << i;
  }
}

}  // namespace
}  // namespace fivebar
