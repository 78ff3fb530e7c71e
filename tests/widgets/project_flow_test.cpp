// SPDX-License-Identifier: GPL-3.0-or-later
// One truth, end to end: the studio window's G-code (File > Export G-code, what Run streams) is
// byte-identical to `fivebar plan` and to `fivebar-studio --export-gcode` for corpus drawings;
// a project saved, reopened and exported gives the same G-code; the unsaved-changes question;
// recent projects; the machine profile remembered across restarts.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QCloseEvent>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>

#include "app/studio/file_actions.hpp"
#include "app/studio/main_window.hpp"
#include "test_files.hpp"
#include "app/studio/startup.hpp"
#include "core/project/project.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kWaitMs = 60000;

MachineProfile makerPlotter() { return preset("maker-plotter").value_or(MachineProfile{}); }

QString corpus(const char* relative) {
  return QStringLiteral(FIVEBAR_SHARED_DIR "/corpus/svg/") + QString::fromLatin1(relative);
}

QByteArray slurp(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Opens a file in the window and waits for its plan; false with the reason on failure.
::testing::AssertionResult openAndPlan(studio::MainWindow& w, const QString& path) {
  w.importer().setInteractive(false);
  QSignalSpy imported(&w.importer(), &ImportController::finished);
  w.importer().openFile(path);
  if (!imported.wait(kWaitMs)) return ::testing::AssertionFailure() << "import timed out";
  if (!imported.front().at(0).toBool())
    return ::testing::AssertionFailure() << imported.front().at(1).toString().toStdString();
  QSignalSpy planned(&w.preview(), &PreviewController::resultChanged);
  while (w.preview().busy() || w.preview().result().status == PreviewStatus::Empty)
    if (!planned.wait(kWaitMs)) return ::testing::AssertionFailure() << "planning timed out";
  if (w.preview().result().status != PreviewStatus::Planned)
    return ::testing::AssertionFailure() << w.preview().result().message.toStdString();
  return ::testing::AssertionSuccess();
}

int runTool(const QString& program, const QStringList& args, QString* err = nullptr) {
  QProcess p;
  p.start(program, args);
  if (!p.waitForFinished(120000)) return -1;
  if (err) *err = QString::fromLocal8Bit(p.readAllStandardError());
  return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}

class OneTruth : public ::testing::TestWithParam<const char*> {};

TEST_P(OneTruth, StudioExportEqualsFivebarPlanByteForByte) {
  const QString svg = corpus(GetParam());
  if (!QFileInfo::exists(svg)) GTEST_SKIP() << "corpus not present: " << svg.toStdString();
  QTemporaryDir dir;
  const QString cli = dir.filePath(QStringLiteral("cli.gcode"));
  const QString headless = dir.filePath(QStringLiteral("headless.gcode"));
  const QString window = dir.filePath(QStringLiteral("window.gcode"));
  QString err;
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_CLI), {QStringLiteral("plan"), svg, QStringLiteral("--machine"),
                                                  QStringLiteral("maker-plotter"), QStringLiteral("-o"), cli}, &err), 0)
      << err.toStdString();
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_STUDIO), {svg, QStringLiteral("--machine"), QStringLiteral("maker-plotter"),
                                                     QStringLiteral("--export-gcode"), headless}, &err), 0)
      << err.toStdString();
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openAndPlan(w, svg));
  QString error;
  ASSERT_TRUE(w.files().exportGcodeTo(window, &error)) << error.toStdString();
  const QByteArray expected = slurp(cli);
  ASSERT_GT(expected.size(), 100);
  EXPECT_TRUE(slurp(headless) == expected) << "fivebar-studio --export-gcode differs from fivebar plan";
  EXPECT_TRUE(slurp(window) == expected) << "the window's export differs from fivebar plan";
}

INSTANTIATE_TEST_SUITE_P(Corpus, OneTruth,
                         ::testing::Values("vpype-plotter/arc_with_rotate/arc_with_rotate.svg",
                                           "vpype-plotter/benchmark/300_beziers.svg",
                                           "vpype-plotter/benchmark/500_circles.svg"));

