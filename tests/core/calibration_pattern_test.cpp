// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration pattern (core/calibration/pattern.hpp), MARKS.csv / MEASURED.csv, and the
// accuracy pattern's figures.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/calibration/accuracy_pattern.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/pattern.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/calibration/stroke_digits.hpp"
#include "core/output/fixed_decimal.hpp"
#include "core/output/gcode.hpp"
#include "core/planning/safety.hpp"
#include "core/workspace/workspace.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

const CalibrationPattern& makerPattern() {
  static const CalibrationPattern p = [] {
    const PatternResult r = makeCalibrationPattern(*preset("maker-plotter"));
    EXPECT_TRUE(r.pattern) << r.error;
    return *r.pattern;
  }();
  return p;
}

TEST(CalibrationPattern, MarksAreSafeSpreadAndNumbered) {
  const MachineProfile p = *preset("maker-plotter");
  const CalibrationPattern& pat = makerPattern();
  int grid = 0, backlash = 0;
  for (size_t i = 0; i < pat.marks.size(); ++i) {
    const PatternMark& m = pat.marks[i];
    EXPECT_EQ(m.id, static_cast<int>(i) + 1);
    EXPECT_TRUE(checkPose(p, m.q).ok()) << "mark " << m.id;
    const FkResult fk = forward(p.geometry, m.q, p.assembly);
    ASSERT_TRUE(fk.ok());
    EXPECT_LT((fk.p - m.nominalMm).norm(), 1e-9);
    (m.kind == MarkKind::Grid ? grid : backlash) += 1;
    for (size_t j = 0; j < i; ++j)
      EXPECT_GE((pat.marks[j].nominalMm - m.nominalMm).norm(), 0.99 * PatternOptions{}.minSpacingMm)
          << "marks " << pat.marks[j].id << " and " << m.id;
  }
  EXPECT_EQ(grid, 25);
  EXPECT_EQ(backlash, 12);  // two rows of three per motor
  ASSERT_TRUE(pat.accuracy);
  EXPECT_EQ(pat.accuracy->lines.size(), 10u);
  // No mark (ring and number) touches an accuracy line.
  for (const PatternMark& m : pat.marks)
    for (const AccuracyLine& l : pat.accuracy->lines) {
      const Vec2 d = l.endMm - l.startMm;
      const double t = std::clamp((m.nominalMm - l.startMm).dot(d) / d.squaredNorm(), 0.0, 1.0);
      EXPECT_GT((l.startMm + t * d - m.nominalMm).norm(), PatternOptions{}.clearanceMm) << "mark " << m.id;
    }
  // The edge is included: several marks lie within a few mm of clearance of the safe region's
  // boundary (a point a little further out is not safe).
  const WorkspaceSettings s = workspaceSettings(p);
  int nearEdge = 0;
  for (const PatternMark& m : pat.marks) {
    bool edge = false;
    for (int k = 0; k < 16 && !edge; ++k) {
      const double a = 2.0 * kPi * k / 16;
      const Vec2 q = m.nominalMm + (PatternOptions{}.clearanceMm + 4.0) * Vec2(std::cos(a), std::sin(a));
      const PointSample ps = evaluatePoint(p.geometry, s, p.defaultMode, q);
      edge = !ps.reachable || ps.typeIIMarginRad < p.typeIIMarginRad || ps.typeIMarginRad < p.typeIMarginRad;
    }
    nearEdge += edge ? 1 : 0;
  }
  EXPECT_GE(nearEdge, 8);
}

TEST(CalibrationPattern, RowsReverseOneMotorInTheMiddle) {
  const CalibrationPattern& pat = makerPattern();
  std::map<int, std::vector<PatternMark>> rows;
  for (const PatternMark& m : pat.marks)
    if (m.kind == MarkKind::Backlash) rows[m.group].push_back(m);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& [g, row] : rows) {
    ASSERT_EQ(row.size(), 3u);
    const int k = row[0].motor;
    for (int i = 0; i < 3; ++i) {
      const Approach a = k == 1 ? row[static_cast<size_t>(i)].approach1 : row[static_cast<size_t>(i)].approach2;
      const Approach other = k == 1 ? row[static_cast<size_t>(i)].approach2 : row[static_cast<size_t>(i)].approach1;
      EXPECT_EQ(a, i == 1 ? Approach::Minus : Approach::Plus);
      EXPECT_EQ(other, Approach::Plus);
    }
    // Equal steps of motor k, the other motor fixed.
    const double d01 = k == 1 ? row[1].q.theta1 - row[0].q.theta1 : row[1].q.theta2 - row[0].q.theta2;
    const double d12 = k == 1 ? row[2].q.theta1 - row[1].q.theta1 : row[2].q.theta2 - row[1].q.theta2;
    EXPECT_NEAR(d01, d12, radFromDeg(0.011));
    EXPECT_NEAR(k == 1 ? row[2].q.theta2 - row[0].q.theta2 : row[2].q.theta1 - row[0].q.theta1, 0.0, 1e-12);
  }
}

