// SPDX-License-Identifier: GPL-3.0-or-later
// The pipeline: every planned draw move measured independently (dense FK) stays within the
// tolerance, feeds respect the motors, the tool sequence is consistent, travels are safe, the
// placement puts the drawing where asked, infeasible jobs name the path and the reason.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/safety.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

double pointSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double distanceToStroke(const Vec2& p, const std::vector<Vec2>& s) {
  double best = (p - s[0]).norm();
  for (size_t i = 0; i + 1 < s.size(); ++i) best = std::min(best, pointSegment(p, s[i], s[i + 1]));
  return best;
}

// A work-frame drawing: two layers of random circles and zig-zags, about 80 x 60 mm.
Drawing randomDrawing(std::mt19937_64& rng, int paths) {
  std::uniform_real_distribution<double> x(0, 80), y(0, 60), r(2, 12), u(0, 1);
  Drawing d;
  d.source = "random.svg";
  d.layers.resize(2);
  d.layers[0].id = d.layers[0].name = "ink";
  d.layers[1].id = d.layers[1].name = "red";
  d.layers[1].tool.pauseBefore = true;
  d.layers[1].tool.drawSpeedMmPerS = 15.0;
  for (int i = 0; i < paths; ++i) {
    Polyline pl;
    const Vec2 c(x(rng), y(rng));
    if (u(rng) < 0.5) {
      const double rad = std::min({r(rng), c.x(), 80 - c.x(), c.y(), 60 - c.y()}) + 0.5;
      for (int k = 0; k < 64; ++k)
        pl.points.emplace_back(c + rad * Vec2(std::cos(k * kPi / 32), std::sin(k * kPi / 32)));
      pl.closed = true;
    } else {
      for (int k = 0; k < 5; ++k) pl.points.emplace_back(x(rng), y(rng));
    }
    d.layers[static_cast<size_t>(i % 2)].paths.push_back(pl);
  }
  return d;
}

PlanOptions atOptions() {
  PlanOptions o;
  o.atMm = Vec2(0, 170);
  o.toleranceMm = 0.1;
  return o;
}

class PlannerTest : public ::testing::Test {
 protected:
  MachineProfile p = *preset("maker-plotter");
};

TEST_F(PlannerTest, DrawMovesStayWithinToleranceAndFeedsWithinLimits) {
  auto rng = test::rng();
  Drawing d = randomDrawing(rng, 16);
  d.flatteningToleranceMm = 0.04;  // as if imported at the flattening share, every path a curve
  for (Layer& l : d.layers)
    for (Polyline& line : l.paths) line.flattened = true;
  PlanOptions o = atOptions();
  o.optimise = false;  // keep stroke order = placement order to compare with placeDrawing
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  const std::vector<Stroke> strokes = placeDrawing(d, Placement{*o.atMm, 0.0, 1.0});
  const double budget = o.toleranceMm - d.flatteningToleranceMm;
  JointAngles at = r.job.start;
  int draws = 0;
  for (const JobMove& m : r.job.moves) {
    if (m.kind == JobMoveKind::Draw) {
      ++draws;
      // The targets are the angles the G-code carries (4 decimals of a degree): the curve
      // sampled below is the one the machine is sent.
      for (const double q : {m.target.theta1, m.target.theta2})
        EXPECT_NEAR(degFromRad(q) * 1e4, std::nearbyint(degFromRad(q) * 1e4), 1e-6);
      const auto& stroke = strokes[static_cast<size_t>(m.strokeIndex)].points;
      for (int i = 0; i <= 100; ++i) {
        const double u = i / 100.0;
        const FkResult fk = forward(p.geometry, {at.theta1 + u * (m.target.theta1 - at.theta1),
                                                 at.theta2 + u * (m.target.theta2 - at.theta2)},
                                    p.assembly);
        ASSERT_TRUE(fk.ok());
        EXPECT_LE(distanceToStroke(fk.p, stroke), budget);
      }
    }
    if (isMotion(m.kind)) {
      const double t = m.durationS;
      ASSERT_GT(t, 0.0);
      // The GRBL-timed duration is at least the cruise one, so motor speeds stay below limits.
      // GRBL plans the step-rounded move (time_estimate.cpp, StepGrid): up to one step per
      // motor shorter or longer than the exact one.
      const double step1 = radFromDeg(1.0 / p.motors.stepsPerDeg1);
      const double step2 = radFromDeg(1.0 / p.motors.stepsPerDeg2);
      EXPECT_LE(std::abs(m.target.theta1 - at.theta1) - step1,
                p.motors.maxSpeedRadPerS1 * t * (1 + 1e-9));
      EXPECT_LE(std::abs(m.target.theta2 - at.theta2) - step2,
                p.motors.maxSpeedRadPerS2 * t * (1 + 1e-9));
      const double dq = std::hypot(m.target.theta1 - at.theta1, m.target.theta2 - at.theta2);
      EXPECT_LE((dq - std::hypot(step1, step2)) / m.jointFeedRadPerS, t * (1 + 1e-9));
      at = m.target;
    }
  }
  EXPECT_EQ(draws, r.report.segments);
  EXPECT_LE(r.report.jointDeviationMm, budget);
  // The reported deviation counts every source: the moves (G-code rounding measured in them) and
  // the flattening.
  EXPECT_NEAR(r.report.maxDeviationMm, r.report.jointDeviationMm + 0.04, 1e-12);
  EXPECT_EQ(r.report.roundingMm, 0.0);
  EXPECT_LE(r.report.maxDeviationMm, o.toleranceMm);
  EXPECT_NEAR(at.theta1, r.job.start.theta1, 1e-12);  // ends where it started
  EXPECT_GT(r.report.estimatedTimeS, 0.0);
}

