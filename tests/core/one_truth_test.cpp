// SPDX-License-Identifier: GPL-3.0-or-later
// One truth in core: the placement rule (true size, A5 on maker-plotter stays 100 %), the same
// job whatever the load (no wall-clock budget anywhere), the tolerance spent rather than
// reserved (at least 8x fewer pen-down moves than firmware-style segmentation on straight lines),
// and the project file round trip with its error messages.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <random>
#include <thread>

#include "core/output/gcode.hpp"
#include "core/planning/auto_placement.hpp"
#include "core/planning/hatch.hpp"
#include "core/planning/planner.hpp"
#include "core/project/project.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

MachineProfile makerPlotter() { return *preset("maker-plotter"); }

Drawing page(double widthMm, double heightMm) {
  Drawing d;
  d.source = "page.svg";
  d.widthMm = widthMm;
  d.heightMm = heightMm;
  d.layers.resize(1);
  d.layers[0].id = d.layers[0].name = "frame";
  d.layers[0].paths.push_back({{{0, 0}, {widthMm, 0}, {widthMm, heightMm}, {0, heightMm}}, true});
  Polyline curve;
  for (int k = 0; k <= 90; ++k) {
    const double t = k * kPi / 45.0;
    curve.points.emplace_back(0.5 * widthMm + 0.3 * widthMm * std::cos(t),
                              0.5 * heightMm + 0.3 * heightMm * std::sin(3 * t));
  }
  d.layers[0].paths.push_back(curve);
  return d;
}

// Random straight lines, about 80 x 60 mm, the polylines exact (flattening 0).
Drawing randomLines(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> x(0, 80), y(0, 60);
  Drawing d;
  d.source = "lines.svg";
  d.layers.resize(1);
  d.layers[0].id = d.layers[0].name = "lines";
  for (int i = 0; i < n; ++i) d.layers[0].paths.push_back({{{x(rng), y(rng)}, {x(rng), y(rng)}}, false});
  return d;
}

TEST(OneTruth, A5OnTheMakerPlotterStaysAtTrueSize) {
  const MachineProfile p = makerPlotter();
  // A5 landscape, the sheet the maker plotter is designed for (docs/profile-schema.md).
  const auto placed = autoPlacement(page(210, 148), p, std::nullopt, 0.0, PlacementSizing::TrueSize);
  ASSERT_TRUE(placed);
  EXPECT_DOUBLE_EQ(placed->placement.scale, 1.0);
  EXPECT_FALSE(placed->scaledDown);
  EXPECT_EQ(scaleNote(*placed), "");
  EXPECT_GT(placed->fitScale, 1.0);  // it would be enlarged by a fit, and only then
  EXPECT_EQ(placed->placement.centerMm, placed->rectMm.center());
  const PlanResult r = planJob(page(210, 148), p, PlanOptions{});
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(r.placementScale, 1.0);
  // A3 does not fit: scaled down, and said so.
  const auto a3 = autoPlacement(page(297, 420), p, std::nullopt, 0.0, PlacementSizing::TrueSize);
  ASSERT_TRUE(a3);
  EXPECT_TRUE(a3->scaledDown);
  EXPECT_LT(a3->placement.scale, 1.0);
  EXPECT_EQ(scaleNote(*a3).text().rfind("scaled to ", 0), 0u);
}

TEST(OneTruth, TheSameInputGivesByteIdenticalGcodeUnderParallelLoad) {
  auto rng = test::rng();
  const MachineProfile p = makerPlotter();
  Drawing d = randomLines(rng, 3000);  // enough strokes for the 2-opt to run out of its budget
  const std::string reference = writeGcode(planJob(d, p, PlanOptions{}).job, p);
  ASSERT_GT(reference.size(), 1000u);
  // The same plans on every thread at once, with the machine busy besides.
  std::atomic<bool> stop{false};
  std::thread burner([&] {
    volatile double x = 0.0;
    while (!stop) x = x + std::sqrt(x + 1.0);
  });
  std::vector<std::string> out(3);
  std::vector<std::thread> planners;
  for (std::size_t i = 0; i < out.size(); ++i)
    planners.emplace_back([&, i] { out[i] = writeGcode(planJob(d, p, PlanOptions{}).job, p); });
  for (std::thread& t : planners) t.join();
  stop = true;
  burner.join();
  for (const std::string& g : out) EXPECT_TRUE(g == reference) << "G-code differs under load";
}