// An A5 landscape page (210 x 148 mm) with a frame and a curve in another colour.
QString writeA5(const QTemporaryDir& dir) {
  const QString path = dir.filePath(QStringLiteral("a5.svg"));
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(R"(<svg xmlns="http://www.w3.org/2000/svg" width="210mm" height="148mm" viewBox="0 0 210 148">
  <rect x="0" y="0" width="210" height="148" fill="none" stroke="#000" stroke-width="0.3"/>
  <path d="M 20 74 C 50 10, 150 10, 190 74 S 80 140, 20 74" fill="none" stroke="#c00" stroke-width="0.3"/>
</svg>)");
  return path;
}

TEST(ProjectFlow, SavedReopenedAndExportedGivesTheSameGcode) {
  QTemporaryDir dir;
  const QString svg = writeA5(dir);
  const QString project = dir.filePath(QStringLiteral("a5.fivebar"));
  const QString first = dir.filePath(QStringLiteral("first.gcode"));
  const QString second = dir.filePath(QStringLiteral("second.gcode"));
  {
    studio::MainWindow w(makerPlotter());
    ASSERT_TRUE(openAndPlan(w, svg));
    EXPECT_DOUBLE_EQ(w.document().placement().scale, 1.0);  // A5 fits maker-plotter at 100 %
    // Edits a maker would make: a layer hidden, a mode chosen, the drawing moved.
    w.document().setLayerVisible(1, false);
    Placement moved = w.document().placement();
    moved.centerMm += Vec2(3.0, -2.0);
    w.document().setPlacement(moved);
    QSignalSpy replanned(&w.preview(), &PreviewController::resultChanged);
    w.preview().replanNow();
    while (w.preview().busy()) ASSERT_TRUE(replanned.wait(kWaitMs));
    ASSERT_EQ(w.preview().result().status, PreviewStatus::Planned) << w.preview().result().message.toStdString();
    EXPECT_TRUE(w.document().isModified());
    QString error;
    ASSERT_TRUE(w.files().saveTo(project, &error)) << error.toStdString();
    EXPECT_FALSE(w.document().isModified());
    ASSERT_TRUE(w.files().exportGcodeTo(first, &error)) << error.toStdString();
  }
  // The project embeds the drawing: it opens with the SVG gone.
  ASSERT_TRUE(QFile::remove(svg));
  studio::MainWindow w(preset("hoang2015").value_or(MachineProfile{}));  // another machine open
  ASSERT_TRUE(openAndPlan(w, project));
  EXPECT_EQ(w.document().profile().name, makerPlotter().name);  // the project's machine
  EXPECT_FALSE(w.document().drawing().layers[1].visible);
  EXPECT_FALSE(w.document().isModified());
  QString error;
  ASSERT_TRUE(w.files().exportGcodeTo(second, &error)) << error.toStdString();
  EXPECT_TRUE(slurp(first) == slurp(second));
  // fivebar plan PROJECT gives the same job too.
  const QString cli = dir.filePath(QStringLiteral("cli.gcode"));
  QString err;
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_CLI), {QStringLiteral("plan"), project, QStringLiteral("-o"), cli}, &err), 0)
      << err.toStdString();
  EXPECT_TRUE(slurp(cli) == slurp(first));
}

// Recent projects: a saved project heads File > Open recent, above the drawing opened before it;
// the list outlives the window (QSettings), and its entry reopens the project.
TEST(ProjectFlow, SavedProjectsAreRecentAndReopenFromTheMenu) {
  QTemporaryDir dir;
  const QString svg = writeA5(dir);
  const QString project = dir.filePath(QStringLiteral("recent.fivebar"));
  {
    studio::MainWindow w(makerPlotter());
    w.importer().clearRecentFiles();
    ASSERT_TRUE(openAndPlan(w, svg));
    QString error;
    ASSERT_TRUE(w.files().saveTo(project, &error)) << error.toStdString();
    const QStringList recent = w.importer().recentFiles();
    ASSERT_GE(recent.size(), 2);
    EXPECT_EQ(QFileInfo(recent[0]).canonicalFilePath(), QFileInfo(project).canonicalFilePath());
    EXPECT_EQ(QFileInfo(recent[1]).canonicalFilePath(), QFileInfo(svg).canonicalFilePath());
  }
  studio::MainWindow w(makerPlotter());  // a restart
  w.importer().setInteractive(false);
  QMenu menu;
  w.files().fillRecentMenu(&menu);
  QAction* entry = nullptr;
  for (QAction* a : menu.actions())
    if (a->text() == QStringLiteral("recent.fivebar")) entry = a;
  ASSERT_NE(entry, nullptr) << "the saved project is not in File > Open recent";
  QSignalSpy imported(&w.importer(), &ImportController::finished);
  entry->trigger();
  ASSERT_TRUE(imported.wait(kWaitMs));
  ASSERT_TRUE(imported.front().at(0).toBool()) << imported.front().at(1).toString().toStdString();
  EXPECT_EQ(QFileInfo(w.document().projectPath()).canonicalFilePath(), QFileInfo(project).canonicalFilePath());
  EXPECT_DOUBLE_EQ(w.document().placement().scale, 1.0);
}