TEST(CalibrationPattern, NotCongruentToItsMirrorImage) {
  // The scan tells a mirrored sheet from a turned one only when no mirror image of the pattern
  // fits the pattern itself: the best mirrored self-fit leaves marks far off.
  const CalibrationPattern& pat = makerPattern();
  std::vector<Vec2> nominal, mirrored;
  for (const PatternMark& m : pat.marks) {
    nominal.push_back(m.nominalMm);
    mirrored.push_back(Vec2(-m.nominalMm.x(), m.nominalMm.y()));
  }
  // Best correspondence: each mirrored mark to its nearest mark after the (mirror) symmetry.
  std::vector<Vec2> matched;
  double worst = 0.0;
  for (const Vec2& q : mirrored) {
    double best = 1e18;
    for (const Vec2& n : nominal) best = std::min(best, (n - q).norm());
    worst = std::max(worst, best);
  }
  EXPECT_GT(worst, 5.0);
}

// The G-code lines of the pattern: the pose each dot is drawn at is the mark's commanded pose as
// MARKS.csv writes it, reached last with each motor moving in its approach direction.
TEST(CalibrationPattern, GcodeDrawsEachDotAtItsPoseFromItsApproach) {
  const MachineProfile p = *preset("maker-plotter");
  const CalibrationPattern& pat = makerPattern();
  const PlanResult r = planCalibrationPattern(pat, p);
  ASSERT_TRUE(r.ok()) << r.message;
  const std::string gcode = writeGcode(r.job, p);
  std::vector<std::string> lines;
  std::istringstream in(gcode);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto xy = [](const std::string& l) {
    std::istringstream s(l.substr(l.find('X') + 1));
    double x = 0, y = 0;
    s >> x;
    const std::string rest = l.substr(l.find('Y') + 1);
    y = std::stod(rest);
    return std::pair{x, y};
  };
  // Dots: a pen-down not followed by a G1 before the pen-up.
  std::vector<std::pair<double, double>> dots, before;
  for (size_t i = 2; i + 2 < lines.size(); ++i) {
    if (lines[i].rfind("M3 S1000", 0) != 0) continue;
    size_t j = i + 1;
    while (j < lines.size() && lines[j].rfind("G4", 0) == 0) ++j;
    if (lines[j].rfind("M3 S0", 0) != 0 && lines[j].rfind("M5", 0) != 0) continue;
    dots.push_back(xy(lines[i - 1]));
    before.push_back(xy(lines[i - 2]));
  }
  ASSERT_EQ(dots.size(), pat.marks.size());
  const MarksLoad marks = parseMarksCsv(marksCsv(pat), "MARKS.csv");
  ASSERT_TRUE(marks.ok()) << marks.error;
  std::map<std::string, const PatternMark*> byPose;
  for (const MarkRecord& m : marks.marks)
    byPose[fixedDecimal(degFromRad(m.mark.q.theta1), 4) + " " + fixedDecimal(degFromRad(m.mark.q.theta2), 4)] = &m.mark;
  std::set<int> seen;
  for (size_t i = 0; i < dots.size(); ++i) {
    const auto it = byPose.find(fixedDecimal(dots[i].first, 4) + " " + fixedDecimal(dots[i].second, 4));
    ASSERT_NE(it, byPose.end()) << "a dot at X" << dots[i].first << " Y" << dots[i].second << " is no mark's pose";
    const PatternMark& m = *it->second;
    EXPECT_TRUE(seen.insert(m.id).second) << "mark " << m.id << " drawn twice";
    EXPECT_EQ(dots[i].first > before[i].first, m.approach1 == Approach::Plus) << "mark " << m.id;
    EXPECT_EQ(dots[i].second > before[i].second, m.approach2 == Approach::Plus) << "mark " << m.id;
  }
  EXPECT_GT(r.report.estimatedTimeS, 0.0);
}

