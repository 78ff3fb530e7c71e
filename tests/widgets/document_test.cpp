// StudioDocument: every edit is undoable, merges by gesture, and signals what changed.
#include <gtest/gtest.h>

#include <QSignalSpy>

#include "widgets/studio_document.hpp"

namespace fivebar::widgets {
namespace {

Drawing threeLayers() {
  Drawing d;
  d.source = "test";
  for (int i = 0; i < 3; ++i) {
    Layer l;
    l.id = "layer" + std::to_string(i);
    l.name = "Layer " + std::to_string(i);
    Polyline p;
    p.points = {Vec2(i, 0.0), Vec2(i + 1.0, 1.0)};
    l.paths.push_back(p);
    d.layers.push_back(l);
  }
  return d;
}

MachineProfile profile() {
  auto p = preset("maker-plotter");
  EXPECT_TRUE(p.has_value());
  return p.value_or(MachineProfile{});
}

TEST(StudioDocument, ImportIsUndoable) {
  StudioDocument doc(profile());
  QSignalSpy drawingSpy(&doc, &StudioDocument::drawingChanged);
  Placement at;
  at.centerMm = Vec2(5.0, 150.0);
  doc.replaceDrawing(threeLayers(), QStringLiteral("a.svg"), at);
  EXPECT_TRUE(doc.hasDrawing());
  EXPECT_EQ(doc.fileName(), QStringLiteral("a.svg"));
  EXPECT_EQ(doc.placement().centerMm, Vec2(5.0, 150.0));
  doc.undoStack()->undo();
  EXPECT_FALSE(doc.hasDrawing());
  EXPECT_EQ(doc.placement().centerMm, Vec2::Zero());
  doc.undoStack()->redo();
  EXPECT_EQ(doc.drawing().layers.size(), 3u);
  EXPECT_EQ(drawingSpy.count(), 3);
}

TEST(StudioDocument, PlacementEditsUndoAndRedo) {
  StudioDocument doc(profile());
  doc.replaceDrawing(threeLayers(), QStringLiteral("a.svg"), Placement{});
  QSignalSpy spy(&doc, &StudioDocument::placementChanged);
  Placement p = doc.placement();
  p.rotationRad = 0.5;
  doc.setPlacement(p);
  p.scale = 2.0;
  doc.setPlacement(p);
  EXPECT_DOUBLE_EQ(doc.placement().scale, 2.0);
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.placement().scale, 1.0);
  EXPECT_DOUBLE_EQ(doc.placement().rotationRad, 0.5);
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.placement().rotationRad, 0.0);
  doc.undoStack()->redo();
  doc.undoStack()->redo();
  EXPECT_DOUBLE_EQ(doc.placement().scale, 2.0);
  EXPECT_EQ(spy.count(), 6);
}

TEST(StudioDocument, OneGestureIsOneUndoStep) {
  StudioDocument doc(profile());
  doc.replaceDrawing(threeLayers(), QStringLiteral("a.svg"), Placement{});
  const int before = doc.undoStack()->count();
  const int gesture = doc.beginGesture();
  Placement p = doc.placement();
  for (int i = 1; i <= 20; ++i) {
    p.centerMm = Vec2(i, 2.0 * i);
    doc.setPlacement(p, gesture);
  }
  EXPECT_EQ(doc.undoStack()->count(), before + 1);
  EXPECT_EQ(doc.placement().centerMm, Vec2(20.0, 40.0));
  doc.undoStack()->undo();
  EXPECT_EQ(doc.placement().centerMm, Vec2::Zero());
  // A second gesture does not merge into the first.
  const int next = doc.beginGesture();
  doc.setPlacement(p, next);
  p.centerMm = Vec2(1.0, 1.0);
  doc.setPlacement(p, doc.beginGesture());
  EXPECT_EQ(doc.undoStack()->count(), before + 2);
}

TEST(StudioDocument, LayerVisibilityOrderAndToolAreUndoable) {
  StudioDocument doc(profile());
  doc.replaceDrawing(threeLayers(), QStringLiteral("a.svg"), Placement{});
  QSignalSpy spy(&doc, &StudioDocument::layersChanged);
  doc.setLayerVisible(1, false);
  EXPECT_FALSE(doc.drawing().layers[1].visible);
  doc.moveLayer(0, 2);
  EXPECT_EQ(doc.drawing().layers[0].id, "layer1");
  EXPECT_EQ(doc.drawing().layers[2].id, "layer0");
  EXPECT_FALSE(doc.drawing().layers[0].visible);  // the hidden layer moved with its setting
  LayerToolSettings tool;
  tool.drawSpeedMmPerS = 12.0;
  tool.pauseBefore = true;
  doc.setLayerTool(2, tool);
  EXPECT_TRUE(doc.drawing().layers[2].tool.pauseBefore);
  doc.undoStack()->undo();
  EXPECT_FALSE(doc.drawing().layers[2].tool.pauseBefore);
  doc.undoStack()->undo();
  EXPECT_EQ(doc.drawing().layers[0].id, "layer0");
  EXPECT_EQ(doc.drawing().layers[1].id, "layer1");
  EXPECT_FALSE(doc.drawing().layers[1].visible);
  doc.undoStack()->undo();
  EXPECT_TRUE(doc.drawing().layers[1].visible);
  EXPECT_EQ(doc.drawing().layers[1].paths.front().points.front(), Vec2(1.0, 0.0));
  EXPECT_EQ(spy.count(), 6);
  // No-op edits push nothing.
  const int count = doc.undoStack()->count();
  doc.setLayerVisible(0, true);
  doc.moveLayer(1, 1);
  doc.setLayerVisible(7, false);
  EXPECT_EQ(doc.undoStack()->count(), count);
}

TEST(StudioDocument, ModeSelectionAndEffectiveMode) {
  StudioDocument doc(profile());
  QSignalSpy effective(&doc, &StudioDocument::effectiveModeChanged);
  EXPECT_FALSE(doc.modeSelection().has_value());
  EXPECT_EQ(doc.effectiveMode(), doc.profile().defaultMode);
  doc.setAutoResolvedMode(WorkingMode::MinusPlus);
  EXPECT_EQ(doc.effectiveMode(), WorkingMode::MinusPlus);
  doc.setModeSelection(WorkingMode::MinusMinus);
  EXPECT_EQ(doc.effectiveMode(), WorkingMode::MinusMinus);
  doc.undoStack()->undo();
  EXPECT_EQ(doc.effectiveMode(), WorkingMode::MinusPlus);
  EXPECT_EQ(effective.count(), 3);
}

TEST(StudioDocument, ProfileEditIsUndoable) {
  StudioDocument doc(profile());
  MachineProfile p = doc.profile();
  p.geometry.a1 += 10.0;
  QSignalSpy spy(&doc, &StudioDocument::profileChanged);
  doc.setProfile(p);
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, p.geometry.a1);
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, p.geometry.a1 - 10.0);
  EXPECT_EQ(spy.count(), 2);
}

}  // namespace
}  // namespace fivebar::widgets