// Headless export of a job that cannot be drawn: exit status 1, the problems on stderr, no file.
TEST(ProjectFlow, HeadlessExportOfAnInfeasibleProjectExitsOneWithTheProblems) {
  QTemporaryDir dir;
  const QString svg = writeA5(dir);
  const QString project = dir.filePath(QStringLiteral("far.fivebar"));
  {
    studio::MainWindow w(makerPlotter());
    ASSERT_TRUE(openAndPlan(w, svg));
    Placement far = w.document().placement();
    far.centerMm = Vec2(0.0, 2000.0);  // out of reach
    w.document().setPlacement(far);
    QString error;
    ASSERT_TRUE(w.files().saveTo(project, &error)) << error.toStdString();
  }
  const QString out = dir.filePath(QStringLiteral("far.gcode"));
  QString err;
  EXPECT_EQ(runTool(QStringLiteral(FIVEBAR_STUDIO), {project, QStringLiteral("--export-gcode"), out}, &err), 1)
      << err.toStdString();
  EXPECT_FALSE(err.isEmpty());
  EXPECT_TRUE(err.contains(QStringLiteral("layer"))) << err.toStdString();  // names the offending path
  EXPECT_FALSE(QFileInfo::exists(out));
}

// A layer's fill set in the layers panel plans exactly as `fivebar plan --fill hatch` with the same
// spacing, angle and crosshatch; it is saved in the project and comes back with it.
TEST(ProjectFlow, LayerFillFromTheLayersPanelEqualsFivebarPlanFillAndIsSaved) {
  QTemporaryDir dir;
  const QString svg = test::writeTestFile(dir, QStringLiteral("filled.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" width="80mm" height="60mm" viewBox="0 0 80 60">
  <path d="M 10 10 H 70 V 50 H 10 Z M 30 20 H 50 V 40 H 30 Z" fill="#000" fill-rule="evenodd"/>
  <circle cx="60" cy="45" r="8" fill="#000" stroke="#000"/>
</svg>)");
  ASSERT_FALSE(svg.isEmpty());
  const QString cli = dir.filePath(QStringLiteral("cli.gcode"));
  const QString window = dir.filePath(QStringLiteral("window.gcode"));
  const QString reopened = dir.filePath(QStringLiteral("reopened.gcode"));
  const QString project = dir.filePath(QStringLiteral("filled.fivebar"));
  QString err;
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_CLI),
                    {QStringLiteral("plan"), svg, QStringLiteral("--machine"), QStringLiteral("maker-plotter"),
                     QStringLiteral("--fill"), QStringLiteral("hatch"), QStringLiteral("--hatch-spacing"),
                     QStringLiteral("0.8"), QStringLiteral("--hatch-angle"), QStringLiteral("30"),
                     QStringLiteral("--crosshatch"), QStringLiteral("-o"), cli}, &err), 0)
      << err.toStdString();
  {
    studio::MainWindow w(makerPlotter());
    ASSERT_TRUE(openAndPlan(w, svg));
    ASSERT_EQ(w.document().drawing().layers.size(), 1u);
    auto* mode = w.findChild<QComboBox*>(QStringLiteral("layerFill"));
    auto* spacing = w.findChild<QDoubleSpinBox*>(QStringLiteral("layerHatchSpacing"));
    auto* angle = w.findChild<QDoubleSpinBox*>(QStringLiteral("layerHatchAngle"));
    auto* cross = w.findChild<QCheckBox*>(QStringLiteral("layerCrosshatch"));
    ASSERT_TRUE(mode && spacing && angle && cross);
    const int steps = w.document().undoStack()->count();
    mode->setCurrentIndex(mode->findData(static_cast<int>(FillMode::Hatch)));
    spacing->setValue(0.8);
    angle->setValue(30.0);
    cross->setChecked(true);
    EXPECT_EQ(w.document().undoStack()->count(), steps + 4);  // one undo step per change
    const Layer& layer = w.document().drawing().layers[0];
    EXPECT_EQ(layer.fill, FillMode::Hatch);
    EXPECT_DOUBLE_EQ(layer.hatch.spacingMm, 0.8);
    EXPECT_TRUE(layer.hatch.crosshatch);
    QSignalSpy replanned(&w.preview(), &PreviewController::resultChanged);
    w.preview().replanNow();
    while (w.preview().busy()) ASSERT_TRUE(replanned.wait(kWaitMs));
    ASSERT_EQ(w.preview().result().status, PreviewStatus::Planned) << w.preview().result().message.toStdString();
    QString error;
    ASSERT_TRUE(w.files().exportGcodeTo(window, &error)) << error.toStdString();
    ASSERT_TRUE(w.files().saveTo(project, &error)) << error.toStdString();
  }
  const QByteArray expected = slurp(cli);
  ASSERT_GT(expected.size(), 1000);
  EXPECT_TRUE(slurp(window) == expected) << "the studio's hatch differs from fivebar plan --fill hatch";
  EXPECT_TRUE(slurp(project).contains("\"mode\": \"hatch\""));
  // Reopened, the layer keeps its fill and plans the same job; so does fivebar plan PROJECT.
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openAndPlan(w, project));
  EXPECT_EQ(w.document().drawing().layers[0].fill, FillMode::Hatch);
  QString error;
  ASSERT_TRUE(w.files().exportGcodeTo(reopened, &error)) << error.toStdString();
  EXPECT_TRUE(slurp(reopened) == expected);
  const QString fromProject = dir.filePath(QStringLiteral("project.gcode"));
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_CLI), {QStringLiteral("plan"), project, QStringLiteral("-o"), fromProject}, &err), 0)
      << err.toStdString();
  EXPECT_TRUE(slurp(fromProject) == expected);
}

