// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "import_support.hpp"

namespace fivebar::svg {
namespace {

using test::importText;
using test::page;

const std::string kInkscapeDoc = page(
    "<line x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\" stroke=\"#ff0000\"/>"
    "<g id=\"layer1\" inkscape:groupmode=\"layer\" inkscape:label=\"Outline\" stroke=\"#0000ff\" fill=\"none\">"
    "<path d=\"M1 1 L2 2\"/><path d=\"M3 3 L4 4\" stroke=\"#00ff00\"/></g>"
    "<g id=\"layer2\" inkscape:groupmode=\"layer\" inkscape:label=\"Hatch\" stroke=\"#000000\" fill=\"none\">"
    "<g transform=\"translate(1,1)\"><path d=\"M1 1 L2 2\"/></g></g>"
    "<path d=\"M8 8 L9 9\" stroke=\"#ff0000\" fill=\"none\"/>");

TEST(Layers, InkscapeLayersKeepIdLabelAndContentLooseShapesGoByColour) {
  const ImportResult r = importText(kInkscapeDoc);
  ASSERT_TRUE(r.ok()) << r.message;
  const auto& layers = r.drawing.layers;
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[0].id, "color:#ff0000");
  EXPECT_EQ(layers[0].rgb, 0xff0000u);
  EXPECT_EQ(layers[0].paths.size(), 2u);  // both loose red shapes, before and after the layers
  EXPECT_EQ(layers[1].id, "layer1");
  EXPECT_EQ(layers[1].name, "Outline");
  EXPECT_EQ(layers[1].rgb, 0x0000ffu);
  EXPECT_EQ(layers[1].paths.size(), 2u);  // the green path stays in its Inkscape layer
  EXPECT_EQ(layers[2].name, "Hatch");
  EXPECT_EQ(layers[2].paths.size(), 1u);
  for (const Layer& l : layers) EXPECT_TRUE(l.visible);
}

TEST(Layers, ByColourModeSplitsByStrokeColourOnly) {
  ImportOptions o;
  o.layerMode = LayerMode::ByColor;
  const ImportResult r = importText(kInkscapeDoc, o);
  ASSERT_TRUE(r.ok()) << r.message;
  std::vector<std::string> ids;
  for (const Layer& l : r.drawing.layers) ids.push_back(l.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"color:#ff0000", "color:#0000ff", "color:#00ff00",
                                           "color:#000000"}));
}

TEST(Layers, PlainTopLevelGroupsAreLayersWhenThereAreSeveral) {
  const std::string doc = page(
      "<g id=\"a\" stroke=\"#111111\" fill=\"none\"><path d=\"M0 0 L1 1\"/></g>"
      "<g stroke=\"#222222\" fill=\"none\"><path d=\"M0 0 L1 1\"/><path d=\"M2 2 L3 3\"/></g>");
  const ImportResult r = importText(doc);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.drawing.layers.size(), 2u);
  EXPECT_EQ(r.drawing.layers[0].id, "a");
  EXPECT_EQ(r.drawing.layers[0].name, "a");
  EXPECT_EQ(r.drawing.layers[1].id, "layer2");
  EXPECT_EQ(r.drawing.layers[1].name, "Layer 2");
  EXPECT_EQ(r.drawing.layers[1].paths.size(), 2u);
}

TEST(Layers, OneWrapperGroupFallsBackToColours) {
  const std::string doc = page(
      "<g fill=\"none\"><path d=\"M0 0 L1 1\" stroke=\"#123456\"/><path d=\"M0 0 L1 2\" stroke=\"#654321\"/>"
      "<path d=\"M0 0 L1 3\" stroke=\"#123456\"/></g>");
  const ImportResult r = importText(doc);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.drawing.layers.size(), 2u);
  EXPECT_EQ(r.drawing.layers[0].name, "#123456");
  EXPECT_EQ(r.drawing.layers[0].paths.size(), 2u);
  EXPECT_EQ(r.drawing.layers[1].rgb, 0x654321u);
}

}  // namespace
}  // namespace fivebar::svg
