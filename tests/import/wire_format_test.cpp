// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <QTemporaryFile>

#include <cstring>
#include <functional>

#include "core/import/wire_format.hpp"

namespace fivebar::svg {
namespace {

ImportResult sample() {
  ImportResult r;
  r.warnings = {"<image> element removed (1x, first at line 3)"};
  r.drawing.source = "a.svg";
  r.drawing.widthMm = 210.0;
  r.drawing.heightMm = 297.0;
  Layer layer;
  layer.id = "layer1";
  layer.name = "Outline";
  layer.rgb = 0x123456;
  layer.paths.push_back(Polyline{{Vec2(0.1, 0.2), Vec2(1e-300, -5e5)}, false});
  layer.paths.push_back(Polyline{{Vec2(1, 1), Vec2(2, 1), Vec2(2, 2)}, true});
  layer.paths.back().fill = FillRule::EvenOdd;
  layer.paths.back().fillStart = true;
  layer.paths.back().fillOnly = true;
  layer.paths.back().flattened = true;
  r.drawing.layers.push_back(layer);
  return r;
}

TEST(WireFormat, RoundTripIsExact) {
  const ImportResult in = sample();
  ImportResult out;
  ASSERT_TRUE(decodeResult(encodeResult(in), out));
  EXPECT_EQ(out.status, in.status);
  EXPECT_EQ(out.warnings, in.warnings);
  EXPECT_EQ(out.drawing.source, "a.svg");
  EXPECT_EQ(out.drawing.heightMm, 297.0);
  ASSERT_EQ(out.drawing.layers.size(), 1u);
  const Layer& l = out.drawing.layers[0];
  EXPECT_EQ(l.name, "Outline");
  EXPECT_EQ(l.rgb, 0x123456u);
  ASSERT_EQ(l.paths.size(), 2u);
  EXPECT_EQ(l.paths[0].points, in.drawing.layers[0].paths[0].points);
  EXPECT_TRUE(l.paths[1].closed);
  EXPECT_EQ(l.paths[1].fill, FillRule::EvenOdd);
  EXPECT_TRUE(l.paths[1].fillStart && l.paths[1].fillOnly && l.paths[1].flattened);
  EXPECT_EQ(l.paths[0].fill, FillRule::None);
  EXPECT_FALSE(l.paths[0].fillStart || l.paths[0].fillOnly || l.paths[0].flattened);
}

TEST(WireFormat, TruncatedOrForeignBytesAreRejected) {
  const QByteArray bytes = encodeResult(sample());
  ImportResult out;
  for (qsizetype cut : {qsizetype{0}, qsizetype{5}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_FALSE(decodeResult(bytes.left(cut), out)) << "cut at " << cut;
  EXPECT_FALSE(decodeResult(QByteArray("hello world, not a result"), out));
}

// A ByteSource over a string, for the stream decoder.
class StringSource final : public ByteSource {
 public:
  explicit StringSource(QByteArray bytes) : bytes_(std::move(bytes)) {}
  bool read(void* dst, std::size_t n) override {
    if (n > static_cast<std::size_t>(bytes_.size() - pos_)) return false;
    std::memcpy(dst, bytes_.constData() + pos_, n);
    pos_ += static_cast<qsizetype>(n);
    return true;
  }

 private:
  QByteArray bytes_;
  qsizetype pos_ = 0;
};

// Writes a capture stream through a real pipe (as the worker does) and returns its bytes.
QByteArray streamBytes(const std::function<void(CaptureStreamWriter&)>& write) {
  QTemporaryFile file;
  EXPECT_TRUE(file.open());
  {
    CaptureStreamWriter w(file.handle());
    write(w);
  }
  file.seek(0);
  return file.readAll();
}

Capture sampleCapture() {
  Capture c;
  c.runs.push_back(CapturedRun{0, 0x112233, {Polyline{{Vec2(0.5, 1e-300), Vec2(-3, 7)}, false}}});
  c.runs.push_back(CapturedRun{1, 0x000000, {Polyline{{Vec2(1, 1), Vec2(2, 1), Vec2(2, 2)}, true}}});
  c.topLevel.push_back(TopLevelElement{QStringLiteral("g"), QStringLiteral("L1"), QStringLiteral("Pen \u00e9"), true});
  c.topLevel.push_back(TopLevelElement{QStringLiteral("path"), {}, {}, false});
  c.page.sizeKnown = true;
  c.page.widthMm = 210;
  c.page.heightMm = 297;
  c.warnings = {"CSS @import removed (1x, first at line 2)"};
  return c;
}

TEST(WireFormat, CaptureStreamRoundTripsAndRestartForgetsEarlierRuns) {
  const Capture in = sampleCapture();
  const QByteArray bytes = streamBytes([&](CaptureStreamWriter& w) {
    w.runs({CapturedRun{5, 0xabcdef, {Polyline{{Vec2(9, 9), Vec2(8, 8)}, false}}}});
    w.restart();  // the direct reader declined: the general path starts over
    w.runs({in.runs[0]});
    Capture rest = in;
    rest.runs.erase(rest.runs.begin());
    EXPECT_TRUE(w.finish(rest, {"Qt (qt.svg): something"}));
  });
  StringSource source(bytes);
  StreamedCapture out;
  ASSERT_TRUE(decodeCaptureStream(source, out));
  const Capture& c = out.capture;
  ASSERT_EQ(c.runs.size(), 2u);
  EXPECT_EQ(c.runs[0].topIndex, 0);
  EXPECT_EQ(c.runs[0].rgb, 0x112233u);
  EXPECT_EQ(c.runs[0].paths[0].points, in.runs[0].paths[0].points);
  EXPECT_TRUE(c.runs[1].paths[0].closed);
  ASSERT_EQ(c.topLevel.size(), 2u);
  EXPECT_EQ(c.topLevel[0].label, QStringLiteral("Pen \u00e9"));
  EXPECT_TRUE(c.topLevel[0].inkscapeLayer);
  EXPECT_EQ(c.topLevel[1].tag, QStringLiteral("path"));
  EXPECT_TRUE(c.page.sizeKnown);
  EXPECT_EQ(c.page.heightMm, 297.0);
  EXPECT_EQ(c.warnings, in.warnings);
  EXPECT_EQ(out.qtMessages, std::vector<std::string>{"Qt (qt.svg): something"});
  for (qsizetype cut : {qsizetype{0}, qsizetype{3}, bytes.size() / 2, bytes.size() - 1}) {
    StringSource truncated(bytes.left(cut));
    StreamedCapture partial;
    EXPECT_FALSE(decodeCaptureStream(truncated, partial)) << "cut at " << cut;
  }
}

TEST(WireFormat, AFailedCaptureTravelsWithItsStatusAndMessage) {
  Capture failed;
  failed.status = ImportStatus::MalformedXml;
  failed.message = "x.svg: line 3, column 1: Premature end of document.";
  StringSource source(streamBytes([&](CaptureStreamWriter& w) { EXPECT_TRUE(w.finish(failed, {})); }));
  StreamedCapture out;
  ASSERT_TRUE(decodeCaptureStream(source, out));
  EXPECT_EQ(out.capture.status, ImportStatus::MalformedXml);
  EXPECT_EQ(out.capture.message, failed.message);
  const ImportResult r = finishImport(std::move(out.capture), QStringLiteral("x.svg"), {});
  EXPECT_EQ(r.status, ImportStatus::MalformedXml);
  EXPECT_EQ(r.message, failed.message);
}

TEST(WireFormat, APointBudgetStopTravelsWithItsStatus) {
  Capture failed;
  failed.status = ImportStatus::TooManyPoints;
  failed.message = "x.svg: more than 10 points after flattening (the points budget): reading stopped there";
  StringSource source(streamBytes([&](CaptureStreamWriter& w) { EXPECT_TRUE(w.finish(failed, {})); }));
  StreamedCapture out;
  ASSERT_TRUE(decodeCaptureStream(source, out));
  EXPECT_EQ(out.capture.status, ImportStatus::TooManyPoints);
  EXPECT_EQ(out.capture.message, failed.message);
}

TEST(WireFormat, WorkerArgumentsRoundTrip) {
  ImportOptions in;
  in.toleranceMm = 0.0123;
  in.dpi = 72;
  in.forcedWidthMm = 150;
  in.outlineFills = false;
  in.layerMode = LayerMode::ByColor;
  in.maxPoints = 12345;
  in.textFont = "/fonts/my font.jhf";
  QString path;
  ImportOptions out;
  EXPECT_EQ(parseWorkerArguments(workerArguments(QStringLiteral("x y.svg"), in), path, out), QString());
  EXPECT_EQ(path, QStringLiteral("x y.svg"));
  EXPECT_EQ(out.toleranceMm, 0.0123);
  EXPECT_EQ(out.dpi, 72.0);
  EXPECT_EQ(out.forcedWidthMm, 150.0);
  EXPECT_FALSE(out.outlineFills);
  EXPECT_EQ(out.layerMode, LayerMode::ByColor);
  EXPECT_EQ(out.maxPoints, 12345u);
  EXPECT_EQ(out.textFont, "/fonts/my font.jhf");
  EXPECT_FALSE(parseWorkerArguments({QStringLiteral("--bogus"), QStringLiteral("1")}, path, out).isEmpty());
  int fd = -1;
  const QStringList withFd = QStringList{QString::fromLatin1(kResultFdOption), QStringLiteral("7")} +
                             workerArguments(QStringLiteral("a.svg"), in);
  EXPECT_EQ(parseWorkerArguments(withFd, path, out, &fd), QString());
  EXPECT_EQ(fd, 7);
  EXPECT_FALSE(parseWorkerArguments(withFd, path, out).isEmpty());  // only where it is expected
}

}  // namespace
}  // namespace fivebar::svg
