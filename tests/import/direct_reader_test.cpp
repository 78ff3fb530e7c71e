// SPDX-License-Identifier: GPL-3.0-or-later
// The direct reader (core/import/fast_import.hpp) against the general path (sanitiser + Qt SVG +
// capture engine), which is the reference: for random documents inside the reader's subset the
// two must give the same ImportResult (points to 1e-9 mm, layers, flags, warnings, messages);
// documents outside the subset must be declined and still import as before.
#include <gtest/gtest.h>

#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>

#include <atomic>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../core/test_support.hpp"
#include "core/import/fast_import.hpp"
#include "import_support.hpp"

namespace fivebar::svg {
namespace {

constexpr double kSamePointMm = 1e-9;

// Explains the first difference between two results; empty when they are the same.
std::string difference(const ImportResult& a, const ImportResult& b) {
  if (a.status != b.status) return std::string("status ") + toString(a.status) + " vs " + toString(b.status);
  if (a.message.text() != b.message.text()) return "message [" + a.message.text() + "] vs [" + b.message.text() + "]";
  if (a.warnings != b.warnings) return "warnings differ";
  const Drawing &da = a.drawing, &db = b.drawing;
  if (da.widthMm != db.widthMm || da.heightMm != db.heightMm) return "page size differs";
  if (da.layers.size() != db.layers.size()) return "layer count differs";
  for (std::size_t i = 0; i < da.layers.size(); ++i) {
    const Layer &la = da.layers[i], &lb = db.layers[i];
    if (la.id != lb.id || la.name != lb.name || la.rgb != lb.rgb) return "layer " + la.id + " vs " + lb.id;
    if (la.paths.size() != lb.paths.size())
      return "layer " + la.id + ": " + std::to_string(la.paths.size()) + " vs " +
             std::to_string(lb.paths.size()) + " paths";
    for (std::size_t j = 0; j < la.paths.size(); ++j) {
      const Polyline &pa = la.paths[j], &pb = lb.paths[j];
      if (pa.fill != pb.fill || pa.fillStart != pb.fillStart || pa.fillOnly != pb.fillOnly)
        return "path " + std::to_string(j) + ": fill flags differ";
      if (pa.closed != pb.closed || pa.points.size() != pb.points.size())
        return "path " + std::to_string(j) + ": " + std::to_string(pa.points.size()) + " vs " +
               std::to_string(pb.points.size()) + " points";
      for (std::size_t k = 0; k < pa.points.size(); ++k)
        if ((pa.points[k] - pb.points[k]).norm() > kSamePointMm)
          return "path " + std::to_string(j) + " point " + std::to_string(k) + " moved";
    }
  }
  return {};
}

// Random documents inside the direct reader's subset, written in the styles generators use.
class SubsetDocument {
 public:
  explicit SubsetDocument(std::mt19937_64& rng) : rng_(rng) {}

  std::string make() {
    inkscape_ = false;
    std::string out = chance(0.5) ? "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n" : "";
    if (chance(0.3)) out += "<!-- generated -->\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\"";
    if (chance(0.5)) out += " xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"", inkscape_ = true;
    out += pick({" width=\"200mm\" height=\"150mm\" viewBox=\"0 0 200 150\"",
                 " width=\"210mm\" height=\"297mm\" viewBox=\"-10 -5 100 80\"",
                 " width=\"800\" height=\"600\"", " viewBox=\"0 0 400 300\"",
                 " width=\"4in\" height=\"3in\" viewBox=\"0,0,400,300\" preserveAspectRatio=\"xMinYMax\"",
                 " width=\"100mm\" height=\"100mm\" viewBox=\"0 0 50 100\" preserveAspectRatio=\"none\""});
    if (chance(0.3)) out += style();
    out += ">\n";
    const int top = 1 + static_cast<int>(rng_() % 5);
    for (int i = 0; i < top; ++i) out += element(1);
    return out + "</svg>\n";
  }