TEST(OneTruth, TheToleranceIsSpentNotReserved) {
  auto rng = test::rng();
  const MachineProfile p = makerPlotter();
  const Drawing d = randomLines(rng, 200);
  PlanOptions o;
  o.toleranceMm = 0.01;
  o.optimise = false;
  const PlanResult r = planJob(d, p, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_DOUBLE_EQ(r.placementScale, 1.0);
  // Firmware-style segmentation: 200 segments/s at 50 mm/s, none under 0.5 mm.
  const double firmwareLengthMm = std::max(50.0 / 200.0, 0.5);
  long firmware = 0;
  for (const Polyline& l : d.layers[0].paths)
    firmware += static_cast<long>(std::ceil((l.points[1] - l.points[0]).norm() / firmwareLengthMm));
  const double ratio = static_cast<double>(firmware) / r.report.segments;
  std::cout << "firmware-style " << firmware << " moves, planned " << r.report.segments
            << " (ratio " << ratio << "), max deviation " << r.report.maxDeviationMm << " mm\n";
  // The issue's goal: 8x (ErrorBudget checks seeds 1-10 too). Reached by spending the whole
  // budget: no flattening share for straight lines, the G-code rounding measured (moves between
  // rounded angles) instead of reserved, split pieces aimed at 98.5 % of the budget, their
  // waypoints set off the line so that each curve uses both sides of the band (docs/planning.md,
  // "Tolerance budget" and "Offset waypoints").
  EXPECT_GE(ratio, 8.0);
  EXPECT_LE(r.report.maxDeviationMm, o.toleranceMm);
  // Reserving the flattening share as before (0.4 of the tolerance) costs about a third more.
  Drawing reserved = d;
  reserved.flatteningToleranceMm = importToleranceMm(o.toleranceMm);
  for (Polyline& l : reserved.layers[0].paths) l.flattened = true;
  const PlanResult old = planJob(reserved, p, o);
  ASSERT_TRUE(old.ok()) << old.message;
  EXPECT_GT(old.report.segments, 1.2 * r.report.segments);
  EXPECT_EQ(r.report.flatteningMm, 0.0);  // straight lines: nothing spent on flattening
  EXPECT_GT(r.report.jointDeviationMm, 0.7 * o.toleranceMm);  // the budget is used
}

// A drawing of straight lines and flattened curves: each stroke pays for its own flattening only.
TEST(OneTruth, FlatteningIsChargedPerStroke) {
  auto rng = test::rng();
  const MachineProfile p = makerPlotter();
  PlanOptions o;
  o.toleranceMm = 0.01;
  o.optimise = false;
  const Drawing lines = randomLines(rng, 60);
  Drawing mixed = lines;
  mixed.flatteningToleranceMm = 0.003;  // work mm; placed at scale 1
  Drawing curves = mixed;
  for (Polyline& l : curves.layers[0].paths) l.flattened = true;
  mixed.layers[0].paths[7].flattened = true;  // one stroke of curves among straight lines
  const PlanResult straight = planJob(lines, p, o), one = planJob(mixed, p, o), all = planJob(curves, p, o);
  ASSERT_TRUE(straight.ok()) << straight.message;
  ASSERT_TRUE(one.ok()) << one.message;
  ASSERT_TRUE(all.ok()) << all.message;
  // The flattened stroke's error is reported, counted in the bound, and kept within the tolerance.
  EXPECT_EQ(straight.report.flatteningMm, 0.0);
  EXPECT_DOUBLE_EQ(one.report.flatteningMm, 0.003);
  EXPECT_DOUBLE_EQ(all.report.flatteningMm, 0.003);
  for (const PlanResult* r : {&straight, &one, &all}) {
    EXPECT_LE(r->report.maxDeviationMm, o.toleranceMm);
    EXPECT_GE(r->report.maxDeviationMm, r->report.jointDeviationMm + r->report.roundingMm);
  }
  EXPECT_GE(all.report.maxDeviationMm,
            all.report.jointDeviationMm * 0.5 + all.report.flatteningMm + all.report.roundingMm);
  // Only the flattened stroke is cut finer: the straight ones keep the whole budget.
  EXPECT_GT(all.report.segments, one.report.segments);
  EXPECT_GE(one.report.segments, straight.report.segments);
  EXPECT_LT(one.report.segments - straight.report.segments,
            (all.report.segments - straight.report.segments) / 4);
  // A drawing too coarse for its scale is refused only when it holds curves.
  Drawing coarse = lines;
  coarse.flatteningToleranceMm = 0.05;
  EXPECT_TRUE(planJob(coarse, p, o).ok());
  coarse.layers[0].paths[0].flattened = true;
  EXPECT_EQ(planJob(coarse, p, o).status, PlanStatus::CoarseDrawing);
}

Project sampleProject() {
  Project p;
  p.drawingName = "two layers.svg";
  p.drawingSvg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10mm\" height=\"10mm\">\n"
                 "<path d=\"M1 1 L9 9\" stroke=\"#000\"/></svg>\n";
  p.flatteningToleranceMm = 0.04;
  p.solidDashes = true;
  p.placement = Placement{Vec2(3.5, 180.25), 0.5, 0.75, 1.25};
  p.layers = {{"color:#ff0000", "red", false, {12.5, 400.0, true}, FillMode::Hatch, {0.75, 0.5, true, false}},
              {"ink", "ink", true, {}, FillMode::Outline, {}}};
  p.mode = WorkingMode::PlusMinus;
  p.toleranceMm = 0.05;
  p.profile = *preset("hoang2015");
  return p;
}

TEST(OneTruth, ProjectRoundTripKeepsEverything) {
  const Project p = sampleProject();
  const ProjectLoad load = projectFromJson(projectToJson(p), "a.fivebar");
  ASSERT_TRUE(load.project) << load.issues.front().message;
  const Project& q = *load.project;
  EXPECT_EQ(q.drawingName, p.drawingName);
  EXPECT_EQ(q.drawingSvg, p.drawingSvg);
  EXPECT_EQ(q.flatteningToleranceMm, p.flatteningToleranceMm);
  EXPECT_TRUE(q.solidDashes) << "the studio's 'draw dashed strokes solid' is the project's";
  EXPECT_EQ(q.placement.centerMm, p.placement.centerMm);
  EXPECT_NEAR(q.placement.rotationRad, p.placement.rotationRad, 1e-15);
  EXPECT_EQ(q.placement.scale, p.placement.scale);
  EXPECT_EQ(q.placement.stretchY, p.placement.stretchY);
  ASSERT_EQ(q.layers.size(), 2u);
  EXPECT_EQ(q.layers[0].id, "color:#ff0000");
  EXPECT_FALSE(q.layers[0].visible);
  EXPECT_EQ(q.layers[0].tool.drawSpeedMmPerS, 12.5);
  EXPECT_EQ(q.layers[0].tool.power, 400.0);
  EXPECT_TRUE(q.layers[0].tool.pauseBefore);
  EXPECT_EQ(q.layers[0].fill, FillMode::Hatch);
  EXPECT_EQ(q.layers[0].hatch.spacingMm, 0.75);
  EXPECT_NEAR(q.layers[0].hatch.angleRad, 0.5, 1e-15);
  EXPECT_TRUE(q.layers[0].hatch.crosshatch);
  EXPECT_FALSE(q.layers[0].hatch.outline);
  EXPECT_EQ(q.layers[1].fill, FillMode::Outline);
  EXPECT_EQ(q.mode, p.mode);
  EXPECT_EQ(q.toleranceMm, p.toleranceMm);
  EXPECT_EQ(toJson(q.profile), toJson(p.profile));
  EXPECT_EQ(projectToJson(q), projectToJson(p));  // stable text
}

TEST(OneTruth, BadProjectsNameTheField) {
  auto issueOf = [](const std::string& text) {
    const ProjectLoad l = projectFromJson(text, "bad.fivebar");
    EXPECT_FALSE(l.project);
    return l.issues.empty() ? std::string() : l.issues.front().field + ": " + l.issues.front().message.text();
  };
  EXPECT_NE(issueOf("{ not json").find("bad.fivebar:1:"), std::string::npos);
  std::string text = projectToJson(sampleProject());
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  EXPECT_NE(issueOf(replace("\"version\": 2", "\"version\": 99")).find("version 99 is not supported"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"mode\": \"hatch\"", "\"mode\": \"solid\"")).find("layers[0].fill.mode"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"hatch_spacing_mm\": 0.75", "\"hatch_spacing_mm\": 0")).find("layers[0].fill"),
            std::string::npos);
  EXPECT_NE(issueOf(replace("\"scale\": 0.75", "\"scale\": -1")).find("placement.scale"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"mode\": \"+-\"", "\"mode\": \"sideways\"")).find("mode must be"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"a1\": 70.0", "\"a1\": \"long\"")).find("machine.geometry.a1"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"tolerance_mm\"", "\"tolerance_mn\"")).find("tolerance_mn"), std::string::npos);
  EXPECT_NE(issueOf(replace("\"dashes\": \"solid\"", "\"dashes\": \"dotted\"")).find("drawing.dashes"), std::string::npos);
}

