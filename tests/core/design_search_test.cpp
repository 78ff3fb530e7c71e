// SPDX-License-Identifier: GPL-3.0-or-later
// core/design search: the issue's goal brief, determinism, impossible briefs, cancel, the
// trade-off set and the profile of a design.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <utility>

#include "core/design/design_json.hpp"
#include "core/design/pareto.hpp"
#include "core/design/placement.hpp"
#include "core/design/search.hpp"

namespace fivebar::design {
namespace {

DesignBrief goalBrief() {
  DesignBrief b;  // 110 x 90, links <= 200, base <= 250, clearance 10, type II >= 15 deg
  b.widthMm = 110.0;
  b.heightMm = 90.0;
  b.bounds.maxLinkMm = 200.0;
  b.bounds.maxBaseMm = 250.0;
  b.rules.clearanceMm = 10.0;
  b.rules.workspace.typeIIMarginRad = radFromDeg(15.0);
  return b;
}

// A small budget for the tests that are not about quality.
SearchOptions quick() {
  SearchOptions o;
  o.startsPerMode = 2;
  o.globalEvaluations = 600;
  o.localEvaluations = 300;
  return o;
}

void expectWithinBrief(const Design& d, const DesignBrief& b) {
  const Geometry& g = d.geometry;
  for (double len : {g.a1, g.b1, g.a2, g.b2}) {
    EXPECT_GE(len, b.bounds.minLinkMm - 1e-9);
    EXPECT_LE(len, b.bounds.maxLinkMm + 1e-9);
  }
  EXPECT_LE(g.w, b.bounds.maxBaseMm + 1e-9);
  EXPECT_GE(g.w, g.a1 + g.a2 + b.rules.clearanceMm - 1e-9);  // Hoang criterion 1
  EXPECT_NEAR(d.rect.width(), d.rotated ? b.heightMm : b.widthMm, 1e-9);
  EXPECT_GE(d.rect.yMin, 0.0);
  // Re-evaluated here at a finer sampling than the search's final one.
  const Evaluation fine = evaluateDesign(g, d.mode, d.rect, b.rules, Sampling{0.5});
  EXPECT_TRUE(fine.feasible()) << fine.violations.binding(kViolationScaleMm);
  EXPECT_GE(fine.measures.minTypeIIMarginRad, b.rules.workspace.typeIIMarginRad);
}

TEST(DesignSearch, GoalBriefBeatsTheHoangDesignWithinAMinute) {
  const DesignBrief b = goalBrief();
  const auto t0 = std::chrono::steady_clock::now();
  const SearchResult r = searchDesigns(b);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.status, SearchStatus::Found) << r.message;
  ASSERT_TRUE(r.best);
  EXPECT_LE(r.best->evaluation.measures.worstCondition, 2.2);
  EXPECT_LT(seconds, 60.0);
  expectWithinBrief(*r.best, b);
  const Evaluation fine = evaluateDesign(r.best->geometry, r.best->mode, r.best->rect, b.rules, Sampling{0.5});
  EXPECT_LE(fine.measures.worstCondition, 2.2 * 1.01);
}

TEST(DesignSearch, SymmetricBriefKeepsTheArmsEqual) {
  DesignBrief b = goalBrief();
  b.bounds.symmetric = true;
  b.mode = WorkingMode::PlusPlus;
  const SearchResult r = searchDesigns(b, quick());
  ASSERT_EQ(r.status, SearchStatus::Found) << r.message;
  EXPECT_EQ(r.best->geometry.a1, r.best->geometry.a2);
  EXPECT_EQ(r.best->geometry.b1, r.best->geometry.b2);
  EXPECT_EQ(r.best->mode, WorkingMode::PlusPlus);
  expectWithinBrief(*r.best, b);
}

TEST(DesignSearch, SameSeedSameDesignWhateverTheThreads) {
  DesignBrief b = goalBrief();
  b.mode = WorkingMode::PlusMinus;
  SearchOptions one = quick(), two = quick();
  one.threads = 1;
  two.threads = 2;
  const SearchResult a = searchDesigns(b, one), c = searchDesigns(b, two);
  ASSERT_TRUE(a.best && c.best);
  EXPECT_EQ(a.best->geometry, c.best->geometry);
  EXPECT_EQ(a.best->rect.xMin, c.best->rect.xMin);
  EXPECT_EQ(a.best->rect.yMin, c.best->rect.yMin);
  EXPECT_EQ(a.evaluations, c.evaluations);
  ASSERT_EQ(a.pareto.size(), c.pareto.size());
  for (std::size_t i = 0; i < a.pareto.size(); ++i) EXPECT_EQ(a.pareto[i].geometry, c.pareto[i].geometry);
  // A different seed explores differently (the designs differ in some digit).
  SearchOptions other = quick();
  other.seed = 2;
  const SearchResult d = searchDesigns(b, other);
  ASSERT_TRUE(d.best);
  EXPECT_FALSE(d.best->geometry == a.best->geometry);
}

TEST(DesignSearch, ImpossibleReachNamesTheBindingConstraint) {
  DesignBrief b = goalBrief();
  b.widthMm = 400.0;
  b.heightMm = 300.0;
  b.bounds.maxLinkMm = 100.0;
  const SearchResult r = searchDesigns(b, quick());
  EXPECT_EQ(r.status, SearchStatus::Impossible);
  EXPECT_EQ(r.binding, "reach");
  EXPECT_NE(r.message.find("reach binds"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("--max-link"), std::string::npos) << r.message;
  EXPECT_TRUE(r.pareto.empty());
}

TEST(DesignSearch, ImpossibleClearanceIsFoundWithoutSearching) {
  DesignBrief b = goalBrief();
  b.bounds.minLinkMm = 100.0;
  b.bounds.maxBaseMm = 150.0;  // w >= 100 + 100 + 10 cannot hold
  const SearchResult r = searchDesigns(b, quick());
  EXPECT_EQ(r.status, SearchStatus::Impossible);
  EXPECT_EQ(r.binding, "clearance");
  EXPECT_EQ(r.evaluations, 0);
  EXPECT_NE(r.message.find("w >= 210.0 mm"), std::string::npos) << r.message;
}

TEST(DesignSearch, ImpossibleTypeIIMarginNamesIt) {
  DesignBrief b = goalBrief();
  b.rules.workspace.typeIIMarginRad = radFromDeg(80.0);
  const SearchResult r = searchDesigns(b, quick());
  EXPECT_EQ(r.status, SearchStatus::Impossible);
  EXPECT_EQ(r.binding, "typeII") << r.message;
  EXPECT_NE(r.message.find("type II margin binds"), std::string::npos) << r.message;
}

TEST(DesignSearch, CancelStopsQuickly) {
  std::atomic<bool> cancel{false};
  int calls = 0;
  const auto progress = [&](const SearchProgress& p) {
    ++calls;
    EXPECT_GE(p.fraction, 0.0);
    EXPECT_LE(p.fraction, 1.0);
    if (p.evaluations >= 2048) cancel = true;
  };
  const SearchResult r = searchDesigns(goalBrief(), {}, progress, &cancel);
  EXPECT_EQ(r.status, SearchStatus::Cancelled);
  EXPECT_GT(calls, 0);
  EXPECT_LT(r.evaluations, 20000);
}

TEST(DesignSearch, TradeOffSetIsNonDominatedAndFeasible) {
  const DesignBrief b = goalBrief();
  const SearchResult r = searchDesigns(b, quick());
  ASSERT_EQ(r.status, SearchStatus::Found);
  ASSERT_GE(r.pareto.size(), 3u);
  for (std::size_t i = 0; i < r.pareto.size(); ++i) {
    const DesignMeasures& m = r.pareto[i].evaluation.measures;
    EXPECT_TRUE(r.pareto[i].evaluation.feasible());
    if (i > 0) {  // sorted by footprint, so the condition number falls
      const DesignMeasures& prev = r.pareto[i - 1].evaluation.measures;
      EXPECT_GT(m.footprintMm2, prev.footprintMm2);
      EXPECT_LT(m.worstCondition, prev.worstCondition);
    }
  }
}

TEST(DesignPareto, ArchiveKeepsOnlyNonDominatedPoints) {
  ParetoArchive<int> a;
  EXPECT_TRUE(a.insert(3.0, 1.0, 0));
  EXPECT_TRUE(a.insert(1.0, 3.0, 1));
  EXPECT_FALSE(a.insert(3.5, 3.5, 2));  // dominated
  EXPECT_TRUE(a.insert(2.0, 2.0, 3));
  EXPECT_TRUE(a.insert(0.5, 0.5, 4));   // dominates all
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a.points()[0].payload, 4);
  const auto idx = spreadIndices({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, 4);
  ASSERT_EQ(idx.size(), 4u);
  EXPECT_EQ(idx.front(), 0u);
  EXPECT_EQ(idx.back(), 9u);
}

TEST(DesignProfile, IsCompleteValidAndRoundTrips) {
  const DesignBrief b = goalBrief();
  const SearchResult r = searchDesigns(b, quick());
  ASSERT_TRUE(r.best);
  const MachineProfile p = designProfile(*r.best, b, "design-test");
  EXPECT_TRUE(validate(p).empty());
  EXPECT_EQ(p.geometry, r.best->geometry);
  EXPECT_EQ(p.defaultMode, r.best->mode);
  const ProfileLoad back = profileFromJson(toJson(p), "design-test.json");
  ASSERT_TRUE(back.profile) << (back.issues.empty() ? "" : back.issues[0].message);
  EXPECT_EQ(back.profile->geometry, p.geometry);
  // Every sample of the rectangle is reachable within the profile's joint limits.
  WorkspaceSettings s = workspaceSettings(p);
  for (const Vec2& q : rectangleSamples(r.best->rect, 5.0))
    EXPECT_TRUE(evaluatePoint(p.geometry, s, p.defaultMode, q).reachable) << q.transpose();
  const nlohmann::json j = searchJson(b, r, quick());
  EXPECT_EQ(j["geometry"]["a1"].get<double>(), r.best->geometry.a1);
  EXPECT_EQ(j["workingMode"].get<std::string>(), std::string(toString(r.best->mode)));
  EXPECT_EQ(j["rectangle"]["xMinMm"].get<double>(), r.best->rect.xMin);
  EXPECT_EQ(j["pareto"]["designs"].size(), r.pareto.size());
}

// The weighted mix (docs/design.md "Mix"): a weight on one term alone ranks designs exactly as
// that term's own objective does, so the search finds the same design.
TEST(DesignMix, OneWeightGivesThatObjectivesDesign) {
  struct Case {
    Objective single;
    MixWeights weights;
  };
  for (const Case& c : {Case{Objective::Condition, {1.0, 0.0, 0.0}},
                        Case{Objective::Footprint, {0.0, 0.0, 2.5}}}) {
    DesignBrief single = goalBrief();
    single.mode = WorkingMode::PlusMinus;
    single.objective = c.single;
    DesignBrief mix = single;
    mix.objective = Objective::Mix;
    mix.weights = c.weights;
    const SearchResult a = searchDesigns(single, quick()), b = searchDesigns(mix, quick());
    ASSERT_TRUE(a.best && b.best) << toString(c.single);
    const Geometry &ga = a.best->geometry, &gb = b.best->geometry;
    for (auto [x, y] : {std::pair{ga.a1, gb.a1}, {ga.b1, gb.b1}, {ga.a2, gb.a2}, {ga.b2, gb.b2}, {ga.w, gb.w}})
      EXPECT_NEAR(x, y, 1e-6) << toString(c.single);
    EXPECT_NEAR(a.best->rect.xMin, b.best->rect.xMin, 1e-6);
    EXPECT_NEAR(a.best->rect.yMin, b.best->rect.yMin, 1e-6);
  }
}

TEST(DesignMix, FootprintWeightTradesConditionForASmallerMachine) {
  DesignBrief cond = goalBrief();
  cond.mode = WorkingMode::PlusMinus;
  DesignBrief mix = cond;
  mix.objective = Objective::Mix;
  mix.weights = {1.0, 0.0, 1.0};
  const SearchResult a = searchDesigns(cond, quick()), b = searchDesigns(mix, quick());
  ASSERT_EQ(a.status, SearchStatus::Found);
  ASSERT_EQ(b.status, SearchStatus::Found);
  const DesignMeasures &ma = a.best->evaluation.measures, &mb = b.best->evaluation.measures;
  EXPECT_LT(mb.footprintMm2, 0.9 * ma.footprintMm2);
  EXPECT_GT(mb.worstCondition, ma.worstCondition);
  // The mix's own score is better for the mix's design than for the condition design.
  EXPECT_LT(objectiveValue(Objective::Mix, mb, mix.weights), objectiveValue(Objective::Mix, ma, mix.weights));
  expectWithinBrief(*b.best, mix);
}

TEST(DesignMix, TermsAreNormalisedAndWeightsValidated) {
  const Geometry g{70, 200, 70, 200, 250};
  const DesignRules rules;
  const Evaluation e = evaluateDesign(g, WorkingMode::PlusPlus, centredRect(0.0, 155.0, 110, 90), rules);
  const DesignMeasures& m = e.measures;
  EXPECT_DOUBLE_EQ(m.rectangleAreaMm2, 110.0 * 90.0);
  EXPECT_DOUBLE_EQ(normalisedFootprint(m), m.footprintMm2 / (110.0 * 90.0));
  EXPECT_GE(normalisedFootprint(m), 1.0);
  EXPECT_DOUBLE_EQ(normalisedResolution(m), m.worstMmPerStep / (rules.workspace.stepRad1 * std::sqrt(110.0 * 90.0)));
  EXPECT_DOUBLE_EQ(objectiveValue(Objective::Mix, m, {2.0, 0.0, 0.0}), 2.0 * m.worstCondition);
  EXPECT_DOUBLE_EQ(objectiveValue(Objective::Mix, m, {1.0, 1.0, 1.0}),
                   normalisedCondition(m) + normalisedResolution(m) + normalisedFootprint(m));
  DesignBrief b = goalBrief();
  b.objective = Objective::Mix;
  b.weights = {0.0, 0.0, 0.0};
  auto issues = validate(b);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "weights");
  b.weights = {1.0, -1.0, 0.0};
  EXPECT_EQ(validate(b).size(), 1u);
  b.objective = Objective::Condition;  // weights are the mix's only
  EXPECT_TRUE(validate(b).empty());
  EXPECT_EQ(parseObjective("mix"), Objective::Mix);
}

// The placement alone: one weight on resolution places the rectangle like the resolution
// objective; rotation is tried when allowed and reported.
TEST(DesignMix, PlacementWithOneWeightMatchesItsObjective) {
  const Geometry g{70, 200, 70, 200, 250};
  const DesignRules rules;
  PlacementOptions single, mix;
  single.objective = Objective::Resolution;
  mix.objective = Objective::Mix;
  mix.weights = {0.0, 1.0, 0.0};
  const Placement a = bestPlacement(g, WorkingMode::PlusPlus, 100.0, 60.0, rules, single);
  const Placement b = bestPlacement(g, WorkingMode::PlusPlus, 100.0, 60.0, rules, mix);
  EXPECT_NEAR(a.rect.xMin, b.rect.xMin, 1e-6);
  EXPECT_NEAR(a.rect.yMin, b.rect.yMin, 1e-6);
}

}  // namespace
}  // namespace fivebar::design