TEST(ProjectFlow, UnsavedChangesAskBeforeClosing) {
  QTemporaryDir dir;
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openAndPlan(w, writeA5(dir)));
  EXPECT_FALSE(w.document().isModified());  // only opened: nothing to save yet
  Placement moved = w.document().placement();
  moved.centerMm.x() += 2.0;
  w.document().setPlacement(moved);  // an edit
  int asked = 0;
  QMessageBox::StandardButton answer = QMessageBox::Cancel;
  w.files().setAsk([&](const QString&) {
    ++asked;
    return answer;
  });
  const QString saved = dir.filePath(QStringLiteral("saved.fivebar"));
  w.files().setAskPath([&](const QString&, const QString&, const QString&) { return saved; });
  QCloseEvent cancelled;
  QApplication::sendEvent(&w, &cancelled);
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(cancelled.isAccepted());  // Cancel keeps the window open
  answer = QMessageBox::Save;
  QCloseEvent save;
  QApplication::sendEvent(&w, &save);
  EXPECT_EQ(asked, 2);
  EXPECT_TRUE(save.isAccepted());
  EXPECT_TRUE(QFileInfo::exists(saved));  // saved through Save As
  EXPECT_FALSE(w.document().isModified());
  QCloseEvent clean;
  QApplication::sendEvent(&w, &clean);
  EXPECT_EQ(asked, 2);  // nothing unsaved: no question
  EXPECT_TRUE(clean.isAccepted());
  const ProjectLoad load = projectFromJson(slurp(saved).toStdString(), "saved.fivebar");
  ASSERT_TRUE(load.project) << (load.issues.empty() ? "" : load.issues.front().message);
  EXPECT_NE(load.project->drawingSvg.find("210mm"), std::string::npos);
}

