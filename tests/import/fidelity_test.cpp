// SPDX-License-Identifier: GPL-3.0-or-later
// What a browser draws: symbols through use, zero-size shapes, closing edges of filled paths,
// markers, text and viewport lengths, transform-origin, invalid path data, .svgz, messages.
// Geometry is compared with what the SVG specifies (bounding boxes, lengths, distances).
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/import/svgz.hpp"
#include "geometry_support.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::joined;
using test::warned;

using test::allPaths;
using test::importText;
using test::page;

struct Box {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -std::numeric_limits<double>::infinity(), maxY = maxX;
};

// Bounding box of every point, in the page frame (y down) of a page `heightMm` tall.
Box pageBox(const Drawing& d) {
  Box b;
  for (const Polyline& line : allPaths(d))
    for (const Vec2& p : line.points) {
      const double y = d.heightMm - p.y();
      b.minX = std::min(b.minX, p.x());
      b.maxX = std::max(b.maxX, p.x());
      b.minY = std::min(b.minY, y);
      b.maxY = std::max(b.maxY, y);
    }
  return b;
}

void expectBox(const Drawing& d, double x0, double y0, double x1, double y1, double tol = 1e-6) {
  const Box b = pageBox(d);
  EXPECT_NEAR(b.minX, x0, tol);
  EXPECT_NEAR(b.minY, y0, tol);
  EXPECT_NEAR(b.maxX, x1, tol);
  EXPECT_NEAR(b.maxY, y1, tol);
}

double length(const Polyline& line) {
  double sum = 0.0;
  for (std::size_t i = 1; i < line.points.size(); ++i) sum += (line.points[i] - line.points[i - 1]).norm();
  if (line.closed && line.points.size() > 2) sum += (line.points.front() - line.points.back()).norm();
  return sum;
}

const std::string kSquareSymbol =
    "<symbol id=\"sq\" viewBox=\"0 0 10 10\"><rect x=\"0\" y=\"0\" width=\"10\" height=\"10\" "
    "fill=\"none\" stroke=\"black\"/></symbol>";