// A version 1 project (before layer fills) loads, its layers drawn with outline fills.
TEST(OneTruth, AVersionOneProjectLoadsWithOutlineFills) {
  std::string text = projectToJson(sampleProject());
  const auto cut = [&](const std::string& from, const std::string& to) {
    const std::size_t a = text.find(from);
    ASSERT_NE(a, std::string::npos) << from;
    text.replace(a, to.size(), to);
  };
  cut("\"version\": 2", "\"version\": 1");
  // Drop every "fill" member (the first of its layer object: keys are written sorted).
  for (std::size_t at = text.find("\"fill\": {"); at != std::string::npos; at = text.find("\"fill\": {")) {
    std::size_t stop = text.find('}', at) + 1;
    if (stop < text.size() && text[stop] == ',') ++stop;
    while (stop < text.size() && std::isspace(static_cast<unsigned char>(text[stop]))) ++stop;
    text.erase(at, stop - at);
  }
  ASSERT_EQ(text.find("\"fill\""), std::string::npos) << text;
  const ProjectLoad load = projectFromJson(text, "old.fivebar");
  ASSERT_TRUE(load.project) << load.issues.front().message;
  EXPECT_EQ(load.project->layers[0].fill, FillMode::Outline);
  EXPECT_FALSE(load.project->layers[0].visible);  // the rest as saved
}