 private:
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::string pick(std::initializer_list<const char*> options) {
    return *(options.begin() + static_cast<std::ptrdiff_t>(rng_() % options.size()));
  }
  std::string number() {
    const double v = std::uniform_real_distribution<double>(-20, 220)(rng_);
    char text[32];
    const int digits = static_cast<int>(rng_() % 4);
    if (chance(0.1)) std::snprintf(text, sizeof text, "%.3e", v);
    else std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
  }
  std::string colour() {
    return pick({"none", "black", "red", "#00f", "#12ab9C", "#000000", "darkgreen", "#fff"});
  }
  std::string style() {
    std::string s;
    if (chance(0.5)) s += " fill=\"" + colour() + "\"";
    if (chance(0.6)) s += " stroke=\"" + colour() + "\"";
    if (chance(0.3)) s += " stroke-width=\"" + pick({"0.3", "1", "2.5", ".5"}) + "\"";
    return s;
  }
  std::string separator() { return pick({" ", ",", " , ", "\n  ", "  "}); }
  std::string pathData() {
    std::string d = pick({"M", "m"}) + number() + separator() + number();
    const int n = 1 + static_cast<int>(rng_() % 8);
    for (int i = 0; i < n; ++i) {
      const std::string op = pick({"L", "l", "H", "h", "V", "v", "C", "c", "S", "s", "Q", "q", "T", "t",
                                   "Z", "z", "M", "m"});
      const char lower = static_cast<char>(op[0] | 0x20);
      const int arity = lower == 'z' ? 0 : lower == 'h' || lower == 'v' ? 1
                        : lower == 'c' ? 6 : lower == 's' || lower == 'q' ? 4 : 2;
      d += (chance(0.5) ? " " : "") + op;
      const int groups = arity == 0 ? 0 : 1 + static_cast<int>(rng_() % 2);
      for (int g = 0; g < groups * arity; ++g) d += (g == 0 ? pick({"", " "}) : separator()) + number();
    }
    return d;
  }
  std::string points() {
    std::string p;
    const int n = 1 + static_cast<int>(rng_() % 6);
    for (int i = 0; i < n; ++i) p += (i ? separator() : "") + number() + "," + number();
    return p;
  }
  std::string element(int depth) {
    const int kind = static_cast<int>(rng_() % (depth < 4 ? 6 : 5));
    std::string id = chance(0.5) ? " id=\"e" + std::to_string(rng_() % 20) + "\"" : "";
    switch (kind) {
      case 0: return "<path" + id + " d=\"" + pathData() + "\"" + style() + "/>\n";
      case 1: return "<polyline" + id + " points=\"" + points() + "\"" + style() + "/>\n";
      case 2: return "<polygon" + id + " points=\"" + points() + "\"" + style() + "/>\n";
      case 3:
        return "<line" + id + " x1=\"" + number() + "\" y1=\"" + number() + "\" x2=\"" + number() +
               "\" y2=\"" + number() + "\"" + style() + "></line>\n";
      case 4: return "<path d=\"" + pathData() + "\"" + style() + ">  </path>\n";
      default: {
        std::string g = "<g" + id + style();
        if (inkscape_ && chance(0.5))
          g += " inkscape:groupmode=\"layer\" inkscape:label=\"Pen " + std::to_string(rng_() % 3) + "\"";
        g += ">\n";
        const int children = static_cast<int>(rng_() % 4);
        for (int i = 0; i < children; ++i) g += element(depth + 1);
        return g + "</g>\n";
      }
    }
  }

