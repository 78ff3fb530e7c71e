// SPDX-License-Identifier: GPL-3.0-or-later
// The scan (core/calibration/scan): synthetic sheets rendered by QPainter at 300 and 600 dpi,
// turned, mirrored, blurred and noisy (seeded): every mark found within 0.05 mm of where it was
// drawn and numbered right; bad input named.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <algorithm>
#include <random>

#include "core/calibration/mark_match.hpp"
#include "core/calibration/marks_csv.hpp"
#include "core/calibration/scan/scan.hpp"
#include "synthetic_scan.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

struct Fixture {
  CalibrationPattern pattern;
  std::vector<MarkRecord> marks;
};
const Fixture& maker() {
  static const Fixture f = [] {
    Fixture x;
    const PatternResult r = makeCalibrationPattern(*preset("maker-plotter"));
    EXPECT_TRUE(r.pattern) << r.error;
    x.pattern = *r.pattern;
    const MarksLoad m = parseMarksCsv(marksCsv(x.pattern), "MARKS.csv");
    EXPECT_TRUE(m.ok()) << m.error;
    x.marks = m.marks;
    return x;
  }();
  return f;
}

// Scans the sheet and checks every mark: found, numbered right, within 0.05 mm.
void expectExact(const test::Sheet& sheet, double dpi, bool mirrored, const std::string& what) {
  const Fixture& f = maker();
  const ScanOutcome s = scanImage(sheet.image, dpi, f.marks, what);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.measured.size(), f.marks.size()) << what;
  EXPECT_TRUE(s.missingIds.empty()) << what;
  EXPECT_EQ(s.mirrored, mirrored) << what;
  double worst = 0.0;
  for (const MeasuredMark& m : s.measured) {
    const Vec2 truth = sheet.truePaperMm.at(m.id);
    worst = std::max(worst, (m.measuredMm - truth).norm());
    EXPECT_LT((m.measuredMm - truth).norm(), 0.05) << what << ": mark " << m.id;
  }
  std::cout << what << ": worst mark error " << worst << " mm\n";
}

TEST(Scan, At600DpiTurnedBlurredNoisy) {
  test::SheetOptions o;
  o.dpi = 600;
  o.rotationDeg = 7.5;
  o.blurSigmaPx = 1.5;
  o.noiseSigma = 10;
  o.seed = test::seed();
  expectExact(test::renderSheet(maker().pattern, o), 600, false, "600 dpi, 7.5 deg");
}

TEST(Scan, At300DpiMirroredTurnedBlurredNoisy) {
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = -113.0;
  o.mirrored = true;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 8;
  o.seed = test::seed() + 1;
  expectExact(test::renderSheet(maker().pattern, o), 300, true, "300 dpi, mirrored, -113 deg");
}

TEST(Scan, ImperfectMachineMarksAreStillNumberedRight) {
  // Every mark drawn up to 2 mm from its nominal place (an uncalibrated machine), the sheet upside
  // down: numbering by the pattern still holds and positions are where the marks are.
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> u(-1.4, 1.4);
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 181.0;
  o.blurSigmaPx = 1.0;
  o.noiseSigma = 6;
  o.seed = test::seed() + 2;
  for (const PatternMark& m : maker().pattern.marks) o.displacementMm[m.id] = Vec2(u(rng), u(rng));
  expectExact(test::renderSheet(maker().pattern, o), 300, false, "300 dpi, displaced marks, 181 deg");
}

TEST(SyntheticScan, EachMarksStrokesMoveWithItWhateverTheOrderOfTheMarks) {
  // renderSheet finds a mark's strokes by plotting order, not by the order of the marks (by id):
  // the same pattern with its marks listed in another order renders the same sheet.
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> u(-1.4, 1.4);
  test::SheetOptions o;
  o.dpi = 150;
  for (const PatternMark& m : maker().pattern.marks) o.displacementMm[m.id] = Vec2(u(rng), u(rng));
  const CalibrationPattern& pattern = maker().pattern;
  CalibrationPattern reversed = pattern;
  std::reverse(reversed.marks.begin(), reversed.marks.end());
  std::reverse(reversed.dotStroke.begin(), reversed.dotStroke.end());
  const test::Sheet a = test::renderSheet(pattern, o), b = test::renderSheet(reversed, o);
  EXPECT_TRUE(a.image == b.image) << "the order of the marks changed the drawing";
  EXPECT_EQ(a.truePaperMm, b.truePaperMm);
}

