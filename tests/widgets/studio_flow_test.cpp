// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's flows end to end, offscreen: import a drawing (through the isolated worker),
// placement fitted into the workspace, mode choice, the planned preview, the simulation running
// to the end, and the main window painting a planned job.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPainter>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <set>

#include "app/studio/main_window.hpp"
#include "test_files.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "paint/studio_palette.hpp"
#include "core/planning/auto_placement.hpp"
#include "core/planning/planner.hpp"
#include "paint/view_transform.hpp"
#include "widgets/document/job_pipeline.hpp"
#include "widgets/canvas/workspace_cache.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kWaitMs = 30000;

MachineProfile makerPlotter() {
  auto p = preset("maker-plotter");
  EXPECT_TRUE(p.has_value());
  return p.value_or(MachineProfile{});
}

// A 40 x 30 mm drawing with two colours (two layers).
QString writeDrawing(const QTemporaryDir& dir) {
  const QString path = dir.filePath(QStringLiteral("two-colours.svg"));
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(R"(<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="30mm" viewBox="0 0 40 30">
  <rect x="2" y="2" width="36" height="26" fill="none" stroke="#ff0000" stroke-width="0.3"/>
  <circle cx="20" cy="15" r="10" fill="none" stroke="#0000ff" stroke-width="0.3"/>
</svg>)");
  return path;
}

struct Studio {
  StudioDocument doc{makerPlotter()};
  WorkspaceCache workspace{doc};
  PreviewController preview{doc};
  SimulationController sim;
  ImportController importer{doc, nullptr};
  Studio() { importer.setInteractive(false); }
};

bool importAndWait(Studio& s, const QString& path, QString* message = nullptr) {
  QSignalSpy done(&s.importer, &ImportController::finished);
  s.importer.openFile(path);
  if (!done.wait(kWaitMs)) return false;
  if (message) *message = done.front().at(1).toString();
  return done.front().at(0).toBool();
}

PreviewResult planAndWait(Studio& s) {
  QSignalSpy ready(&s.preview, &PreviewController::resultChanged);
  s.preview.replanNow();
  EXPECT_TRUE(ready.wait(kWaitMs));
  return s.preview.result();
}

TEST(StudioFlow, ImportPlacesTheDrawingAtTrueSizeInsideTheSafeRectangle) {
  QTemporaryDir dir;
  Studio s;
  QString note;
  ASSERT_TRUE(importAndWait(s, writeDrawing(dir), &note));
  EXPECT_TRUE(note.isEmpty()) << note.toStdString();  // it fits: nothing to say
  EXPECT_EQ(s.doc.drawing().layers.size(), 2u);
  EXPECT_DOUBLE_EQ(s.doc.placement().scale, 1.0);  // true size, not blown up to the rectangle
  const auto rule = autoPlacement(s.doc.drawing(), s.doc.profile(), std::nullopt, 0.0,
                                    PlacementSizing::TrueSize);
  ASSERT_TRUE(rule);
  const RectMm rect = rule->rectMm;
  EXPECT_EQ(s.doc.placement().centerMm, rect.center());  // centred in the rule's rectangle
  const auto strokes = placeDrawing(s.doc.drawing(), s.doc.placement());
  const auto bounds = strokeBounds(strokes);
  ASSERT_TRUE(bounds);
  EXPECT_GE(bounds->x0, rect.x0 - 1e-6);
  EXPECT_LE(bounds->x1, rect.x1 + 1e-6);
  EXPECT_GE(bounds->y0, rect.y0 - 1e-6);
  EXPECT_LE(bounds->y1, rect.y1 + 1e-6);
  EXPECT_NEAR(bounds->width(), 36.0, 0.05);  // the 36 mm rectangle (centre line), not enlarged
  // Undo removes the import; redo restores it with its placement.
  const Placement placed = s.doc.placement();
  s.doc.undoStack()->undo();
  EXPECT_FALSE(s.doc.hasDrawing());
  s.doc.undoStack()->redo();
  EXPECT_EQ(s.doc.placement().centerMm, placed.centerMm);
}

