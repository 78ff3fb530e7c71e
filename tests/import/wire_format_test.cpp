#include <gtest/gtest.h>

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
}

TEST(WireFormat, TruncatedOrForeignBytesAreRejected) {
  const QByteArray bytes = encodeResult(sample());
  ImportResult out;
  for (qsizetype cut : {qsizetype{0}, qsizetype{5}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_FALSE(decodeResult(bytes.left(cut), out)) << "cut at " << cut;
  EXPECT_FALSE(decodeResult(QByteArray("hello world, not a result"), out));
}

TEST(WireFormat, WorkerArgumentsRoundTrip) {
  ImportOptions in;
  in.toleranceMm = 0.0123;
  in.dpi = 72;
  in.forcedWidthMm = 150;
  in.outlineFills = false;
  in.layerMode = LayerMode::ByColor;
  QString path;
  ImportOptions out;
  EXPECT_EQ(parseWorkerArguments(workerArguments(QStringLiteral("x y.svg"), in), path, out), QString());
  EXPECT_EQ(path, QStringLiteral("x y.svg"));
  EXPECT_EQ(out.toleranceMm, 0.0123);
  EXPECT_EQ(out.dpi, 72.0);
  EXPECT_EQ(out.forcedWidthMm, 150.0);
  EXPECT_FALSE(out.outlineFills);
  EXPECT_EQ(out.layerMode, LayerMode::ByColor);
  EXPECT_FALSE(parseWorkerArguments({QStringLiteral("--bogus"), QStringLiteral("1")}, path, out).isEmpty());
}

}  // namespace
}  // namespace fivebar::svg