  std::mt19937_64& rng_;
  bool inkscape_ = false;
};

ImportOptions randomOptions(std::mt19937_64& rng) {
  ImportOptions o;
  o.toleranceMm = std::uniform_real_distribution<double>(0.005, 0.5)(rng);
  o.outlineFills = rng() % 2 == 0;
  const LayerMode modes[] = {LayerMode::Auto, LayerMode::ByGroup, LayerMode::ByColor};
  o.layerMode = modes[rng() % 3];
  if (rng() % 4 == 0) o.forcedWidthMm = 123.0;
  return o;
}

TEST(DirectReader, RandomSubsetDocumentsImportExactlyAsTheGeneralPath) {
  std::mt19937_64 rng = test::rng();
  SubsetDocument generator(rng);
  for (int i = 0; i < 400; ++i) {
    const QByteArray svg = QByteArray::fromStdString(generator.make());
    const ImportOptions o = randomOptions(rng);
    DirectCapture capture;
    ASSERT_EQ(captureDirect(svg, o, {}, capture), DirectStatus::Captured) << svg.toStdString();
    const ImportResult direct = importSvgData(svg, QStringLiteral("doc.svg"), o);
    const ImportResult general = importSvgDataGeneral(svg, QStringLiteral("doc.svg"), o);
    ASSERT_EQ(difference(direct, general), "") << "document " << i << ":\n" << svg.toStdString();
  }
}

TEST(DirectReader, TheTenMegabyteStyleOfPlotterFileIsCaptured) {
  std::mt19937_64 rng = test::rng();
  std::string body;
  for (int i = 0; i < 200; ++i) {
    body += "<path d=\"M" + std::to_string(rng() % 200) + " " + std::to_string(rng() % 150);
    for (int k = 0; k < 4; ++k)
      body += " C" + std::to_string(rng() % 200) + ".5 " + std::to_string(rng() % 150) + " " +
              std::to_string(rng() % 200) + " " + std::to_string(rng() % 150) + ".25 " +
              std::to_string(rng() % 200) + " " + std::to_string(rng() % 150);
    body += "\"/>\n<polyline points=\"1 2 30 40 " + std::to_string(rng() % 200) + " 7 \"/>\n";
  }
  const QByteArray svg = QByteArray::fromStdString(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"150mm\" viewBox=\"0 0 200 150\">\n"
      "<g fill=\"none\" stroke=\"black\" stroke-width=\"0.3\">\n" + body + "</g>\n</svg>\n");
  ImportOptions o;
  o.toleranceMm = 0.04;
  DirectCapture capture;
  ASSERT_EQ(captureDirect(svg, o, {}, capture), DirectStatus::Captured);
  const ImportResult direct = importSvgData(svg, QStringLiteral("plot.svg"), o);
  ASSERT_TRUE(direct.ok()) << direct.message;
  EXPECT_EQ(test::pathCount(direct.drawing), 400u);
  EXPECT_EQ(difference(direct, importSvgDataGeneral(svg, QStringLiteral("plot.svg"), o)), "");
}

// Each of these leaves the subset somewhere; the direct reader must decline (never guess) and
// the import must still be the general path's.
TEST(DirectReader, DocumentsOutsideTheSubsetAreDeclinedAndImportAsBefore) {
  const std::string shape = "<path d=\"M1 1 L9 9\" stroke=\"black\"/>";
  const std::vector<std::string> outside = {
      test::page("<rect x=\"1\" y=\"1\" width=\"5\" height=\"5\" stroke=\"black\"/>"),
      test::page("<g transform=\"translate(5,5)\">" + shape + "</g>"),
      test::page("<path d=\"M1 1 A 5 5 0 0 1 9 9\" stroke=\"black\"/>"),
      test::page("<path d=\"M1 1 L9 9\" style=\"stroke:black\"/>"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" opacity=\"0.5\"/>"),
      test::page("<path d=\"M1 1 L9 nan\" stroke=\"black\"/>"),
      test::page("<path d=\"M1 1 L9 9 X\" stroke=\"black\"/>"),
      test::page("<path d=\"M1 1 L9\" stroke=\"black\"/>"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"url(#g)\"/>"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" stroke-width=\"1mm\"/>"),
      test::page("<text x=\"1\" y=\"5\">A</text>"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" stroke=\"red\"/>"),
      test::page("<g>" + shape),
      test::page(shape + "text between"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\"/><!-- a -- b -->"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"&#x23;000\"/>"),
      "<!DOCTYPE svg [<!ENTITY a \"b\">]>" + test::page(shape),
      test::page(shape) + "<extra/>",
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" xlink:href=\"#a\"/>"),
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" onclick=\"x()\"/>"),
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"0\" height=\"10\">" + shape + "</svg>",
      "<svg width=\"10mm\" height=\"10mm\">" + shape + "</svg>",
      test::page("<path d=\"M1 1 L9 9\" stroke=\"black\" stroke-width=\"0.0009765625\"/>"),
  };
  for (const std::string& text : outside) {
    const QByteArray svg = QByteArray::fromStdString(text);
    DirectCapture capture;
    EXPECT_EQ(captureDirect(svg, {}, {}, capture), DirectStatus::Declined) << text;
    EXPECT_EQ(difference(importSvgData(svg, QStringLiteral("x.svg")),
                         importSvgDataGeneral(svg, QStringLiteral("x.svg"))), "")
        << text;
  }
}