TEST(ProjectFlow, TheMachineProfileIsRememberedAcrossRestarts) {
  QSettings().remove(QStringLiteral("machine/profileJson"));
  MachineProfile edited = makerPlotter();
  edited.name = "my plotter";
  edited.geometry.a1 += 1.0;
  {
    studio::MainWindow w(makerPlotter());
    w.document().setProfile(edited);
  }
  const QString json = studio::FileActions::rememberedProfileJson();
  ASSERT_FALSE(json.isEmpty());
  const ProfileLoad load = profileFromJson(json.toStdString(), "remembered");
  ASSERT_TRUE(load.profile);
  EXPECT_EQ(load.profile->name, "my plotter");
  EXPECT_DOUBLE_EQ(load.profile->geometry.a1, edited.geometry.a1);
  // The studio started without --machine uses it; --machine still wins.
  std::string error;
  const auto atStart = studio::startupProfile(std::nullopt, error);
  ASSERT_TRUE(atStart) << error;
  EXPECT_EQ(atStart->name, "my plotter");
  EXPECT_EQ(studio::startupProfile(QStringLiteral("hoang2015"), error)->name,
            preset("hoang2015")->name);
  QSettings().remove(QStringLiteral("machine/profileJson"));
  EXPECT_EQ(studio::startupProfile(std::nullopt, error)->name, makerPlotter().name);
}

// fivebar-studio --timings prints, once the opened drawing is planned, the time from opening it,
// the import's share and every stage of the plan, in the form of `fivebar plan --timings`.
TEST(ProjectFlow, StudioTimingsPrintTheImportAndEveryStage) {
  QTemporaryDir dir;
  const QString svg = test::writeTestFile(dir, QStringLiteral("square.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" width="40mm" height="40mm" viewBox="0 0 40 40">
  <rect x="2" y="2" width="36" height="36" fill="none" stroke="#000"/></svg>)");
  ASSERT_FALSE(svg.isEmpty());
  QString err;
  ASSERT_EQ(runTool(QStringLiteral(FIVEBAR_STUDIO),
                    {svg, QStringLiteral("--machine"), QStringLiteral("maker-plotter"), QStringLiteral("--timings"),
                     QStringLiteral("--screenshot"), dir.filePath(QStringLiteral("shot.png"))},
                    &err),
            0)
      << err.toStdString();
  const QRegularExpression total(QStringLiteral("fivebar-studio: opened and planned in (\\d+) ms\n"
                                                "  import and placement: (\\d+) ms\n"));
  const QRegularExpressionMatch m = total.match(err);
  ASSERT_TRUE(m.hasMatch()) << err.toStdString();
  EXPECT_GE(m.captured(1).toLongLong(), m.captured(2).toLongLong());  // the import is part of it
  for (const char* stage : {"mode screening", "optimise", "segmentation, feeds, travel", "job scene"})
    EXPECT_TRUE(QRegularExpression(QStringLiteral("\n  %1: \\d+ ms \\(cpu \\d+ ms\\)").arg(QLatin1String(stage)))
                    .match(err)
                    .hasMatch())
        << stage << "\n" << err.toStdString();
}

}  // namespace
}  // namespace fivebar::widgets

namespace fivebar::widgets {
namespace {

TEST(ProjectFlow, RunAsksBeforeAJobOverEightHoursOrTwoMillionMoves) {
  PlannedJob job;
  job.summary.estimatedTimeS = 7.9 * 3600.0;
  job.summary.segments = 1999999;
  EXPECT_TRUE(longJobQuestion(job).isEmpty());
  job.summary.estimatedTimeS = 8.5 * 3600.0;
  EXPECT_TRUE(longJobQuestion(job).contains(QStringLiteral("8.5 hours"))) << longJobQuestion(job).toStdString();
  job.summary.estimatedTimeS = 60.0;
  job.summary.segments = 2500000;
  EXPECT_TRUE(longJobQuestion(job).contains(QLocale().toString(2500000))) << longJobQuestion(job).toStdString();
}

}  // namespace
}  // namespace fivebar::widgets