// A drawing too big for the workspace is scaled down on import to the rule's rectangle (the
// scale `fivebar plan` picks), and the studio says so: the import's message and the Placement
// panel's note.
TEST(StudioFlow, ADrawingTooBigIsScaledDownAndTheStudioSaysSo) {
  studio::MainWindow window(makerPlotter());
  window.resize(1400, 900);
  window.show();
  window.importer().setInteractive(false);
  QSignalSpy imported(&window.importer(), &ImportController::finished);
  window.importer().openData(R"(<svg xmlns="http://www.w3.org/2000/svg" width="1000mm" height="1000mm" viewBox="0 0 40 40">
  <rect x="2" y="2" width="36" height="36" fill="none" stroke="#000000"/></svg>)",
                             QStringLiteral("poster.svg"));
  ASSERT_TRUE(imported.wait(kWaitMs));
  ASSERT_TRUE(imported.front().at(0).toBool());
  const QString message = imported.front().at(1).toString();
  const double scale = window.document().placement().scale;
  EXPECT_LT(scale, 1.0);
  const auto rule = autoPlacement(window.document().drawing(), window.document().profile(), std::nullopt, 0.0,
                                  PlacementSizing::TrueSize);
  ASSERT_TRUE(rule);
  EXPECT_DOUBLE_EQ(scale, rule->placement.scale);  // the CLI's rule
  const QString percent = QLocale().toString(scale * 100.0, 'f', scale * 100.0 < 10.0 ? 1 : 0);
  EXPECT_EQ(message, QStringLiteral("scaled to %1 % to fit the workspace").arg(percent)) << message.toStdString();
  auto* note = window.findChild<QLabel*>(QStringLiteral("placementNote"));
  ASSERT_NE(note, nullptr);
  EXPECT_TRUE(note->isVisible());
  EXPECT_EQ(note->text(), message);
}

// Pre-flight paints only the offending path red: a drawing of two squares moved so that one
// leaves the workspace is infeasible, its problems name that path only, and the drawing's scene
// paints red pixels over it and none over the other square.
TEST(StudioFlow, PreflightPaintsOnlyTheOffendingPathRed) {
  QTemporaryDir dir;
  const QString path = test::writeTestFile(dir, QStringLiteral("two-squares.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="10mm" viewBox="0 0 60 10">
  <rect x="1" y="1" width="8" height="8" fill="none" stroke="#000000"/>
  <rect x="51" y="1" width="8" height="8" fill="none" stroke="#000000"/></svg>)");
  ASSERT_FALSE(path.isEmpty());
  Studio s;
  ASSERT_TRUE(importAndWait(s, path));
  // Move the drawing right, 1 mm at a time, until the planner finds the right square (path 1)
  // outside while the left one (path 0) is still fine.
  const auto problemPaths = [&](const Placement& at) {
    std::set<int> paths;
    const PlanResult r = planJob(s.doc.drawing(), s.doc.profile(), studioPlanOptions(at, std::nullopt, 0.1));
    for (const PlanProblem& p : r.report.problems) paths.insert(p.pathIndex);
    return paths;
  };
  Placement moved = s.doc.placement();
  bool found = false;
  for (int step = 0; step < 400 && !found; ++step) {
    moved.centerMm.x() += 1.0;
    found = problemPaths(moved) == std::set<int>{1};
  }
  ASSERT_TRUE(found) << "no placement with only the right square outside";
  s.doc.setPlacement(moved);
  const PreviewResult r = planAndWait(s);
  ASSERT_EQ(r.status, PreviewStatus::Infeasible) << r.message.toStdString();
  ASSERT_FALSE(r.problems.empty());
  for (const PreviewProblem& p : r.problems) {
    EXPECT_EQ(p.layerIndex, 0);
    EXPECT_EQ(p.pathIndex, 1) << p.text.toStdString();
  }
  ASSERT_TRUE(r.drawingScene);
  // Paint the drawing's scene and look at each square's outline.
  const auto strokes = placeDrawing(s.doc.drawing(), moved);
  const QRectF all = [&] {
    const auto b = strokeBounds(strokes);
    return QRectF(QPointF(b->x0, b->y0), QPointF(b->x1, b->y1));
  }();
  paint::ViewTransform view;
  view.setViewportPx(QSizeF(800, 200));
  view.fit(all, 20.0);
  QImage image(800, 200, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    r.drawingScene->paint(painter, view, ScenePaintOptions{});
  }
  const auto redAndInk = [&](int pathIndex) {
    std::pair<int, int> counts{0, 0};
    for (const Stroke& st : strokes) {
      if (st.pathIndex != pathIndex) continue;
      for (std::size_t k = 0; k + 1 < st.points.size(); ++k) {
        const Vec2 mid = 0.5 * (st.points[k] + st.points[k + 1]);
        const QPoint px = view.widgetFromMachine(QPointF(mid.x(), mid.y())).toPoint();
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const QColor c = image.pixelColor(px + QPoint(dx, dy));
            if (c.rgb() == paint::palette::problem().rgb()) ++counts.first;
            else if (c.rgb() != QColor(Qt::white).rgb()) ++counts.second;
          }
      }
    }
    return counts;
  };
  const auto [goodRed, goodInk] = redAndInk(0);
  const auto [badRed, badInk] = redAndInk(1);
  EXPECT_EQ(goodRed, 0);
  EXPECT_GT(goodInk, 0);
  EXPECT_GT(badRed, 0);
  (void)badInk;
}

