// SPDX-License-Identifier: GPL-3.0-or-later
// Third-party SVGs (/work/shared/corpus/svg): every valid file imports or is refused with a
// reason; every adversarial file ends within the time limit in an error or a sane import.
// One test per file, each through the worker, so ctest runs them in parallel.
#include <gtest/gtest.h>

#include <QDir>
#include <QDirIterator>

#include <chrono>
#include <cmath>
#include <iostream>

#include "core/import/svg_import.hpp"

namespace fivebar::svg {
namespace {

QString corpusDir() { return QStringLiteral(FIVEBAR_SHARED_DIR "/corpus/svg"); }

std::vector<std::string> svgFiles(const QStringList& folders) {
  std::vector<std::string> files;
  for (const QString& folder : folders) {
    QDirIterator it(corpusDir() + u'/' + folder, {QStringLiteral("*.svg")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) files.push_back(QDir(corpusDir()).relativeFilePath(it.next()).toStdString());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

// A successful import must be finite and inside the coordinate limit.
void expectSane(const ImportResult& r, const std::string& file) {
  EXPECT_TRUE(std::isfinite(r.drawing.widthMm) && std::isfinite(r.drawing.heightMm)) << file;
  for (const Layer& layer : r.drawing.layers)
    for (const Polyline& line : layer.paths) {
      EXPECT_GE(line.points.size(), 2u) << file;
      for (const Vec2& p : line.points)
        ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()) && std::abs(p.x()) <= 1e6 &&
                    std::abs(p.y()) <= 1e6) << file;
    }
}

// A refusal a user would accept: names the file and says what is wrong.
void expectClearRefusal(const ImportResult& r, const std::string& file) {
  EXPECT_NE(r.message.text().find(file), std::string::npos) << r.message;
  EXPECT_GT(r.message.text().size(), file.size() + 10) << r.message;
  std::cout << "REFUSED " << file << " [" << toString(r.status) << "]: " << r.message << '\n';
}

class ValidCorpus : public ::testing::TestWithParam<std::string> {};
class AdversarialCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidCorpus, ImportsOrIsRefusedWithAReason) {
  const std::string file = (corpusDir() + u'/' + QString::fromStdString(GetParam())).toStdString();
  const ImportResult r = importSvgFile(QString::fromStdString(file));
  if (r.ok()) {
    expectSane(r, file);
    return;
  }
  EXPECT_NE(r.status, ImportStatus::WorkerCrashed) << r.message;
  EXPECT_NE(r.status, ImportStatus::WorkerTimeout) << r.message;
  expectClearRefusal(r, file);
}

TEST_P(AdversarialCorpus, EndsWithinTheLimitInAnErrorOrASaneImport) {
  const std::string file = (corpusDir() + u'/' + QString::fromStdString(GetParam())).toStdString();
  const auto start = std::chrono::steady_clock::now();
  const ImportResult r = importSvgFile(QString::fromStdString(file));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 11.0) << file;
  if (r.ok()) expectSane(r, file);
  else expectClearRefusal(r, file);
}

INSTANTIATE_TEST_SUITE_P(Corpus, ValidCorpus,
                         ::testing::ValuesIn(svgFiles({QStringLiteral("resvg/valid"),
                                                       QStringLiteral("vpype-plotter")})),
                         testName);
INSTANTIATE_TEST_SUITE_P(Corpus, AdversarialCorpus,
                         ::testing::ValuesIn(svgFiles({QStringLiteral("resvg/adversarial")})),
                         testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ValidCorpus);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(AdversarialCorpus);

TEST(Corpus, IsPresentOrSkipped) {
  if (!QDir(corpusDir()).exists()) GTEST_SKIP() << "no corpus at " << corpusDir().toStdString();
  EXPECT_FALSE(svgFiles({QStringLiteral("resvg/valid")}).empty());
  EXPECT_FALSE(svgFiles({QStringLiteral("resvg/adversarial")}).empty());
}

TEST(Corpus, VpypeMultilayerFileKeepsItsInkscapeLayers) {
  const QString file = corpusDir() + QStringLiteral("/vpype-plotter/misc/multilayer_by_attributes.svg");
  if (!QFile::exists(file)) GTEST_SKIP() << "corpus absent";
  const ImportResult r = importSvgFile(file);
  ASSERT_TRUE(r.ok()) << r.message;
  // 15.875 cm square page.
  EXPECT_NEAR(r.drawing.widthMm, 158.75, 1e-9);
  std::vector<std::string> names;
  for (const Layer& l : r.drawing.layers) names.push_back(l.name);
  EXPECT_NE(std::find(names.begin(), names.end(), "3"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "2"), names.end());
}

// vpype's halftone jobs hold zero-radius arcs (a 0.001-unit line and back, butt caps): no
// renderer shows them, so none may become a pen dot; each arc with a radius is one closed dot.
TEST(Corpus, HalftoneZeroRadiusDotsAreNotDrawn) {
  QDirIterator it(corpusDir() + QStringLiteral("/vpype-plotter/issue_59"), {QStringLiteral("halftone_*.svg")}, QDir::Files);
  if (!it.hasNext()) GTEST_SKIP() << "corpus absent";
  const QString file = it.next();
  QFile text(file);
  ASSERT_TRUE(text.open(QIODevice::ReadOnly));
  const QString d = QString::fromUtf8(text.readAll());
  const long long arcs = d.count(QStringLiteral(" a ")), zero = d.count(QStringLiteral(" a 0.000 0.000 "));
  ASSERT_GT(zero, 0);
  const ImportResult r = importSvgFile(file);
  ASSERT_TRUE(r.ok()) << r.message;
  std::size_t dots = 0, lines = 0;
  for (const Layer& layer : r.drawing.layers)
    for (const Polyline& line : layer.paths) {
      ++lines;
      // A zero-radius arc and its closepath: two points 0.001 units apart (0.00026 mm).
      if (line.points.size() == 2 && (line.points[1] - line.points[0]).norm() <= 0.05) ++dots;
    }
  EXPECT_EQ(dots, 0u);
  // One closed dot per arc with a radius, plus a pen lift where the long path was split
  // (the import warns "split into 9 parts": at most 8 dots cut in two).
  EXPECT_GE(static_cast<long long>(lines), arcs - zero);
  EXPECT_LE(static_cast<long long>(lines), arcs - zero + 8);
}

}  // namespace
}  // namespace fivebar::svg