TEST_F(PlannerTest, ToolSequenceIsConsistentAndTravelsAreSafe) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 12);
  const PlanResult r = planJob(d, p, atOptions());
  ASSERT_TRUE(r.ok()) << r.message;
  bool down = false;
  int pauses = 0;
  JointAngles at = r.job.start;
  for (const JobMove& m : r.job.moves) {
    switch (m.kind) {
      case JobMoveKind::PenDown: EXPECT_FALSE(down); down = true; break;
      case JobMoveKind::PenUp: EXPECT_TRUE(down); down = false; break;
      case JobMoveKind::Draw: EXPECT_TRUE(down); break;
      case JobMoveKind::Travel:
        EXPECT_FALSE(down);
        EXPECT_TRUE(checkJointMove(p, at, m.target).ok());
        break;
      case JobMoveKind::Pause: EXPECT_FALSE(down); ++pauses; break;
      case JobMoveKind::Dwell: break;
    }
    if (isMotion(m.kind)) at = m.target;
  }
  EXPECT_FALSE(down);
  EXPECT_GE(pauses, 1);  // the second layer asks for a pen change
  // Layer speed override: the red layer draws at most 15 mm/s.
  for (const JobMove& m : r.job.moves)
    if (m.kind == JobMoveKind::Draw && m.layerIndex == 1) {
      EXPECT_LE(m.feedMmPerS, 15.0 * (1 + 1e-9));
    }
}

TEST_F(PlannerTest, AtPutsTheBoundingBoxCentreThere) {
  Drawing d;
  d.layers.resize(1);
  d.layers[0].paths.push_back({{{0, 0}, {40, 0}, {40, 20}}, false});
  PlanOptions o = atOptions();
  o.atMm = Vec2(10, 160);
  o.scale = 0.5;
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  // bbox 40 x 20 centred at (20, 10): at half scale (0,0) -> (0, 155), (40,20) -> (20, 165).
  Vec2 first = Vec2::Constant(1e9), last = first;
  for (const JobMove& m : r.job.moves) {
    if (m.kind == JobMoveKind::PenDown && first.x() == 1e9) first = m.targetXY;
    if (m.kind == JobMoveKind::Draw) last = m.targetXY;
  }
  // The pen goes down where the G-code's rounded angles put it.
  EXPECT_LT((first - Vec2(0, 155)).norm(), gcodeRoundingBoundMm(p));
  EXPECT_LT((last - Vec2(20, 165)).norm(), 1e-6);
  EXPECT_NEAR(r.report.penDownMm, 0.5 * 60.0, 1e-6);
}