TEST(StudioFlow, ImportErrorsNameTheFile) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("broken.svg"));
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10mm\" height=\"10mm\"><path d=");
  f.close();
  Studio s;
  QString message;
  EXPECT_FALSE(importAndWait(s, path, &message));
  EXPECT_TRUE(message.contains(QStringLiteral("broken.svg"))) << message.toStdString();
  EXPECT_FALSE(s.doc.hasDrawing());
  EXPECT_FALSE(importAndWait(s, dir.filePath(QStringLiteral("missing.svg")), &message));
  EXPECT_TRUE(message.contains(QStringLiteral("missing.svg"))) << message.toStdString();
}

TEST(StudioFlow, PreviewPlansTheJobAndModesSwitch) {
  QTemporaryDir dir;
  Studio s;
  ASSERT_TRUE(importAndWait(s, writeDrawing(dir)));
  PreviewResult r = planAndWait(s);
  ASSERT_EQ(r.status, PreviewStatus::Planned) << r.message.toStdString();
  ASSERT_TRUE(r.job && r.trajectory && r.jobScene);
  EXPECT_GT(r.job->summary.segments, 10);
  EXPECT_GT(r.job->summary.penDownMm, 100.0);  // rectangle + circle of the fitted drawing
  EXPECT_GT(r.jobScene->segmentCount(), 10u);
  EXPECT_TRUE(r.problems.empty());
  ASSERT_TRUE(r.mode);
  EXPECT_EQ(s.doc.effectiveMode(), *r.mode);  // Auto shows the planner's pick
  // Choosing a mode is instant for the overlays (cached maps) and replans the job in it.
  s.doc.setModeSelection(WorkingMode::PlusPlus);
  EXPECT_EQ(s.doc.effectiveMode(), WorkingMode::PlusPlus);
  r = planAndWait(s);
  ASSERT_TRUE(r.mode);
  EXPECT_EQ(*r.mode, WorkingMode::PlusPlus);
  // A drawing moved far out of reach is infeasible, with problems that say where.
  Placement far = s.doc.placement();
  far.centerMm = Vec2(0.0, 2000.0);
  s.doc.setPlacement(far);
  r = planAndWait(s);
  EXPECT_EQ(r.status, PreviewStatus::Infeasible);
  ASSERT_FALSE(r.problems.empty());
  EXPECT_GT(r.problems.front().whereMm.y(), 1000.0);
  s.doc.undoStack()->undo();
  r = planAndWait(s);
  EXPECT_EQ(r.status, PreviewStatus::Planned);
}