TEST(Scan, ReadsPngAndJpegFiles) {
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 31.0;
  o.blurSigmaPx = 0.7;
  const test::Sheet sheet = test::renderSheet(maker().pattern, o);
  QTemporaryDir dir;
  for (const char* ext : {"png", "jpg"}) {
    const QString path = dir.filePath(QString("scan.") + ext);
    ASSERT_TRUE(sheet.image.save(path, nullptr, 95));
    const ScanOutcome s = scanFile(path.toStdString(), 300, maker().marks);
    ASSERT_TRUE(s.ok()) << s.error;
    ASSERT_EQ(s.measured.size(), maker().marks.size());
    for (const MeasuredMark& m : s.measured)
      EXPECT_LT((m.measuredMm - sheet.truePaperMm.at(m.id)).norm(), 0.05) << ext << " mark " << m.id;
  }
}

TEST(Scan, BadInputIsNamed) {
  const Fixture& f = maker();
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 12;
  const test::Sheet sheet = test::renderSheet(f.pattern, o);
  // Wrong dpi: the rings are half the size expected; the message suggests the real dpi.
  const ScanOutcome wrong = scanImage(sheet.image, 600, f.marks, "SCAN.png");
  EXPECT_EQ(wrong.error.text().rfind("SCAN.png: no marks found at 600 dpi", 0), 0u) << wrong.error;
  EXPECT_NE(wrong.error.text().find("about 3"), std::string::npos) << wrong.error;  // "about 300 dpi" or so
  // A blank page.
  QImage blank(400, 300, QImage::Format_Grayscale8);
  blank.fill(255);
  EXPECT_EQ(scanImage(blank, 300, f.marks, "blank.png").error,
            "blank.png: no ink found (the image has almost no contrast)");
  // An unreadable file.
  QTemporaryDir dir;
  const std::string junk = dir.filePath("junk.png").toStdString();
  { std::FILE* fp = std::fopen(junk.c_str(), "wb"); std::fputs("not a picture", fp); std::fclose(fp); }
  EXPECT_EQ(scanFile(junk, 300, f.marks).error.text().rfind(junk + ": cannot read the image", 0), 0u);
  EXPECT_EQ(scanFile("/nonexistent/scan.png", 300, f.marks).error.text().rfind("/nonexistent/scan.png: cannot read", 0), 0u);
  EXPECT_EQ(scanImage(sheet.image, -1, f.marks, "SCAN.png").error, "SCAN.png: the dpi must be a positive number");
  // Another machine's pattern: the marks do not match.
  const PatternResult other = makeCalibrationPattern(*preset("hoang2015"));
  ASSERT_TRUE(other.pattern) << other.error;
  const MarksLoad otherMarks = parseMarksCsv(marksCsv(*other.pattern), "OTHER.csv");
  const ScanOutcome mismatch = scanImage(sheet.image, 300, otherMarks.marks, "SCAN.png");
  EXPECT_FALSE(mismatch.ok());
  EXPECT_EQ(mismatch.error.text().rfind("SCAN.png: ", 0), 0u) << mismatch.error;
}

TEST(MarkMatch, SymmetricPointSetIsAmbiguous) {
  // A square's corners plus its centre: a quarter turn maps it onto itself.
  const std::vector<Vec2> nominal{{0, 0}, {50, 0}, {50, 50}, {0, 50}, {25, 25}};
  std::vector<Vec2> found;
  for (const Vec2& p : nominal) found.push_back(p + Vec2(10, 10));
  const MarkMatch m = matchMarks(found, nominal);
  EXPECT_NE(m.error.text().find("ambiguous"), std::string::npos) << m.error;
}

}  // namespace
}  // namespace fivebar
