// SPDX-License-Identifier: GPL-3.0-or-later
// Hoang's accuracy lines measured in a scan (core/calibration/scan/scan_lines.hpp): synthetic sheets
// painted by QPainter (round pen 0.4 mm) at 300 and 600 dpi, turned, mirrored, blurred and noisy
// (seeded), with lines drawn longer or shorter and bowed as an imperfect machine draws them; each
// line's length and straightness within 0.05 / 0.03 mm of the drawn truth; the lines among the
// marks of the whole calibration sheet; bad input named. Also `fivebar calibrate lines`.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cstdio>
#include <filesystem>

#include "../cli/cli_support.hpp"
#include "core/calibration/scan/scan_lines.hpp"
#include "synthetic_scan.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

// The accuracy lines as an imperfect machine draws them: line i stretched by stretchMm * (i - 4.5)
// and bowed sideways by bowMm * (1 - i / 10) at its middle (a parabola through 41 points).
CalibrationPattern drawnLines(double stretchMm, double bowMm) {
  const AccuracyPattern a = accuracyPatternAt(Vec2(0, 150), Vec2(1, 0));
  CalibrationPattern p;
  for (size_t i = 0; i < a.lines.size(); ++i) {
    const AccuracyLine& l = a.lines[i];
    const Vec2 mid = 0.5 * (l.startMm + l.endMm);
    const Vec2 u = (l.endMm - l.startMm).normalized(), n(-u.y(), u.x());
    const double half = 0.5 * ((l.endMm - l.startMm).norm() + stretchMm * (static_cast<double>(i) - 4.5));
    const double bow = bowMm * (1.0 - static_cast<double>(i) / 10.0);
    Stroke s;
    for (int k = 0; k <= 40; ++k) {
      const double f = -1.0 + k / 20.0;
      s.points.push_back(mid + f * half * u + bow * (1.0 - f * f) * n);
    }
    p.strokes.push_back(s);
  }
  return p;
}

// The drawn truth of each line (rigid motions and mirroring keep lengths and straightness).
AccuracyFigures truthOf(const CalibrationPattern& p) {
  std::vector<std::vector<Vec2>> lines;
  for (const Stroke& s : p.strokes) lines.push_back(s.points);
  return *accuracyFigures(lines);
}

// Every line within the tolerances, in the order across the sheet (which may run either way).
void expectLines(const LineScanOutcome& scan, const AccuracyFigures& truth, const std::string& what) {
  ASSERT_TRUE(scan.ok()) << what << ": " << scan.error.text();
  ASSERT_TRUE(scan.figures);
  ASSERT_EQ(scan.lines.size(), truth.lines.size()) << what;
  double worst[2] = {0.0, 0.0}, worstStraight[2] = {0.0, 0.0};
  const size_t n = truth.lines.size();
  for (int dir = 0; dir < 2; ++dir)
    for (size_t i = 0; i < n; ++i) {
      const LineAccuracy& t = truth.lines[dir == 0 ? i : n - 1 - i];
      const LineAccuracy& s = scan.figures->lines[i];
      worst[dir] = std::max(worst[dir], std::abs(s.lengthMm - t.lengthMm));
      worstStraight[dir] = std::max(worstStraight[dir], std::abs(s.straightnessMm - t.straightnessMm));
    }
  const int d = worst[0] <= worst[1] ? 0 : 1;
  double meanSigned = 0.0;
  for (size_t i = 0; i < n; ++i)
    meanSigned += (scan.figures->lines[i].lengthMm - truth.lines[d == 0 ? i : n - 1 - i].lengthMm) / static_cast<double>(n);
  std::printf("%s: worst length error %.4f mm (mean %+.4f), worst straightness error %.4f mm (pen %.3f mm)\n",
              what.c_str(), worst[d], meanSigned, worstStraight[d], scan.lines.front().penWidthMm);
  EXPECT_LE(worst[d], 0.05) << what;
  EXPECT_LE(worstStraight[d], 0.03) << what;
  EXPECT_NEAR(scan.lines.front().penWidthMm, 0.4, 0.08) << what;
}

TEST(ScanLines, At600DpiTurnedBlurredNoisy) {
  const CalibrationPattern p = drawnLines(0.15, 0.3);
  test::SheetOptions o;
  o.dpi = 600;
  o.rotationDeg = 7.5;
  o.blurSigmaPx = 1.5;
  o.noiseSigma = 10;
  o.seed = test::seed();
  expectLines(scanAccuracyLines(test::renderSheet(p, o).image, 600, "600dpi"), truthOf(p), "600 dpi, 7.5 deg");
}

TEST(ScanLines, At300DpiMirroredTurnedBlurredNoisy) {
  const CalibrationPattern p = drawnLines(-0.12, 0.2);
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = -113;
  o.mirrored = true;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 8;
  o.seed = test::seed() + 1;
  expectLines(scanAccuracyLines(test::renderSheet(p, o).image, 300, "300dpi"), truthOf(p), "300 dpi, mirrored, -113 deg");
}

