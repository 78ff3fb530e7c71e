// SPDX-License-Identifier: GPL-3.0-or-later
// The corpus check of issue 29: every file of resvg's shapes/ and structure/ tests drawn as the
// reference PNG beside it shows (resvg's rendering, 300 px wide). Our plotted lines are laid over
// the PNG: (1) nothing drawn that the PNG does not show: every point along our lines lies within
// kDrawnSlackPx of an ink pixel; (2) nothing shown that is not drawn: every ink pixel lies within
// kStrokeSlackPx of one of our lines (a stroke's half width) or inside one of our closed outlines
// (a fill). One test per file; skipped without ../shared.
#include <gtest/gtest.h>

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QImage>

#include <cmath>
#include <queue>

#include "core/import/svg_import.hpp"

namespace fivebar::svg {
namespace {

constexpr int kDrawnSlackPx = 3;     // anti-aliasing and the flattening tolerance
constexpr int kStrokeSlackPx = 12;   // half the widest stroke of these tests, plus anti-aliasing

QString corpusDir() { return QStringLiteral(FIVEBAR_SHARED_DIR "/corpus/svg/resvg/valid"); }

std::vector<std::string> files() {
  std::vector<std::string> out;
  for (const char* folder : {"shapes", "structure"}) {
    QDirIterator it(corpusDir() + u'/' + QLatin1String(folder), {QStringLiteral("*.svg")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) out.push_back(QDir(corpusDir()).relativeFilePath(it.next()).toStdString());
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool ink(QRgb p) {
  return qAlpha(p) > 40 && (qRed(p) < 225 || qGreen(p) < 225 || qBlue(p) < 225);
}

// Distance in pixels (chessboard) from every pixel to the nearest pixel where `seed` is true.
std::vector<int> distanceField(int w, int h, const std::vector<char>& seed) {
  std::vector<int> d(static_cast<std::size_t>(w) * h, 1 << 20);
  std::queue<int> q;
  for (int i = 0; i < w * h; ++i)
    if (seed[static_cast<std::size_t>(i)]) d[static_cast<std::size_t>(i)] = 0, q.push(i);
  while (!q.empty()) {
    const int i = q.front();
    q.pop();
    const int x = i % w, y = i / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const std::size_t j = static_cast<std::size_t>(ny * w + nx);
        if (d[j] > d[static_cast<std::size_t>(i)] + 1) d[j] = d[static_cast<std::size_t>(i)] + 1, q.push(static_cast<int>(j));
      }
  }
  return d;
}

bool insideRing(double x, double y, const std::vector<QPointF>& ring) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y() > y) != (ring[j].y() > y) &&
        x < (ring[j].x() - ring[i].x()) * (y - ring[i].y()) / (ring[j].y() - ring[i].y()) + ring[i].x())
      in = !in;
  return in;
}

// Files whose reference PNG cannot judge the drawing, each with the reason (checked otherwise).
const char* knownDifference(const std::string& file) {
  static const std::pair<const char*, const char*> known[] = {
      {"shapes/rect/q-values.svg", "resvg draws no Q units (CSS: 1Q = 1/4 mm; Lengths.* test them)"},
      {"shapes/rect/vw-and-vh-values.svg", "resvg draws no vw/vh units (SVG 2; Lengths.ViewportUnits*)"},
      {"structure/defs/multiple-defs.svg", "a gradient fading into the white page at the shape's edge"},
      {"structure/defs/nested-defs.svg", "a gradient fading into the white page at the shape's edge"},
      {"structure/defs/out-of-order.svg", "a gradient fading into the white page at the shape's edge"},
      {"structure/defs/simple-case.svg", "a gradient fading into the white page at the shape's edge"},
      {"structure/defs/style-inheritance-on-text.svg", "text: the system font's glyphs, not resvg's Noto Sans"},
      {"structure/svg/mixed-namespaces.svg", "text: the system font's glyphs (the foreign <a> is not drawn: "
                                             "Visibility.ElementsOfAForeignNamespaceAreNotDrawn)"},
      {"structure/symbol/with-transform.svg", "resvg follows SVG 1.1 (no transform on <symbol>); SVG 2 applies it"},
  };
  for (const auto& [name, reason] : known)
    if (file == name) return reason;
  return nullptr;
}

class ReferencePng : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferencePng, DrawnAsTheReferenceShows) {
  if (const char* reason = knownDifference(GetParam())) GTEST_SKIP() << reason;
  const QString svg = corpusDir() + u'/' + QString::fromStdString(GetParam());
  QString png = svg;
  png.replace(png.size() - 3, 3, QStringLiteral("png"));
  QImage image(png);
  ASSERT_FALSE(image.isNull()) << png.toStdString();
  image = image.convertToFormat(QImage::Format_ARGB32);
  ImportOptions options;
  options.isolation = Isolation::InProcess;
  const ImportResult r = importSvgInProcess(svg, options);
  ASSERT_TRUE(r.ok()) << r.message;
  const int w = image.width(), h = image.height();
  const double sx = w / r.drawing.widthMm, sy = h / r.drawing.heightMm;
  auto pixel = [&](const Vec2& p) { return QPointF(p.x() * sx, (r.drawing.heightMm - p.y()) * sy); };
  std::vector<char> inkMask(static_cast<std::size_t>(w) * h, 0), lineMask(inkMask.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) inkMask[static_cast<std::size_t>(y * w + x)] = ink(image.pixel(x, y));
  // Our lines, sampled every half pixel; closed outlines kept as rings for the fill test.
  std::vector<std::vector<QPointF>> rings;
  int stray = 0, samples = 0;
  const std::vector<int> toInk = distanceField(w, h, inkMask);
  for (const Layer& layer : r.drawing.layers)
    for (const Polyline& line : layer.paths) {
      std::vector<QPointF> px;
      for (const Vec2& p : line.points) px.push_back(pixel(p));
      if (line.closed) rings.push_back(px);
      const std::size_t n = px.size();
      for (std::size_t i = 0; i < (line.closed ? n : n - 1); ++i) {
        const QPointF a = px[i], b = px[(i + 1) % n];
        const int steps = std::max(1, static_cast<int>(std::ceil(2 * std::hypot(b.x() - a.x(), b.y() - a.y()))));
        for (int k = 0; k <= steps; ++k) {
          const QPointF p = a + (b - a) * (static_cast<double>(k) / steps);
          const int x = std::clamp(static_cast<int>(p.x()), 0, w - 1), y = std::clamp(static_cast<int>(p.y()), 0, h - 1);
          lineMask[static_cast<std::size_t>(y * w + x)] = 1;
          ++samples;
          if (toInk[static_cast<std::size_t>(y * w + x)] > kDrawnSlackPx) ++stray;
        }
      }
    }
  EXPECT_EQ(stray, 0) << "of " << samples << " points along our lines, " << stray
                      << " lie where the reference shows nothing";
  const std::vector<int> toLine = distanceField(w, h, lineMask);
  int unexplained = 0, inkPixels = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x);
      if (!inkMask[i]) continue;
      ++inkPixels;
      if (toLine[i] <= kStrokeSlackPx) continue;
      const bool filled = std::any_of(rings.begin(), rings.end(),
                                      [&](const auto& ring) { return insideRing(x + 0.5, y + 0.5, ring); });
      if (!filled) ++unexplained;
    }
  EXPECT_EQ(unexplained, 0) << "of " << inkPixels << " ink pixels of the reference, " << unexplained
                            << " are far from every line we draw";
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, ReferencePng, ::testing::ValuesIn(files()), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ReferencePng);

}  // namespace
}  // namespace fivebar::svg