TEST(DirectReader, LongPathsThatTheSanitiserWouldSplitAreDeclined) {
  std::string d = "M0 0";
  for (int i = 0; i < 6000; ++i) d += " C1 1 2 2 " + std::to_string(i % 90) + " 3";
  const QByteArray svg = QByteArray::fromStdString(test::page("<path d=\"" + d + "\" stroke=\"black\"/>"));
  DirectCapture capture;
  EXPECT_EQ(captureDirect(svg, {}, {}, capture), DirectStatus::Declined);
  const ImportResult r = importSvgData(svg, QStringLiteral("long.svg"));
  ASSERT_TRUE(r.ok()) << r.message;
  bool warned = false;
  for (const fivebar::Message& w : r.warnings) warned = warned || w.text().find("split") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(DirectReader, CancelIsHonouredAndTheSinkReceivesEveryRunInOrder) {
  std::string body;
  for (int i = 0; i < 20000; ++i)
    body += "<polyline points=\"" + std::to_string(i % 97) + " 1 5 " + std::to_string(i % 13) + " 9 9\"/>";
  const QByteArray svg = QByteArray::fromStdString(test::page("<g stroke=\"black\" fill=\"none\">" + body + "</g>"));
  std::size_t streamed = 0;
  RunSink sink;
  sink.take = [&](std::vector<CapturedRun>& runs) {
    for (const CapturedRun& r : runs) streamed += r.paths.size();
  };
  DirectCapture capture;
  ASSERT_EQ(captureDirect(svg, {}, {}, capture, sink), DirectStatus::Captured);
  std::size_t kept = 0;
  for (const CapturedRun& r : capture.runs) kept += r.paths.size();
  EXPECT_GT(streamed, 0u);
  EXPECT_EQ(streamed + kept, 20000u);
  std::atomic<bool> cancel{true};
  ImportOptions o;
  o.cancel = &cancel;
  EXPECT_EQ(captureDirect(svg, o, {}, capture), DirectStatus::Cancelled);
  EXPECT_EQ(importSvgData(svg, QStringLiteral("c.svg"), o).status, ImportStatus::Cancelled);
}

// Through the worker, the streamed runs (several chunks) and a late decline (a <rect> after
// megabytes of plain paths: the worker sends a restart record) give the general path's result.
TEST(DirectReader, WorkerStreamsTheSameDrawingAndRestartsAfterALateDecline) {
  ASSERT_FALSE(findSvgWorker().isEmpty()) << "fivebar-svg-worker not built";
  std::string body;
  for (int i = 0; i < 6000; ++i)
    body += "<path d=\"M" + std::to_string(i % 190) + " 5 C 20 30 " + std::to_string(i % 70) +
            " 90 150 " + std::to_string(i % 140) + "\"/>\n";
  QTemporaryDir dir;
  for (const std::string& tail : {std::string(), std::string("<rect width=\"5\" height=\"5\"/>")}) {
    const QByteArray svg = QByteArray::fromStdString(test::page("<g stroke=\"black\" fill=\"none\">" + body + tail + "</g>", 200, 150));
    const QString path = dir.filePath(tail.empty() ? QStringLiteral("plain.svg") : QStringLiteral("late.svg"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(svg);
    f.close();
    ImportOptions o;
    o.toleranceMm = 0.01;  // many points: several 512 kB chunks
    const ImportResult viaWorker = importSvgFile(path, o);
    ASSERT_TRUE(viaWorker.ok()) << viaWorker.message;
    EXPECT_EQ(difference(viaWorker, importSvgDataGeneral(svg, path, o)), "") << path.toStdString();
  }
}

}  // namespace
}  // namespace fivebar::svg