TEST(Symbols, SymbolInDefsIsDrawnThroughUseAtItsViewport) {
  const ImportResult r = importText(
      page("<defs>" + kSquareSymbol + "</defs><use href=\"#sq\" x=\"20\" y=\"10\" width=\"30\" height=\"30\"/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  expectBox(r.drawing, 20, 10, 50, 40);
  EXPECT_NEAR(length(allPaths(r.drawing)[0]), 120.0, 1e-6);
}

TEST(Symbols, SymbolOutsideDefsIsNotDrawnByItselfOnlyThroughUse) {
  const ImportResult none = importText(page(kSquareSymbol, 100, 50));
  ASSERT_TRUE(none.ok()) << none.message;
  EXPECT_EQ(allPaths(none.drawing).size(), 0u);
  // The use comes before the symbol; xlink:href; no width/height: 100% of the viewport (100 x 50,
  // meet: 50 x 50 centred at x 25).
  const ImportResult r = importText(page("<use xlink:href=\"#sq\" x=\"5\" y=\"0\"/>" + kSquareSymbol, 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  expectBox(r.drawing, 30, 0, 80, 50);
}

TEST(Symbols, PreserveAspectRatioAndUseTransformAndNesting) {
  // A 10 x 20 viewBox in a 40 x 40 viewport, xMinYMax meet: scale 2, 20 x 40 at the left.
  const std::string tall =
      "<symbol id=\"tall\" viewBox=\"0 0 10 20\" preserveAspectRatio=\"xMinYMax meet\">"
      "<path d=\"M0 0 H10 V20 H0 Z\" fill=\"none\" stroke=\"black\"/></symbol>";
  const ImportResult r = importText(
      page(tall + "<use href=\"#tall\" transform=\"translate(10 5)\" x=\"1\" y=\"2\" width=\"40\" height=\"40\"/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  expectBox(r.drawing, 11, 7, 31, 47);
  // none: stretched to 40 x 40.
  std::string stretched = tall;
  stretched.replace(stretched.find("xMinYMax meet"), 13, "none");
  const ImportResult s = importText(page(stretched + "<use href=\"#tall\" width=\"40\" height=\"40\"/>", 100, 50));
  ASSERT_TRUE(s.ok()) << s.message;
  expectBox(s.drawing, 0, 0, 40, 40);
  // A symbol whose content uses another symbol (nested use), placed twice.
  const std::string outer =
      "<symbol id=\"outer\" viewBox=\"0 0 100 100\"><use href=\"#sq\" x=\"50\" y=\"50\" width=\"50\" height=\"50\"/></symbol>";
  const ImportResult n = importText(page("<defs>" + kSquareSymbol + outer + "</defs>"
                                         "<use href=\"#outer\" width=\"20\" height=\"20\"/>"
                                         "<use href=\"#outer\" x=\"60\" width=\"40\" height=\"40\"/>", 100, 50));
  ASSERT_TRUE(n.ok()) << n.message;
  ASSERT_EQ(allPaths(n.drawing).size(), 2u);
  expectBox(n.drawing, 10, 10, 100, 40);
}

TEST(ZeroSize, ZeroSizeShapesAreNotDrawn) {
  const ImportResult r = importText(page(
      "<g fill=\"none\" stroke=\"black\"><rect x=\"5\" y=\"5\" width=\"0\" height=\"20\"/>"
      "<rect x=\"5\" y=\"5\" width=\"20\"/><circle cx=\"50\" cy=\"20\" r=\"0\"/>"
      "<ellipse cx=\"50\" cy=\"20\" rx=\"0\" ry=\"10\"/><ellipse cx=\"50\" cy=\"20\" rx=\"-1\"/>"
      "<ellipse cx=\"20\" cy=\"20\" ry=\"5\"/></g>"));
  ASSERT_TRUE(r.ok()) << r.message;
  // Only the last one: rx missing = auto = ry, a 10 mm circle.
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  expectBox(r.drawing, 15, 15, 25, 25, 0.06);
}

TEST(Fills, FillOnlyOpenPathGetsItsClosingEdge) {
  const ImportResult r = importText(page("<path d=\"M20 20 h60 v60 h-60\" fill=\"black\"/>", 100, 100));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  const Polyline square = allPaths(r.drawing)[0];
  EXPECT_TRUE(square.closed);
  EXPECT_NEAR(length(square), 240.0, 1e-6);
  // A stroked open path stays open: three sides.
  const ImportResult stroked = importText(page("<path d=\"M20 20 h60 v60 h-60\" stroke=\"black\" fill=\"none\"/>", 100, 100));
  ASSERT_TRUE(stroked.ok()) << stroked.message;
  EXPECT_NEAR(length(allPaths(stroked.drawing)[0]), 180.0, 1e-6);
  // A fill-only polyline: one closed outline (QPainter's polyline pass paints nothing).
  const ImportResult poly = importText(page("<polyline points=\"10 10 50 10 50 50\" fill=\"red\"/>", 100, 100));
  ASSERT_TRUE(poly.ok()) << poly.message;
  ASSERT_EQ(allPaths(poly.drawing).size(), 1u);
  EXPECT_NEAR(length(allPaths(poly.drawing)[0]), 80.0 + std::sqrt(3200.0), 1e-6);
}

TEST(Markers, MarkerOutsideDefsIsDrawnOnlyThroughMarkerProperties) {
  const ImportResult r = importText(page(
      "<marker id=\"m\" markerWidth=\"10\" markerHeight=\"10\"><path d=\"M0 0 L10 5 L0 10 Z\" fill=\"black\"/></marker>"
      "\n<path d=\"M10 10 L90 10\" stroke=\"black\" marker-end=\"url(#m)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  // The path and the triangle at its end (stroke width 1, orient 0, refX/refY 0).
  ASSERT_EQ(allPaths(r.drawing).size(), 2u);
  expectBox(r.drawing, 10, 10, 100, 20);
  EXPECT_FALSE(warned(r, "marker")) << joined(r);
}

TEST(Lengths, TextPercentAndEmPositions) {
  const std::string text = "<text x=\"50%\" y=\"3em\" font-size=\"10\" fill=\"black\">H</text>";
  const ImportResult r = importText(page(text, 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_FALSE(allPaths(r.drawing).empty());
  const Box b = pageBox(r.drawing);
  // The glyph starts at x = 50 (plus its side bearing) and stands on the baseline y = 30.
  EXPECT_GE(b.minX, 50.0);
  EXPECT_LT(b.minX, 52.0);
  EXPECT_NEAR(b.maxY, 30.0, 0.3);
  EXPECT_GT(b.minY, 30.0 - 10.0);
  EXPECT_LT(b.minY, 30.0 - 5.0);
}

TEST(Lengths, ViewportUnitsAndTransformOrigin) {
  // 100 x 50 viewport: 50vw = 50, 10vmin = 5, 20vmax = 20, 40vh = 20.
  const ImportResult r = importText(page(
      "<circle cx=\"50vw\" cy=\"40vh\" r=\"10vmin\" fill=\"none\" stroke=\"black\"/>"
      "<line x1=\"0\" y1=\"45\" x2=\"20vmax\" y2=\"45\" stroke=\"black\"/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  expectBox(r.drawing, 0, 15, 55, 45, 0.06);
  // rotate(90) about the square's centre keeps it in place; about 0 0 it would land at x < 0.
  const ImportResult o = importText(page(
      "<rect x=\"40\" y=\"20\" width=\"20\" height=\"10\" transform=\"rotate(90)\" "
      "transform-origin=\"50 25\" fill=\"none\" stroke=\"black\"/>", 100, 50));
  ASSERT_TRUE(o.ok()) << o.message;
  expectBox(o.drawing, 45, 15, 55, 35);
  const ImportResult c = importText(page(
      "<rect x=\"40\" y=\"20\" width=\"10\" height=\"5\" transform=\"scale(2)\" "
      "transform-origin=\"center\" fill=\"none\" stroke=\"black\"/>", 100, 50));
  ASSERT_TRUE(c.ok()) << c.message;
  expectBox(c.drawing, 30, 15, 50, 25);  // scaled about (50, 25); about 0 0: 80..100 x 40..50
}

TEST(Warnings, TextRotateClipAndMaskAreNamed) {
  const ImportResult r = importText(page(
      "<text x=\"10\" y=\"20\" rotate=\"30\" fill=\"black\">A</text>"
      "<path d=\"M0 0 L5 5\" stroke=\"black\" clip-path=\"url(#c)\" mask=\"url(#m)\"/>"));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(warned(r, "rotate on <text> is not applied")) << joined(r);
  EXPECT_TRUE(warned(r, "<path> clip-path #c not found: drawn unclipped")) << joined(r);
  EXPECT_TRUE(warned(r, "mask not applied")) << joined(r);
}

TEST(PathData, InvalidDataDrawsUpToTheErrorWithAWarningNamingElementAndLine) {
  const ImportResult r = importText(page(
      "\n\n<path id=\"bad\" d=\"M10 10 L90 10 L90 x40 L10 40\" stroke=\"black\" fill=\"none\"/>", 100, 50));
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(allPaths(r.drawing).size(), 1u);
  EXPECT_NEAR(length(allPaths(r.drawing)[0]), 80.0, 1e-6);
  ASSERT_TRUE(warned(r, "line 3: <path id=\"bad\"> attribute d: invalid path data at character 19"))
      << joined(r);
  EXPECT_TRUE(warned(r, "drawn up to the error"));
  const ImportResult fine = importText(page("<path d=\"M10 10 L90 10\" stroke=\"black\"/>"));
  EXPECT_TRUE(fine.warnings.empty()) << joined(fine);
}

TEST(Messages, NumbersTooLargeAreNamedAsSuch) {
  const ImportResult big = importText(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 9E80 7\"><path d=\"M0 0 L1 1\" stroke=\"black\"/></svg>");
  EXPECT_EQ(big.status, ImportStatus::InvalidDocument);
  EXPECT_NE(big.message.text().find("a number too large (9E80"), std::string::npos) << big.message;
  const ImportResult huge = importText(page("\n<path id=\"p\" d=\"M0 0 L 1e308 5\" stroke=\"black\"/>"));
  EXPECT_EQ(huge.status, ImportStatus::InvalidNumber);
  EXPECT_NE(huge.message.text().find("line 2: <path id=\"p\"> attribute d contains a number beyond 1e300 (1e308)"),
            std::string::npos)
      << huge.message;
}

QByteArray gzip(const QByteArray& in) {
  z_stream z{};
  deflateInit2(&z, 9, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  QByteArray out(static_cast<qsizetype>(deflateBound(&z, static_cast<uLong>(in.size()))) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.constData()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(static_cast<qsizetype>(z.total_out));
  deflateEnd(&z);
  return out;
}

TEST(Svgz, CompressedFilesImportLikeThePlainOnesInProcessAndThroughTheWorker) {
  const std::string doc = page("<circle cx=\"50\" cy=\"25\" r=\"20\" fill=\"none\" stroke=\"black\"/>");
  const ImportResult plain = importText(doc);
  ASSERT_TRUE(plain.ok()) << plain.message;
  const QByteArray packed = gzip(QByteArray::fromStdString(doc));
  ASSERT_TRUE(isGzip(packed));
  const ImportResult inProcess = importSvgData(packed, QStringLiteral("t.svgz"));
  ASSERT_TRUE(inProcess.ok()) << inProcess.message;
  EXPECT_EQ(allPaths(inProcess.drawing)[0].points, allPaths(plain.drawing)[0].points);
  QTemporaryDir dir;
  QFile f(dir.filePath(QStringLiteral("t.svgz")));
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(packed);
  f.close();
  const ImportResult viaWorker = importSvgFile(f.fileName());
  ASSERT_TRUE(viaWorker.ok()) << viaWorker.message;
  EXPECT_EQ(allPaths(viaWorker.drawing)[0].points, allPaths(plain.drawing)[0].points);
}

TEST(Svgz, DecompressedSizeIsBoundedAndCorruptDataIsNamed) {
  const QByteArray bomb = gzip(QByteArray(4 << 20, ' '));  // 4 MiB of spaces, a few kB packed
  QByteArray out;
  const std::string over = gunzip(bomb, 1 << 20, out);
  EXPECT_NE(over.find("more than 1 MiB after decompression"), std::string::npos) << over;
  EXPECT_TRUE(out.isEmpty());
  EXPECT_EQ(gunzip(bomb, 8 << 20, out), "");
  EXPECT_EQ(out.size(), 4 << 20);
  EXPECT_EQ(gzipAnnouncedSize(bomb), 4u << 20);
  QByteArray broken = bomb.left(bomb.size() / 2);
  const ImportResult r = importSvgData(broken, QStringLiteral("broken.svgz"));
  EXPECT_EQ(r.status, ImportStatus::FileError);
  EXPECT_NE(r.message.text().find("broken.svgz: compressed SVG (gzip): the gzip data ends early"),
            std::string::npos)
      << r.message;
}

}  // namespace
}  // namespace fivebar::svg