TEST_F(PlannerTest, FitWithoutAtStaysInTheSingularityFreeRegion) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 8);  // flatteningToleranceMm 0: the fit may enlarge it
  PlanOptions o;
  o.fit = true;
  const PlanResult r = planJob(d, p, o);
  EXPECT_GT(r.placementScale, 1.0);  // 80 x 60 mm fitted into maker-plotter's rectangle
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GE(r.report.minSingularityMarginDeg, degFromRad(p.typeIIMarginRad) - 1e-9);
}

TEST_F(PlannerTest, EveryDrawAndTravelMovePassesTheSafetyCheck) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 12);
  PlanOptions o;
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  JointAngles at = r.job.start;
  double smallest = kPi;
  for (const JobMove& m : r.job.moves) {
    if (!isMotion(m.kind)) continue;
    const MoveCheck c = checkJointMove(p, at, m.target);
    ASSERT_TRUE(c.ok()) << toString(m.kind) << " move: " << describe(c);
    smallest = std::min(smallest, c.minTypeIIMarginRad);
    at = m.target;
  }
  // The reported margin is that of the moves sent (refined to 0.1 deg of joint motion).
  EXPECT_NEAR(r.report.minSingularityMarginDeg, degFromRad(smallest), 0.2);
}

TEST_F(PlannerTest, AutoPicksTheFeasibleModeWithTheLargestMargin) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 6);
  PlanOptions o;
  const PlanResult autoPlan = planJob(d, p, o);
  ASSERT_TRUE(autoPlan.ok()) << autoPlan.message;
  double best = -1.0;
  WorkingMode bestMode = WorkingMode::PlusPlus;
  for (WorkingMode m : kAllWorkingModes) {
    PlanOptions one = o;
    one.mode = m;
    const PlanResult r = planJob(d, p, one);
    if (r.ok() && r.report.minSingularityMarginDeg > best)
      best = r.report.minSingularityMarginDeg, bestMode = m;
  }
  EXPECT_EQ(autoPlan.report.mode, bestMode);
  EXPECT_DOUBLE_EQ(autoPlan.report.minSingularityMarginDeg, best);
}

TEST_F(PlannerTest, TheSameDrawingAlwaysGivesTheSameJob) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 60);  // enough strokes for the 2-opt to work
  PlanOptions o;
  const PlanResult a = planJob(d, p, o), b = planJob(d, p, o);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  ASSERT_EQ(a.job.moves.size(), b.job.moves.size());
  for (size_t i = 0; i < a.job.moves.size(); ++i) {
    ASSERT_EQ(a.job.moves[i].kind, b.job.moves[i].kind) << i;
    ASSERT_EQ(a.job.moves[i].target.theta1, b.job.moves[i].target.theta1) << i;
    ASSERT_EQ(a.job.moves[i].target.theta2, b.job.moves[i].target.theta2) << i;
  }
}

TEST_F(PlannerTest, TrueSizeByDefaultEnlargingOnlyWithFit) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 6);  // about 80 x 60 mm: fits maker-plotter at 100 %
  PlanOptions o;
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(r.placementScale, 1.0);
  EXPECT_TRUE(r.placementNote.empty()) << r.placementNote;
  o.fit = true;
  const PlanResult fitted = planJob(d, p, o);
  ASSERT_TRUE(fitted.ok()) << fitted.message;
  EXPECT_GT(fitted.placementScale, 1.5);
  // The placement planJob chose, given as a fixed placement, gives the same job.
  PlanOptions fixedAt;
  setFixedPlacement(fixedAt, r.placement);
  const PlanResult again = planJob(d, p, fixedAt);
  ASSERT_TRUE(again.ok()) << again.message;
  ASSERT_EQ(again.job.moves.size(), r.job.moves.size());
  for (size_t i = 0; i < r.job.moves.size(); ++i)
    ASSERT_EQ(again.job.moves[i].target.theta1, r.job.moves[i].target.theta1) << i;
}