// A planned job carries no drawing scene (its draw moves are the drawing); while the next plan
// runs, the canvas shows those draw moves moved to the new placement, faded, with "Planning...".
TEST(StudioFlow, WhilePlanningTheLastJobsDrawMovesShowTheDrawingAtTheNewPlacement) {
  QTemporaryDir dir;
  Studio s;
  ASSERT_TRUE(importAndWait(s, writeDrawing(dir)));
  const PreviewResult r = planAndWait(s);
  ASSERT_EQ(r.status, PreviewStatus::Planned) << r.message.toStdString();
  EXPECT_EQ(r.drawingScene, nullptr);
  ASSERT_TRUE(r.jobScene);
  JobLayer layer(s.doc, s.preview, s.sim);
  const QRectF bounds = r.jobScene->boundsMm();
  paint::ViewTransform view(bounds.center(), 1.0, QSizeF(400, 400));
  view.fit(bounds.adjusted(-60, -60, 60, 60), 10.0);
  // Painted pixels in the left and right halves of the image.
  auto painted = [&](int& left, int& right) {
    QImage image(400, 400, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    layer.paint(painter, view);
    painter.end();
    left = right = 0;
    for (int y = 60; y < 400; ++y)  // below the "Planning..." banner
      for (int x = 0; x < 400; ++x)
        if (image.pixel(x, y) != qRgb(255, 255, 255)) ++(x < 200 ? left : right);
  };
  int left = 0, right = 0;
  painted(left, right);
  ASSERT_GT(left + right, 50) << "the planned job is not painted";
  // The drawing moved 40 mm towards machine -x: the next plan starts, and the canvas shows
  // the old job's draw moves at the new place at once.
  Placement moved = s.doc.placement();
  moved.centerMm += Vec2(-40.0, 0.0);
  s.doc.setPlacement(moved);
  s.preview.replanNow();
  ASSERT_TRUE(s.preview.busy());
  int movedLeft = 0, movedRight = 0;
  painted(movedLeft, movedRight);
  EXPECT_GT(movedLeft + movedRight, 20) << "nothing shown while planning";
  const bool xRight = view.widgetFromMachine(QPointF(1, 0)).x() > view.widgetFromMachine(QPointF(0, 0)).x();
  EXPECT_GT(xRight ? movedLeft - left : movedRight - right, 0) << "not shown at the new placement";
  QSignalSpy ready(&s.preview, &PreviewController::resultChanged);
  while (s.preview.busy()) ASSERT_TRUE(ready.wait(kWaitMs));
  EXPECT_EQ(s.preview.result().status, PreviewStatus::Planned);
}

TEST(StudioFlow, HiddenLayersAreNotPlanned) {
  QTemporaryDir dir;
  Studio s;
  ASSERT_TRUE(importAndWait(s, writeDrawing(dir)));
  const double both = planAndWait(s).job->summary.penDownMm;
  s.doc.setLayerVisible(0, false);
  const PreviewResult one = planAndWait(s);
  ASSERT_EQ(one.status, PreviewStatus::Planned);
  EXPECT_LT(one.job->summary.penDownMm, both - 10.0);
  s.doc.undoStack()->undo();
  EXPECT_NEAR(planAndWait(s).job->summary.penDownMm, both, 1e-6);
}

TEST(StudioFlow, SimulationReachesTheEndAndLeavesTheTrace) {
  QTemporaryDir dir;
  Studio s;
  ASSERT_TRUE(importAndWait(s, writeDrawing(dir)));
  const PreviewResult r = planAndWait(s);
  ASSERT_EQ(r.status, PreviewStatus::Planned);
  s.sim.setTrajectory(r.trajectory);
  MachineLayer machine(s.doc, s.sim);
  QSignalSpy finished(&s.sim, &SimulationController::finished);
  s.sim.setSpeed(50.0);
  EXPECT_DOUBLE_EQ(s.sim.speed(), 50.0);
  s.sim.setSpeed(500.0);
  EXPECT_DOUBLE_EQ(s.sim.speed(), SimulationController::kMaxSpeed);
  s.sim.play();
  ASSERT_TRUE(s.sim.playing());
  // Drive the clock deterministically instead of waiting in real time.
  double lastT = 0.0;
  int steps = 0;
  while (!s.sim.atEnd() && steps < 100000) {
    s.sim.advance(0.05);
    EXPECT_GE(s.sim.timeS(), lastT);
    lastT = s.sim.timeS();
    ++steps;
  }
  EXPECT_TRUE(s.sim.atEnd());
  EXPECT_EQ(finished.count(), 1);
  EXPECT_FALSE(s.sim.playing());
  EXPECT_EQ(s.sim.completedMoves(), static_cast<int>(r.job->moves.size()));
  // The machine is drawn at the trajectory's final pose.
  ASSERT_TRUE(machine.pose());
  const TrajectorySample end = r.trajectory->at(r.trajectory->durationS());
  EXPECT_NEAR((machine.pose()->P - end.p).norm(), 0.0, 1e-9);
  // Stepping moves between move starts.
  s.sim.setTimeS(0.0);
  s.sim.stepForward();
  EXPECT_GT(s.sim.timeS(), 0.0);
  const double t1 = s.sim.timeS();
  s.sim.stepForward();
  EXPECT_GT(s.sim.timeS(), t1);
  s.sim.stepBackward();
  EXPECT_DOUBLE_EQ(s.sim.timeS(), t1);
}

TEST(StudioFlow, MainWindowShowsTheDemoJob) {
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  ASSERT_TRUE(demo.open(QIODevice::ReadOnly));
  studio::MainWindow window(makerPlotter());
  window.resize(1400, 900);
  window.show();
  window.importer().setInteractive(false);
  QSignalSpy imported(&window.importer(), &ImportController::finished);
  window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  ASSERT_TRUE(imported.wait(kWaitMs));
  ASSERT_TRUE(imported.front().at(0).toBool()) << imported.front().at(1).toString().toStdString();
  QSignalSpy planned(&window.preview(), &PreviewController::resultChanged);
  ASSERT_TRUE(planned.wait(kWaitMs));
  while (window.preview().busy()) ASSERT_TRUE(planned.wait(kWaitMs));
  ASSERT_EQ(window.preview().result().status, PreviewStatus::Planned)
      << window.preview().result().message.toStdString();
  EXPECT_EQ(window.document().drawing().layers.size(), 3u);
  // The canvas shows the job: pixels in the job colours appear inside the drawing's area.
  CanvasView& canvas = window.canvas();
  QImage image(canvas.size(), QImage::Format_ARGB32_Premultiplied);
  {
    QPainter painter(&image);
    canvas.render(painter);
  }
  const QPointF c = canvas.view().widgetFromMachine(
      QPointF(window.document().placement().centerMm.x(), window.document().placement().centerMm.y()));
  int coloured = 0;
  for (int y = static_cast<int>(c.y()) - 60; y < c.y() + 60; ++y) {
    for (int x = static_cast<int>(c.x()) - 60; x < c.x() + 60; ++x) {
      const QColor px = image.pixelColor(x, y);
      coloured += px.saturation() > 120 && px.value() > 60;
    }
  }
  EXPECT_GT(coloured, 200);
  // The simulation was handed the trajectory.
  EXPECT_NE(window.simulation().trajectory(), nullptr);
}

// Help > About shows the application's version, the one `fivebar-studio --version` prints
// (main.cpp sets it from the CMake project version; the package test checks --version).
TEST(StudioFlow, AboutShowsTheApplicationVersion) {
  const QString before = QCoreApplication::applicationVersion();
  QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
  studio::MainWindow window(makerPlotter());
  QAction* about = nullptr;
  for (QAction* a : window.findChildren<QAction*>())
    if (a->text().contains(QStringLiteral("About"))) about = a;
  ASSERT_NE(about, nullptr);
  QString shown;
  QTimer::singleShot(0, [&shown] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      shown = box->text();
      box->accept();
    }
  });
  about->trigger();
  QCoreApplication::setApplicationVersion(before);
  EXPECT_TRUE(shown.contains(QStringLiteral("FiveBar Studio 9.8.7"))) << shown.toStdString();
}

}  // namespace
}  // namespace fivebar::widgets