TEST(CalibrationPattern, OtherPresetsGetAPatternOrAClearReason) {
  for (const std::string& name : presetNames()) {
    const MachineProfile p = *preset(name);
    const PatternResult r = makeCalibrationPattern(p);
    if (!r.pattern) {
      EXPECT_NE(r.error.text().find("marks"), std::string::npos) << name << ": " << r.error;
      continue;
    }
    if (r.pattern->accuracy)  // marks keep off the accuracy lines on every machine
      for (const PatternMark& m : r.pattern->marks)
        for (const AccuracyLine& l : r.pattern->accuracy->lines) {
          const Vec2 d = l.endMm - l.startMm;
          const double t = std::clamp((m.nominalMm - l.startMm).dot(d) / d.squaredNorm(), 0.0, 1.0);
          EXPECT_GT((l.startMm + t * d - m.nominalMm).norm(), PatternOptions{}.clearanceMm) << name << " mark " << m.id;
        }
    const PlanResult plan = planCalibrationPattern(*r.pattern, p);
    // dai2022 (links all equal, a workspace around the motors) is not planned yet: see
    // docs/calibration-pattern.md "Limits"; its failure must still name the problem.
    if (name == "dai2022" && !plan.ok()) {
      EXPECT_FALSE(plan.message.empty());
      continue;
    }
    EXPECT_TRUE(plan.ok()) << name << ": " << plan.message;
  }
}

TEST(CalibrationPattern, SvgHasEveryStroke) {
  const CalibrationPattern& pat = makerPattern();
  const std::string svg = patternSvg(pat);
  size_t polylines = 0, circles = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++polylines;
  for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, pat.marks.size());
  EXPECT_EQ(polylines + circles, pat.strokes.size());
}

TEST(StrokeDigits, EveryDigitHasStrokesInsideItsCell) {
  for (char c = '0'; c <= '9'; ++c) {
    const auto strokes = digitStrokes(std::string(1, c), Vec2(10, 20), 3.0);
    ASSERT_FALSE(strokes.empty()) << c;
    for (const auto& s : strokes)
      for (const Vec2& p : s) {
        EXPECT_GE(p.x(), 10.0 - 1e-12);
        EXPECT_LE(p.x(), 12.0 + 1e-12);
        EXPECT_GE(p.y(), 20.0 - 1e-12);
        EXPECT_LE(p.y(), 23.0 + 1e-12);
      }
  }
  EXPECT_DOUBLE_EQ(digitTextWidthMm("12", 3.0), 5.0);
}