// A project written before dashes were drawn has no "dashes": its dashed strokes are drawn dashed.
TEST(OneTruth, AProjectWithoutDashesDrawsThemDashed) {
  std::string text = projectToJson(sampleProject());
  const std::string member = "\"dashes\": \"solid\",";
  const std::size_t at = text.find(member);
  ASSERT_NE(at, std::string::npos) << text.substr(0, 400);
  text.erase(at, member.size());
  const ProjectLoad load = projectFromJson(text, "old.fivebar");
  ASSERT_TRUE(load.project) << load.issues.front().message;
  EXPECT_FALSE(load.project->solidDashes);
}

// The single-stroke font SVG text is redrawn in (docs/text.md) is the project's; absent, the
// text keeps its outlines, and a project without one writes no "text_font".
TEST(OneTruth, AProjectKeepsTheFontItsTextIsRedrawnIn) {
  Project p = sampleProject();
  EXPECT_EQ(projectToJson(p).find("text_font"), std::string::npos);
  const ProjectLoad plain = projectFromJson(projectToJson(p), "plain.fivebar");
  ASSERT_TRUE(plain.project);
  EXPECT_EQ(plain.project->textFont, "");
  p.textFont = "scripts";
  const ProjectLoad load = projectFromJson(projectToJson(p), "text.fivebar");
  ASSERT_TRUE(load.project) << load.issues.front().message;
  EXPECT_EQ(load.project->textFont, "scripts");
}

// A layer's fill is applied where the drawing is placed: hatch lines for that layer only.
TEST(OneTruth, EachLayerIsPlacedWithItsOwnFill) {
  Drawing d;
  d.layers.resize(2);
  for (Layer& l : d.layers) {
    Polyline square{{Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)}, true};
    square.fill = FillRule::NonZero;
    square.fillStart = true;
    l.paths.push_back(square);
  }
  d.layers[1].paths[0].points = {Vec2(20, 0), Vec2(30, 0), Vec2(30, 10), Vec2(20, 10)};
  d.layers[1].fill = FillMode::Hatch;
  d.layers[1].hatch.spacingMm = 1.0;
  const std::vector<Stroke> strokes = placeDrawing(d, Placement{Vec2(0, 150), 0.0, 1.0});
  int first = 0, second = 0;
  for (const Stroke& s : strokes) (s.layerIndex == 0 ? first : second) += 1;
  EXPECT_EQ(first, 1);   // the outline alone
  EXPECT_GT(second, 1);  // the outline and its hatch lines (boustrophedon: few strokes)
  std::size_t hatchPoints = 0;
  for (const Polyline& l : filledPaths(d.layers[1])) hatchPoints += l.points.size();
  EXPECT_GE(hatchPoints, 4u + 2u * 9u);  // 9 or 10 lines of two ends each, plus the square
  d.layers[1].fill = FillMode::None;  // stroked shape: its outline stays
  EXPECT_EQ(placeDrawing(d, Placement{Vec2(0, 150), 0.0, 1.0}).size(), 2u);
}

TEST(OneTruth, LayerStatesFollowTheProjectOrder) {
  Drawing d;
  d.layers.resize(3);
  d.layers[0].id = "a";
  d.layers[1].id = "b";
  d.layers[2].id = "c";
  applyLayerStates(d, {{"c", "", false, {}, FillMode::Outline, {}},
                       {"a", "", true, {5.0, -1.0, false}, FillMode::Hatch, {}}});
  ASSERT_EQ(d.layers.size(), 3u);
  EXPECT_EQ(d.layers[0].id, "c");
  EXPECT_FALSE(d.layers[0].visible);
  EXPECT_EQ(d.layers[1].id, "a");
  EXPECT_EQ(d.layers[1].tool.drawSpeedMmPerS, 5.0);
  EXPECT_EQ(d.layers[1].fill, FillMode::Hatch);
  EXPECT_EQ(d.layers[2].id, "b");  // not named by the project: after, in its own order
}

}  // namespace
}  // namespace fivebar