TEST(ScanLines, At300DpiAlongThePixelsSharp) {
  const CalibrationPattern p = drawnLines(0.1, 0.0);
  for (const double deg : {0.0, 90.0, 45.0}) {
    test::SheetOptions o;
    o.dpi = 300;
    o.rotationDeg = deg;
    expectLines(scanAccuracyLines(test::renderSheet(p, o).image, 300, "sharp"), truthOf(p),
                "300 dpi sharp, " + std::to_string(static_cast<int>(deg)) + " deg");
  }
}

// The whole calibration sheet: the lines among rings, dots and numbers.
TEST(ScanLines, TheLinesAmongTheMarksOfTheCalibrationSheet) {
  const PatternResult r = makeCalibrationPattern(*preset("maker-plotter"));
  ASSERT_TRUE(r.pattern && r.pattern->accuracy) << r.error;
  std::vector<std::vector<Vec2>> planned;
  for (const AccuracyLine& l : r.pattern->accuracy->lines) planned.push_back({l.startMm, l.endMm});
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 3.0;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 6;
  o.seed = test::seed();
  expectLines(scanAccuracyLines(test::renderSheet(*r.pattern, o).image, 300, "sheet"), *accuracyFigures(planned),
              "calibration sheet, 300 dpi");
}

TEST(ScanLines, BadInputIsNamed) {
  const CalibrationPattern p = drawnLines(0.0, 0.0);
  test::SheetOptions o;
  o.dpi = 300;
  const QImage image = test::renderSheet(p, o).image;
  const LineScanOutcome wrongDpi = scanAccuracyLines(image, 150, "A.png");
  EXPECT_NE(wrongDpi.error.text().find("A.png: found 0 parallel lines of about 40 mm at 150 dpi, expected 10"),
            std::string::npos)
      << wrongDpi.error.text();
  EXPECT_TRUE(wrongDpi.error.translatable());
  QImage cut = image.copy(0, 0, image.width(), image.height() / 2);  // part of the pattern
  const LineScanOutcome partial = scanAccuracyLines(cut, 300, "B.png");
  EXPECT_NE(partial.error.text().find("B.png: found "), std::string::npos) << partial.error.text();
  QImage blank(400, 300, QImage::Format_Grayscale8);
  blank.fill(250);
  EXPECT_NE(scanAccuracyLines(blank, 300, "C.png").error.text().find("C.png: no ink found"), std::string::npos);
  EXPECT_NE(scanAccuracyLines(image, 0, "D.png").error.text().find("D.png: the dpi must be a positive number"),
            std::string::npos);
  EXPECT_NE(scanAccuracyLinesFile("/nonexistent/E.png", 300).error.text().find("/nonexistent/E.png: cannot read the image"),
            std::string::npos);
}

#ifdef FIVEBAR_CLI
TEST(ScanLinesCli, CalibrateLinesPrintsAndWritesTheFigures) {
  namespace fs = std::filesystem;
  QTemporaryDir tmp;
  const fs::path dir = tmp.path().toStdString();
  const CalibrationPattern p = drawnLines(0.15, 0.25);
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 30;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 5;
  o.seed = test::seed();
  const std::string png = (dir / "LINES.png").string(), csv = (dir / "LINES.csv").string();
  ASSERT_TRUE(test::renderSheet(p, o).image.save(QString::fromStdString(png)));
  const std::string cmd = std::string(FIVEBAR_CLI) + " calibrate lines --image " + cli_test::quote(png) +
                          " --dpi 300 -o " + cli_test::quote(csv) + " >" + cli_test::quote((dir / "out.txt").string()) +
                          " 2>" + cli_test::quote((dir / "err.txt").string());
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cli_test::slurp(dir / "err.txt");
  const std::string out = cli_test::slurp(dir / "out.txt");
  EXPECT_NE(out.find("10 accuracy lines found"), std::string::npos) << out;
  EXPECT_NE(out.find("worst length error"), std::string::npos) << out;
  const std::string table = cli_test::slurp(csv);
  EXPECT_EQ(table.rfind("line,length_mm,length_error_mm,straightness_mm,x0_mm,y0_mm,x1_mm,y1_mm\n", 0), 0u);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 11);
  // A wrong dpi: exit 1, the reason named, nothing written.
  const std::string csv2 = (dir / "NONE.csv").string();
  const std::string bad = std::string(FIVEBAR_CLI) + " calibrate lines --image " + cli_test::quote(png) +
                          " --dpi 1200 -o " + cli_test::quote(csv2) + " >/dev/null 2>" +
                          cli_test::quote((dir / "err2.txt").string());
  const int s2 = std::system(bad.c_str());
  EXPECT_TRUE(WIFEXITED(s2) && WEXITSTATUS(s2) == 1);
  EXPECT_NE(cli_test::slurp(dir / "err2.txt").find("expected 10"), std::string::npos);
  EXPECT_FALSE(fs::exists(csv2));
}
#endif

}  // namespace
}  // namespace fivebar
