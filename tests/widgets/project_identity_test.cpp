// SPDX-License-Identifier: GPL-3.0-or-later
// One document identity (issue 23): an SVG opened while a project is open makes a new untitled
// project. The title names what Save writes, Save (Ctrl+S) then asks for a name, the project on
// disk is never written over with the new drawing, unsaved project changes are asked about
// before the SVG replaces them, and undoing the import gives the project back as it was.
#include <gtest/gtest.h>

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <ostream>

#include "app/studio/file_actions.hpp"
#include "app/studio/main_window.hpp"
#include "core/project/project.hpp"
#include "test_files.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "widgets/panels/fill_options_box.hpp"

// Failures print titles and paths as text.
void PrintTo(const QString& text, std::ostream* os) { *os << '"' << text.toStdString() << '"'; }

namespace fivebar::widgets {
namespace {

constexpr int kWaitMs = 60000;

MachineProfile makerPlotter() { return preset("maker-plotter").value_or(MachineProfile{}); }

QByteArray slurp(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Opens `path` through File > Open's door (the unsaved-changes question first) and waits for the
// import; false with the reason when it did not finish or failed. Cancelled at the question:
// nothing is imported and the result is "not opened".
::testing::AssertionResult openThroughFileMenu(studio::MainWindow& w, const QString& path) {
  w.importer().setInteractive(false);
  QSignalSpy imported(&w.importer(), &ImportController::finished);
  w.files().openPath(path);
  if (!w.importer().busy() && imported.isEmpty()) return ::testing::AssertionFailure() << "not opened";
  if (imported.isEmpty() && !imported.wait(kWaitMs)) return ::testing::AssertionFailure() << "import timed out";
  if (!imported.front().at(0).toBool())
    return ::testing::AssertionFailure() << imported.front().at(1).toString().toStdString();
  return ::testing::AssertionSuccess();
}

QString titleOfProject(const QString& path) {
  return studio::MainWindow::tr("%1[*] - FiveBar Studio").arg(QFileInfo(path).fileName());
}
QString titleOfUntitled(const QString& drawing) {
  return studio::MainWindow::tr("Untitled project (%1)[*] - FiveBar Studio").arg(QFileInfo(drawing).fileName());
}

// A project with a maker's edits (a layer hidden, the drawing moved), saved; and another drawing.
struct Files {
  QTemporaryDir dir;
  QString project, otherSvg;
  QByteArray projectBytes;
  Files() {
    const QString svg = test::writeTestFile(dir, QStringLiteral("frame.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="40mm" viewBox="0 0 60 40">
  <rect x="1" y="1" width="58" height="38" fill="none" stroke="#000" stroke-width="0.3"/>
  <circle cx="30" cy="20" r="12" fill="none" stroke="#c00" stroke-width="0.3"/>
</svg>)");
    otherSvg = test::writeTestFile(dir, QStringLiteral("other.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" width="33mm" height="33mm" viewBox="0 0 33 33">
  <path id="other-drawing" d="M 3 3 L 30 30 M 3 30 L 30 3" fill="none" stroke="#00c" stroke-width="0.3"/>
</svg>)");
    project = dir.filePath(QStringLiteral("frame.fivebar"));
    studio::MainWindow w(makerPlotter());
    EXPECT_TRUE(openThroughFileMenu(w, svg));
    w.document().setLayerVisible(1, false);
    Placement moved = w.document().placement();
    moved.centerMm += Vec2(4.0, -3.0);
    w.document().setPlacement(moved);
    QString error;
    EXPECT_TRUE(w.files().saveTo(project, &error)) << error.toStdString();
    projectBytes = slurp(project);
    EXPECT_FALSE(projectBytes.isEmpty());
  }
};

TEST(ProjectIdentity, AnSvgOpenedOverAProjectIsANewUntitledProjectThatSaveAsksANameFor) {
  Files files;
  studio::MainWindow w(makerPlotter());
  int asked = 0;
  w.files().setAsk([&](const QString&) {
    ++asked;
    return QMessageBox::Cancel;
  });
  ASSERT_TRUE(openThroughFileMenu(w, files.project));
  EXPECT_EQ(w.windowTitle(), titleOfProject(files.project));
  ASSERT_TRUE(openThroughFileMenu(w, files.otherSvg));
  EXPECT_EQ(asked, 0);  // the project had no unsaved changes: nothing to ask
  EXPECT_TRUE(w.document().projectPath().isEmpty());
  EXPECT_EQ(w.windowTitle(), titleOfUntitled(files.otherSvg));
  EXPECT_FALSE(w.document().isModified());  // opened, not edited: nothing to ask about yet

  // Ctrl+S asks for a name; cancelled, nothing is written.
  int askedPath = 0;
  QString answer;
  w.files().setAskPath([&](const QString&, const QString&, const QString&) {
    ++askedPath;
    return answer;
  });
  auto* save = w.findChild<QAction*>(QStringLiteral("actionSave"));
  ASSERT_NE(save, nullptr);
  save->trigger();
  EXPECT_EQ(askedPath, 1);
  EXPECT_TRUE(slurp(files.project) == files.projectBytes);  // the project is untouched

  // Given a name, Save writes there, and the title names it from then on.
  answer = files.dir.filePath(QStringLiteral("other.fivebar"));
  save->trigger();
  EXPECT_EQ(askedPath, 2);
  EXPECT_TRUE(slurp(files.project) == files.projectBytes);
  EXPECT_EQ(w.document().projectPath(), answer);
  EXPECT_EQ(w.windowTitle(), titleOfProject(answer));
  EXPECT_FALSE(w.document().isModified());
  const ProjectLoad saved = projectFromJson(slurp(answer).toStdString(), "other.fivebar");
  ASSERT_TRUE(saved.project) << (saved.issues.empty() ? "" : saved.issues.front().message);
  EXPECT_NE(saved.project->drawingSvg.find("other-drawing"), std::string::npos);
  // Saved again: the new project, still without a question.
  save->trigger();
  EXPECT_EQ(askedPath, 2);
  EXPECT_TRUE(slurp(files.project) == files.projectBytes);
}

TEST(ProjectIdentity, UnsavedProjectChangesAreAskedAboutBeforeAnSvgReplacesThem) {
  Files files;
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openThroughFileMenu(w, files.project));
  w.document().setLayerVisible(0, false);  // a change not saved yet
  QMessageBox::StandardButton answer = QMessageBox::Cancel;
  QString question;
  w.files().setAsk([&](const QString& text) {
    question = text;
    return answer;
  });
  EXPECT_FALSE(openThroughFileMenu(w, files.otherSvg));  // cancelled: nothing opened
  EXPECT_TRUE(question.contains(QStringLiteral("frame.fivebar"))) << question.toStdString();
  EXPECT_EQ(w.document().projectPath(), files.project);
  EXPECT_FALSE(w.document().drawing().layers[0].visible);  // the change is still there
  answer = QMessageBox::Discard;
  ASSERT_TRUE(openThroughFileMenu(w, files.otherSvg));
  EXPECT_EQ(w.windowTitle(), titleOfUntitled(files.otherSvg));
  EXPECT_TRUE(slurp(files.project) == files.projectBytes);
  // The untitled project's own question (once it is edited) names the drawing it was made from.
  w.document().setLayerVisible(0, false);
  answer = QMessageBox::Cancel;
  EXPECT_FALSE(openThroughFileMenu(w, files.project));
  EXPECT_TRUE(question.contains(QStringLiteral("other.svg"))) << question.toStdString();
}

TEST(ProjectIdentity, UndoingTheImportGivesTheProjectBack) {
  Files files;
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openThroughFileMenu(w, files.project));
  const Placement placed = w.document().placement();
  ASSERT_TRUE(openThroughFileMenu(w, files.otherSvg));
  ASSERT_TRUE(w.document().projectPath().isEmpty());
  w.document().undoStack()->undo();
  EXPECT_EQ(w.document().projectPath(), files.project);
  EXPECT_EQ(w.windowTitle(), titleOfProject(files.project));
  EXPECT_FALSE(w.document().isModified());  // exactly the project as saved
  EXPECT_FALSE(w.document().drawing().layers[1].visible);
  EXPECT_EQ(w.document().placement().centerMm, placed.centerMm);
  w.document().undoStack()->redo();
  EXPECT_TRUE(w.document().projectPath().isEmpty());
  EXPECT_EQ(w.windowTitle(), titleOfUntitled(files.otherSvg));
  // Saved as a project of its own, undone and redone: Save writes that project, not the first.
  const QString other = files.dir.filePath(QStringLiteral("other.fivebar"));
  w.files().setAskPath([&](const QString&, const QString&, const QString&) { return other; });
  ASSERT_TRUE(w.files().save());
  w.document().undoStack()->undo();
  EXPECT_EQ(w.document().projectPath(), files.project);
  w.document().undoStack()->redo();
  EXPECT_EQ(w.document().projectPath(), other);
  EXPECT_FALSE(w.document().isModified());
  EXPECT_TRUE(slurp(files.project) == files.projectBytes);
}

// "Import again with these settings" (Fills) reads a drawing again, as an undoable edit; it is
// not offered for a project, whose reopening would drop its unsaved changes without a question.
TEST(ProjectIdentity, ImportAgainIsOfferedForADrawingNotForAProject) {
  Files files;
  studio::MainWindow w(makerPlotter());
  ASSERT_TRUE(openThroughFileMenu(w, files.project));
  ASSERT_NE(w.fillOptions().importAgainButton(), nullptr);
  EXPECT_FALSE(w.fillOptions().importAgainButton()->isEnabled());
  ASSERT_TRUE(openThroughFileMenu(w, files.otherSvg));
  EXPECT_TRUE(w.fillOptions().importAgainButton()->isEnabled());
}

}  // namespace
}  // namespace fivebar::widgets