TEST_F(PlannerTest, ADrawingTooBigIsScaledDownAndSaysSo) {
  Drawing d;
  d.layers.resize(1);
  d.layers[0].paths.push_back({{{0, 0}, {2000, 0}, {2000, 1000}, {0, 1000}}, true});
  const PlanResult r = planJob(d, p, PlanOptions{});
  EXPECT_LT(r.placementScale, 1.0);
  EXPECT_NE(r.placementNote.text().find("% to fit the workspace"), std::string::npos) << r.placementNote;
  EXPECT_EQ(r.placementNote.text().find("scaled to "), 0u) << r.placementNote;
}

TEST_F(PlannerTest, ACoarseDrawingAsksForAFinerImport) {
  auto rng = test::rng();
  Drawing d = randomDrawing(rng, 6);
  d.flatteningToleranceMm = 0.04;  // fine at 100 % with 0.1 mm
  d.layers[0].paths[0].flattened = true;  // one curve is enough to need the finer import
  PlanOptions o = atOptions();
  o.scale = 2.0;                   // 0.08 mm at twice the size: too coarse
  const PlanResult r = planJob(d, p, o);
  EXPECT_EQ(r.status, PlanStatus::CoarseDrawing);
  EXPECT_DOUBLE_EQ(r.requiredFlatteningToleranceMm, 0.02);
  EXPECT_NE(r.message.text().find("import it again"), std::string::npos) << r.message;
  d.flatteningToleranceMm = r.requiredFlatteningToleranceMm;
  EXPECT_TRUE(planJob(d, p, o).ok());
}

TEST_F(PlannerTest, ACancelledPlanStops) {
  auto rng = test::rng();
  const Drawing d = randomDrawing(rng, 20);
  std::atomic<bool> cancel{true};
  PlanOptions o = atOptions();
  o.cancel = &cancel;
  const PlanResult r = planJob(d, p, o);
  EXPECT_EQ(r.status, PlanStatus::Cancelled);
  EXPECT_TRUE(r.job.moves.empty());
}

TEST_F(PlannerTest, AFittedDiagonalLinePlans) {
  // One straight line corner to corner, fitted: split into pieces up to its very end.
  Drawing d;
  d.source = "line.svg";
  d.layers.resize(1);
  d.layers[0].paths.push_back({{Vec2(10, 90), Vec2(90, 10)}, false});
  for (const double tolerance : {0.1, 0.02}) {
    PlanOptions o;
    o.toleranceMm = tolerance;
      const PlanResult r = planJob(d, p, o);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_LE(r.report.maxDeviationMm, tolerance);
  }
  // A tolerance below the G-code rounding is the options' fault, fitted or not.
  PlanOptions tiny;
  tiny.toleranceMm = 0.0001;
  const PlanResult r = planJob(d, p, tiny);
  EXPECT_EQ(r.status, PlanStatus::BadOptions);
  EXPECT_NE(r.message.text().find("tolerance"), std::string::npos) << r.message;
}

TEST_F(PlannerTest, InfeasibleJobNamesThePathAndTheReason) {
  Drawing d;
  d.layers.resize(1);
  d.layers[0].name = "ink";
  d.layers[0].paths.push_back({{{-5, 0}, {5, 0}}, false});       // at the centre: fine
  d.layers[0].paths.push_back({{{-300, 0}, {-290, 0}}, false});  // far out of reach
  d.layers[0].paths.push_back({{{290, 0}, {300, 0}}, false});
  PlanOptions o = atOptions();
  o.mode = WorkingMode::PlusPlus;
  const PlanResult r = planJob(d, p, o);
  EXPECT_EQ(r.status, PlanStatus::Infeasible);
  EXPECT_NE(r.message.text().find("layer 'ink' path 1"), std::string::npos) << r.message;
  ASSERT_FALSE(r.report.problems.empty());
  EXPECT_FALSE(r.report.problems.front().fixes.empty());
  EXPECT_NE(r.report.problems.front().why.text().find("out of reach"), std::string::npos);
}

