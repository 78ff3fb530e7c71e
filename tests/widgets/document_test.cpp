// SPDX-License-Identifier: GPL-3.0-or-later
// StudioDocument: every edit is undoable, merges by gesture, and signals what changed; the
// placement tool turns mouse drags into one undoable edit each.
#include <gtest/gtest.h>

#include <QMouseEvent>
#include <QSignalSpy>
#include <cmath>

#include "core/kinematics/units.hpp"
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QPushButton>

#include "core/planning/auto_placement.hpp"
#include "widgets/canvas/placement_tool.hpp"
#include "widgets/panels/placement_panel.hpp"
#include "widgets/document/studio_document.hpp"

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

namespace fivebar::widgets {
namespace {

void drag(PlacementTool& tool, const paint::ViewTransform& view, QPointF from, QPointF to,
          Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  QMouseEvent press(QEvent::MouseButtonPress, from, from, Qt::LeftButton, Qt::LeftButton, modifiers);
  ASSERT_TRUE(tool.mousePress(&press, view));
  for (int i = 1; i <= 10; ++i) {
    const QPointF at = from + (to - from) * (i / 10.0);
    QMouseEvent move(QEvent::MouseMove, at, at, Qt::NoButton, Qt::LeftButton, modifiers);
    EXPECT_TRUE(tool.mouseMove(&move, view));
  }
  QMouseEvent release(QEvent::MouseButtonRelease, to, to, Qt::LeftButton, Qt::NoButton, modifiers);
  EXPECT_TRUE(tool.mouseRelease(&release, view));
}

// The placement panel offscreen: width and height in mm (aspect kept unless unlocked), "Actual
// size" back to 100 % and "Fit to workspace" as core's autoPlacement fits; each an undo step.
TEST(PlacementPanel, SizeFieldsKeepTheAspectUnlessUnlockedAndActualSizeAndFitWork) {
  StudioDocument doc(profile());
  Drawing d;
  d.source = "rect";
  d.layers.resize(1);
  d.layers[0].id = d.layers[0].name = "ink";
  d.layers[0].paths.push_back({{Vec2(0, 0), Vec2(60, 0), Vec2(60, 40), Vec2(0, 40)}, true});  // 60 x 40 mm
  Placement at;
  at.centerMm = Vec2(0.0, 170.0);
  doc.replaceDrawing(d, QStringLiteral("rect.svg"), at);
  PlacementPanel panel(doc);
  auto* width = panel.findChild<QDoubleSpinBox*>(QStringLiteral("placementWidth"));
  auto* height = panel.findChild<QDoubleSpinBox*>(QStringLiteral("placementHeight"));
  auto* scale = panel.findChild<QDoubleSpinBox*>(QStringLiteral("placementScale"));
  auto* keep = panel.findChild<QCheckBox*>(QStringLiteral("placementKeepAspect"));
  auto* actual = panel.findChild<QPushButton*>(QStringLiteral("placementActualSize"));
  auto* fit = panel.findChild<QPushButton*>(QStringLiteral("placementFit"));
  ASSERT_TRUE(width && height && scale && keep && actual && fit);
  EXPECT_NEAR(width->value(), 60.0, 1e-9);
  EXPECT_NEAR(height->value(), 40.0, 1e-9);
  ASSERT_TRUE(keep->isChecked());
  const int steps = doc.undoStack()->count();
  // Width 90 mm with the aspect kept: 150 %, the height follows.
  width->setValue(90.0);
  EXPECT_NEAR(doc.placement().scale, 1.5, 1e-9);
  EXPECT_NEAR(doc.placement().stretchY, 1.0, 1e-12);
  EXPECT_NEAR(height->value(), 60.0, 1e-6);
  EXPECT_NEAR(scale->value(), 150.0, 1e-6);
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  // Height 30 mm with the aspect kept: 75 %.
  height->setValue(30.0);
  EXPECT_NEAR(doc.placement().scale, 0.75, 1e-9);
  EXPECT_NEAR(width->value(), 45.0, 1e-6);
  // Unlocked: the height changes alone (y stretch), the width stays.
  keep->setChecked(false);
  height->setValue(60.0);
  EXPECT_NEAR(width->value(), 45.0, 1e-6);
  EXPECT_NEAR(doc.placement().scale * doc.placement().stretchY * 40.0, 60.0, 1e-6);
  EXPECT_NEAR(doc.placement().stretchY, 2.0, 1e-9);
  // Actual size: 100 %, no stretch, aspect locked again, centre unchanged.
  actual->click();
  EXPECT_DOUBLE_EQ(doc.placement().scale, 1.0);
  EXPECT_DOUBLE_EQ(doc.placement().stretchY, 1.0);
  EXPECT_TRUE(keep->isChecked());
  EXPECT_EQ(doc.placement().centerMm, Vec2(0.0, 170.0));
  EXPECT_NEAR(width->value(), 60.0, 1e-9);
  // Fit to workspace: what core's autoPlacement gives with PlacementSizing::Fit (enlarged here).
  const auto expected = autoPlacement(doc.drawing(), doc.profile(), doc.modeSelection(),
                                      doc.placement().rotationRad, PlacementSizing::Fit);
  ASSERT_TRUE(expected.has_value());
  fit->click();
  EXPECT_DOUBLE_EQ(doc.placement().scale, expected->placement.scale);
  EXPECT_EQ(doc.placement().centerMm, expected->placement.centerMm);
  EXPECT_GT(doc.placement().scale, 1.0);
  EXPECT_NEAR(width->value(), 60.0 * expected->placement.scale, 0.006);  // shown to 0.01 mm
  // Every change was one undo step; undoing the fit restores 100 %.
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.placement().scale, 1.0);
}

TEST(PlacementTool, DragsMoveScaleAndRotateInOneUndoStepEach) {
  StudioDocument doc(profile());
  Placement at;
  at.centerMm = Vec2(0.0, 150.0);
  doc.replaceDrawing(threeLayers(), QStringLiteral("a.svg"), at);  // work bounds 0..3 x 0..1 mm
  Placement big = doc.placement();
  big.scale = 20.0;  // 60 x 20 mm on the machine
  doc.setPlacement(big);
  PlacementTool tool(doc);
  const paint::ViewTransform view(QPointF(0.0, 150.0), 4.0, QSizeF(800.0, 600.0));
  const int before = doc.undoStack()->count();
  // Move: drag the body 40 px right and 20 px up = +10 mm x, +5 mm y.
  const QPointF centre = view.widgetFromMachine(QPointF(0.0, 150.0));
  EXPECT_EQ(tool.handleAt(centre, view), PlacementTool::Handle::Body);
  drag(tool, view, centre, centre + QPointF(40.0, -20.0));
  EXPECT_NEAR(doc.placement().centerMm.x(), 10.0, 1e-9);
  EXPECT_NEAR(doc.placement().centerMm.y(), 155.0, 1e-9);
  EXPECT_EQ(doc.undoStack()->count(), before + 1);
  // Scale: drag a corner twice as far from the centre.
  const auto corners = tool.cornersMm();
  ASSERT_TRUE(corners);
  const QPointF corner = view.widgetFromMachine((*corners)[2]);
  const QPointF c = view.widgetFromMachine(QPointF(10.0, 155.0));
  EXPECT_EQ(tool.handleAt(corner, view), PlacementTool::Handle::Corner);
  drag(tool, view, corner, c + 2.0 * (corner - c));
  EXPECT_NEAR(doc.placement().scale, 40.0, 1e-6);
  EXPECT_EQ(doc.undoStack()->count(), before + 2);
  // Rotate with Shift: snaps to a multiple of 15 deg.
  const auto rotated = tool.cornersMm();
  const QPointF top = (view.widgetFromMachine((*rotated)[2]) + view.widgetFromMachine((*rotated)[3])) / 2.0;
  QLineF handle(c, top);
  handle.setLength(handle.length() + PlacementTool::kRotateHandleOffsetPx);
  EXPECT_EQ(tool.handleAt(handle.p2(), view), PlacementTool::Handle::Rotate);
  drag(tool, view, handle.p2(), c + QPointF(-60.0, -48.0), Qt::ShiftModifier);
  const double deg = degFromRad(doc.placement().rotationRad);
  EXPECT_NEAR(deg / 15.0, std::round(deg / 15.0), 1e-9);
  EXPECT_GT(std::abs(deg), 10.0);
  EXPECT_EQ(doc.undoStack()->count(), before + 3);
  doc.undoStack()->undo();
  doc.undoStack()->undo();
  doc.undoStack()->undo();
  EXPECT_EQ(doc.placement().centerMm, Vec2(0.0, 150.0));
  EXPECT_DOUBLE_EQ(doc.placement().scale, 20.0);
}

}  // namespace
}  // namespace fivebar::widgets
