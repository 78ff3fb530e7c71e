// SPDX-License-Identifier: GPL-3.0-or-later
// Smaller findings of issue 26, each on the whole window offscreen: Ctrl+Y redoes, an undone
// rotation is named so in the Edit menu, opening a drawing is not an unsaved change, counts are
// written with the locale's thousands separators, English plurals are singular for one, and the
// Help menu opens documentation files that exist.
#include <gtest/gtest.h>

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QTranslator>
#include <QUndoStack>

#include "app/studio/file_actions.hpp"
#include "app/studio/help_menu.hpp"
#include "app/studio/main_window.hpp"
#include "core/machine/profile.hpp"
#include "session/machine_session.hpp"
#include "tests/widgets/event_wait.hpp"
#include "widgets/document/import_controller.hpp"
#include "paint/studio_palette.hpp"
#include "paint/view_transform.hpp"
#include "widgets/canvas/path_scene.hpp"
#include "widgets/document/job_pipeline.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/machine/jog_goto_tool.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"

namespace fivebar {
namespace {

using test::waitUntil;

constexpr int kWaitMs = 60000;

bool openDemo(studio::MainWindow& w) {
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  if (!demo.open(QIODevice::ReadOnly)) return false;
  w.importer().setInteractive(false);
  w.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  return waitUntil([&] { return w.document().hasDrawing() && !w.importer().busy(); }, kWaitMs);
}

QAction* editAction(studio::MainWindow& w, const QString& objectName) {
  return w.findChild<QAction*>(objectName);
}

TEST(StudioFindings, CtrlYRedoesAsCtrlShiftZDoes) {
  studio::MainWindow w(*preset("maker-plotter"));
  ASSERT_TRUE(openDemo(w));
  QAction* redo = editAction(w, QStringLiteral("actionRedo"));
  ASSERT_NE(redo, nullptr);
  EXPECT_TRUE(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
  EXPECT_TRUE(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
  Placement moved = w.document().placement();
  moved.centerMm.x() += 5.0;
  w.document().setPlacement(moved);
  w.document().undoStack()->undo();
  ASSERT_TRUE(redo->isEnabled());
  redo->trigger();
  EXPECT_DOUBLE_EQ(w.document().placement().centerMm.x(), moved.centerMm.x());
}

TEST(StudioFindings, AnUndoneRotationIsNamedRotateDrawing) {
  studio::MainWindow w(*preset("maker-plotter"));
  ASSERT_TRUE(openDemo(w));
  Placement turned = w.document().placement();
  turned.rotationRad += 0.3;
  w.document().setPlacement(turned);
  QAction* undo = editAction(w, QStringLiteral("actionUndo"));
  ASSERT_NE(undo, nullptr);
  EXPECT_EQ(w.document().undoStack()->undoText(), QStringLiteral("Rotate drawing"));
  EXPECT_TRUE(undo->text().contains(QStringLiteral("Rotate drawing"))) << undo->text().toStdString();
  Placement moved = w.document().placement();
  moved.centerMm.y() += 4.0;
  w.document().setPlacement(moved);
  EXPECT_EQ(w.document().undoStack()->undoText(), QStringLiteral("Move drawing"));
  Placement bigger = w.document().placement();
  bigger.scale *= 1.1;
  w.document().setPlacement(bigger);
  EXPECT_EQ(w.document().undoStack()->undoText(), QStringLiteral("Resize drawing"));
}

TEST(StudioFindings, OpeningADrawingIsNotAnUnsavedChangeUntilAnEdit) {
  studio::MainWindow w(*preset("maker-plotter"));
  int asked = 0;
  w.files().setAsk([&](const QString&) {
    ++asked;
    return QMessageBox::Cancel;
  });
  w.show();
  ASSERT_TRUE(openDemo(w));
  EXPECT_FALSE(w.document().isModified());
  EXPECT_FALSE(w.isWindowModified());
  EXPECT_TRUE(w.files().maybeSave());
  EXPECT_EQ(asked, 0) << "nothing to save after only opening an SVG";
  // An edit is a change: now the question comes (and Cancel keeps the window open).
  Placement moved = w.document().placement();
  moved.centerMm.x() += 3.0;
  w.document().setPlacement(moved);
  EXPECT_TRUE(w.document().isModified());
  EXPECT_FALSE(w.close());
  EXPECT_EQ(asked, 1);
  // Undone back to the import: nothing to save again.
  w.document().undoStack()->undo();
  EXPECT_FALSE(w.document().isModified());
}

TEST(StudioFindings, LargeCountsHaveThousandsSeparators) {
  PlannedJob job;
  job.summary.segments = 2500000;
  job.summary.estimatedTimeS = 9.0 * 3600.0;
  const QLocale before;
  QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
  EXPECT_TRUE(widgets::longJobQuestion(job).contains(QStringLiteral("2,500,000"))) << widgets::longJobQuestion(job).toStdString();
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  EXPECT_TRUE(widgets::longJobQuestion(job).contains(QStringLiteral("2.500.000"))) << widgets::longJobQuestion(job).toStdString();
  QLocale::setDefault(before);
}

// English has its plural forms too (translations/plurals_en.ts): "1 checked move".
TEST(StudioFindings, EnglishSaysOneCheckedMoveNotOneCheckedMoves) {
  QTranslator plurals;
  ASSERT_TRUE(plurals.load(QStringLiteral(":/i18n/plurals_en.qm")));
  QCoreApplication::installTranslator(&plurals);
  const char* text = "Go to %1, %2 mm? The dashed path is the pen's travel (%n checked move(s)).";
  EXPECT_TRUE(widgets::GoToTool::tr(text, nullptr, 1).contains(QStringLiteral("(1 checked move).")));
  EXPECT_TRUE(widgets::GoToTool::tr(text, nullptr, 3).contains(QStringLiteral("(3 checked moves).")));
  EXPECT_TRUE(session::MachineSession::tr("%1 (jog in %n checked move(s))", nullptr, 1).endsWith(QStringLiteral("(jog in 1 checked move)")));
  EXPECT_EQ(widgets::MachineSettingsDialog::tr("%n setting(s) differ from the profile.", nullptr, 1),
            QStringLiteral("1 setting differs from the profile."));
  QCoreApplication::removeTranslator(&plurals);
}

// Only the offending path turns red on the canvas, not its whole layer.
TEST(StudioFindings, OnlyTheOffendingPathIsRed) {
  Layer layer;
  layer.id = layer.name = "ink";
  layer.paths.push_back({{Vec2(-5.0, 0.0), Vec2(5.0, 0.0)}});      // reachable
  layer.paths.push_back({{Vec2(-5.0, 20.0), Vec2(5.0, 20.0)}});    // reachable
  layer.paths.push_back({{Vec2(-5.0, 300.0), Vec2(5.0, 300.0)}});  // far out of reach
  auto drawing = std::make_shared<Drawing>();
  drawing->layers.push_back(layer);
  widgets::PipelineInput input;
  input.drawing = drawing;
  input.placement.centerMm = Vec2(0.0, 250.0);  // the paths at y = 100, 120 and 400 mm
  input.profile = *preset("maker-plotter");
  input.modeSelection = WorkingMode::PlusPlus;
  const widgets::PreviewResult r = widgets::runPipeline(input);
  ASSERT_EQ(r.status, widgets::PreviewStatus::Infeasible) << r.message.toStdString();
  for (const widgets::PreviewProblem& p : r.problems) EXPECT_EQ(p.pathIndex, 2) << p.text.toStdString();
  ASSERT_TRUE(r.drawingScene);
  const paint::ViewTransform view(QPointF(0.0, 250.0), 1.0, QSizeF(400.0, 400.0));
  QImage image(400, 400, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  {
    QPainter painter(&image);
    r.drawingScene->paint(painter, view, widgets::ScenePaintOptions{});
  }
  const QRgb red = paint::palette::problem().rgb();
  const auto colourAt = [&](double yMm) {  // the path's middle pixel
    const QPointF px = view.widgetFromMachine(QPointF(0.0, yMm));
    return image.pixelColor(px.toPoint()).rgb();
  };
  EXPECT_EQ(colourAt(400.0), red);
  EXPECT_NE(colourAt(100.0), red);
  EXPECT_NE(colourAt(120.0), red);
  EXPECT_NE(qAlpha(colourAt(100.0)), 0) << "the reachable path is drawn";
}

TEST(StudioFindings, HelpMenuOpensTheDocumentationAndTheFirstJobGuide) {
  studio::MainWindow w(*preset("maker-plotter"));
  QStringList opened;
  w.help().setOpener([&](const QString& path) {
    opened << path;
    return true;
  });
  QAction* guide = w.findChild<QAction*>(QStringLiteral("actionFirstJobGuide"));
  QAction* docs = w.findChild<QAction*>(QStringLiteral("actionDocumentation"));
  ASSERT_NE(guide, nullptr);
  ASSERT_NE(docs, nullptr);
  // Both are in the Help menu.
  QMenu* help = nullptr;
  for (QAction* a : w.menuBar()->actions())
    if (a->menu() != nullptr && a->menu()->actions().contains(guide)) help = a->menu();
  ASSERT_NE(help, nullptr);
  EXPECT_TRUE(help->actions().contains(docs));
  guide->trigger();
  docs->trigger();
  ASSERT_EQ(opened.size(), 2);
  EXPECT_TRUE(opened[0].endsWith(QStringLiteral("/first-job.md"))) << opened[0].toStdString();
  EXPECT_TRUE(opened[1].endsWith(QStringLiteral("/studio.md"))) << opened[1].toStdString();
  for (const QString& path : opened) EXPECT_TRUE(QFileInfo(path).isFile()) << path.toStdString();
  EXPECT_FALSE(studio::documentationDir().isEmpty());
}

}  // namespace
}  // namespace fivebar
