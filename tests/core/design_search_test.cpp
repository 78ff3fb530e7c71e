// core/design search: the issue's goal brief, determinism, impossible briefs, cancel, the
// trade-off set and the profile of a design.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>

#include "core/design/design_json.hpp"
#include "core/design/pareto.hpp"
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

}  // namespace
}  // namespace fivebar::design