// In a working mode other than the home pose's, every travel from and to home must change the
// mode (a leg through full stretch or fold): the advice is the home pose's mode, not moving,
// shrinking or fitting the drawing, which cannot help.
TEST_F(PlannerTest, TravelsFromHomeInAnotherModeAdviseTheHomePosesMode) {
  Drawing d;
  d.layers.resize(1);
  d.layers[0].name = "ink";
  d.layers[0].paths.push_back({{{-5, 0}, {5, 0}, {5, 8}}, false});
  for (WorkingMode mode : {WorkingMode::MinusMinus, WorkingMode::MinusPlus, WorkingMode::PlusMinus}) {
    PlanOptions o = atOptions();
    o.mode = mode;
    const PlanResult r = planJob(d, p, o);
    ASSERT_EQ(r.status, PlanStatus::Infeasible) << toString(mode);
    ASSERT_FALSE(r.report.problems.empty());
    for (const PlanProblem& problem : r.report.problems) {
      ASSERT_FALSE(problem.fixes.empty()) << toString(mode);
      EXPECT_EQ(problem.fixes.front().kind, FixKind::UseMode) << toString(mode) << ": " << problem.why;
      EXPECT_EQ(problem.fixes.front().mode, WorkingMode::PlusPlus) << toString(mode);
      for (const PlanFix& f : problem.fixes) EXPECT_NE(f.kind, FixKind::FitToWorkspace) << toString(mode);
    }
  }
  // The home pose's own mode plans it.
  PlanOptions o = atOptions();
  o.mode = WorkingMode::PlusPlus;
  EXPECT_EQ(planJob(d, p, o).status, PlanStatus::Ok);
}

TEST_F(PlannerTest, EmptyDrawingAndBadToleranceAreRefusedWithAReason) {
  Drawing empty;
  empty.source = "blank.svg";
  const PlanResult a = planJob(empty, p, atOptions());
  EXPECT_EQ(a.status, PlanStatus::EmptyDrawing);
  EXPECT_NE(a.message.text().find("blank.svg"), std::string::npos);
  Drawing d;
  d.layers.resize(1);
  d.layers[0].paths.push_back({{{0, 0}, {10, 0}}, false});
  PlanOptions o = atOptions();
  o.toleranceMm = 0.0005;  // below the G-code rounding bound
  const PlanResult b = planJob(d, p, o);
  EXPECT_EQ(b.status, PlanStatus::BadOptions);
  EXPECT_NE(b.message.text().find("tolerance"), std::string::npos);
}

TEST_F(PlannerTest, ReportJsonCarriesTheFigures) {
  auto rng = test::rng();
  const PlanResult r = planJob(randomDrawing(rng, 6), p, atOptions());
  ASSERT_TRUE(r.ok()) << r.message;
  const nlohmann::json j = nlohmann::json::parse(reportToJson(r.report, [](const PlanFix& f) { return std::string(toString(f.kind)); }));
  EXPECT_EQ(j.at("mode").get<std::string>(), std::string(toString(r.report.mode)));
  EXPECT_DOUBLE_EQ(j.at("estimated_time_s").get<double>(), r.report.estimatedTimeS);
  EXPECT_DOUBLE_EQ(j.at("pen_down_mm").get<double>(), r.report.penDownMm);
  EXPECT_DOUBLE_EQ(j.at("travel_mm").get<double>(), r.report.travelMm);
  EXPECT_EQ(j.at("segments").get<int>(), r.report.segments);
  EXPECT_DOUBLE_EQ(j.at("max_deviation_mm").get<double>(), r.report.maxDeviationMm);
  EXPECT_DOUBLE_EQ(j.at("min_singularity_margin").get<double>(), r.report.minSingularityMarginDeg);
  EXPECT_TRUE(j.at("problems").is_array());
}

}  // namespace
}  // namespace fivebar