TEST(MarksCsv, RoundTripAndErrorsNameTheLineAndField) {
  const CalibrationPattern& pat = makerPattern();
  const MarksLoad back = parseMarksCsv(marksCsv(pat), "MARKS.csv");
  ASSERT_TRUE(back.ok()) << back.error;
  ASSERT_EQ(back.marks.size(), pat.marks.size());
  for (size_t i = 0; i < pat.marks.size(); ++i) {
    EXPECT_EQ(back.marks[i].mark.id, pat.marks[i].id);
    EXPECT_NEAR(back.marks[i].mark.q.theta1, pat.marks[i].q.theta1, 1e-12);
    EXPECT_EQ(back.marks[i].mark.kind, pat.marks[i].kind);
    EXPECT_EQ(back.marks[i].mark.approach1, pat.marks[i].approach1);
    EXPECT_EQ(back.marks[i].mark.rowIndex, pat.marks[i].rowIndex);
    EXPECT_DOUBLE_EQ(back.marks[i].ringRadiusMm, 2.5);
  }
  const std::string h = std::string(kMarksCsvHeader) + "\n";
  EXPECT_EQ(parseMarksCsv(h + "1,10,abc,0,0,grid,+,+,0,0,2.5\n", "M.csv").error,
            "M.csv:2: theta2_deg: 'abc' is not a number");
  EXPECT_EQ(parseMarksCsv(h + "1,10,20,0,0,grid,+,+,0,0,2.5\n1,1,2,3,4,grid,+,+,0,0,2.5\n", "M.csv").error,
            "M.csv:3: id: duplicate id 1");
  EXPECT_EQ(parseMarksCsv("id,x\n", "M.csv").error.text().rfind("M.csv:1: header must be", 0), 0u);
  EXPECT_EQ(parseMarksCsv(h + "1,10,20,0,0,grid,+,+,0,0\n", "M.csv").error, "M.csv:2: 10 fields, expected 11");
  EXPECT_EQ(parseMarksCsv(h + "1,10,20,0,0,grid,up,+,0,0,2.5\n", "M.csv").error,
            "M.csv:2: approach1: 'up' is not + or -");
  EXPECT_EQ(parseMarksCsv("", "M.csv").error, "M.csv: empty file (expected the header '" + std::string(kMarksCsvHeader) + "')");
  EXPECT_EQ(loadMarksCsv("/nonexistent/M.csv").error, "/nonexistent/M.csv: cannot open the file");

  const std::vector<MeasuredMark> measured{{3, 12.5, -7.25, Vec2(1.5, 2.25)}, {7, 1, 2, Vec2(-3, 4)}};
  const MeasuredLoad m = parseMeasuredCsv(measuredCsv(measured), "MEASURED.csv");
  ASSERT_TRUE(m.ok()) << m.error;
  ASSERT_EQ(m.marks.size(), 2u);
  EXPECT_EQ(m.marks[0].id, 3);
  EXPECT_DOUBLE_EQ(m.marks[0].measuredMm.y(), 2.25);
  EXPECT_EQ(measuredCsv(measured).substr(0, measuredCsv(measured).find('\n')), "id,theta1_deg,theta2_deg,x_mm,y_mm");
}

TEST(RigidFit, RecoversARotationTranslationAndMirror) {
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  std::vector<Vec2> machine;
  for (int i = 0; i < 12; ++i) machine.emplace_back(u(rng), u(rng));
  for (bool mirror : {false, true}) {
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.7).toRotationMatrix() *
                              (mirror ? Eigen::Vector2d(1, -1).asDiagonal().toDenseMatrix() : Eigen::Matrix2d::Identity());
    std::vector<Vec2> paper;
    for (const Vec2& m : machine) paper.push_back(R * m + Vec2(40, -15));
    const auto fit = fitRigid(paper, machine);
    ASSERT_TRUE(fit);
    EXPECT_EQ(fit->mirrored, mirror);
    EXPECT_LT(fit->rmsMm, 1e-9);
    for (size_t i = 0; i < machine.size(); ++i) EXPECT_LT((fit->map(paper[i]) - machine[i]).norm(), 1e-9);
  }
}

TEST(AccuracyFigures, StraightnessAndLengthOfMeasuredLines) {
  // A straight 40 mm line (rotated, in a paper frame), and one bowed by 0.3 mm and 0.5 mm long.
  std::vector<Vec2> straight, bowed;
  const Vec2 u = Vec2(std::cos(0.3), std::sin(0.3)), n(-u.y(), u.x());
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    straight.push_back(Vec2(5, 7) + 40.0 * t * u);
    bowed.push_back(Vec2(5, 20) + 40.5 * t * u + 0.3 * 4.0 * t * (1 - t) * n);
  }
  const auto f = accuracyFigures({straight, bowed});
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->lines[0].straightnessMm, 0.0, 1e-9);
  EXPECT_NEAR(f->lines[0].lengthErrorMm, 0.0, 1e-9);
  // The best-fit line of a parabolic bow of height h sits at 2h/3: largest distance 2h/3.
  EXPECT_NEAR(f->lines[1].straightnessMm, 0.2, 0.01);
  EXPECT_NEAR(f->lines[1].lengthErrorMm, 0.5, 1e-6);
  EXPECT_NEAR(f->maxAbsLengthErrorMm, 0.5, 1e-6);
  EXPECT_FALSE(accuracyFigures({{Vec2(1, 1)}}));
  const AccuracyPattern a = accuracyPatternAt(Vec2(0, 150), Vec2(1, 0));
  ASSERT_EQ(a.lines.size(), 10u);
  EXPECT_DOUBLE_EQ((a.lines[0].endMm - a.lines[0].startMm).norm(), 40.0);
  EXPECT_DOUBLE_EQ((a.lines[1].startMm - a.lines[0].startMm).norm(), 10.0);
}

}  // namespace
}  // namespace fivebar
