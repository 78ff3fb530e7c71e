// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's File menu work: Save / Save As / Open project (.fivebar, atomic via QSaveFile;
// Save writes the document's projectPath(), and is Save As while there is none: a drawing just
// opened, even over an open project, is a new untitled project),
// Export G-code (exactly the job Run streams: the preview's planned job, written by core's
// writeGcode), the unsaved-changes question before close, open and quit, the recent-files menu,
// and remembering the machine profile across restarts (QSettings).
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QString>
#include <functional>

class QMenu;
class QWidget;

namespace fivebar::widgets {
class ImportController;
class PreviewController;
class StudioDocument;
}  // namespace fivebar::widgets

namespace fivebar::studio {

class FileActions : public QObject {
  Q_OBJECT
 public:
  FileActions(widgets::StudioDocument& doc, widgets::PreviewController& preview,
              widgets::ImportController& importer, QWidget* window);

  // The question asked before unsaved changes are dropped; replaceable by tests. Returns Save,
  // Discard or Cancel.
  using AskFn = std::function<QMessageBox::StandardButton(const QString& text)>;
  void setAsk(AskFn ask) { ask_ = std::move(ask); }
  // The file name asked for by Save As / Export (empty = cancelled); replaceable by tests.
  using PathFn = std::function<QString(const QString& title, const QString& filter, const QString& suffix)>;
  void setAskPath(PathFn askPath) { askPath_ = std::move(askPath); }

  // True when the document may be dropped: nothing unsaved, or the user saved or discarded it.
  bool maybeSave();
  // Writes the project; false (with a message) when it cannot.
  bool saveTo(const QString& path, QString* error = nullptr);
  // Writes the job Run would stream; false with the reason when there is no planned job.
  bool exportGcodeTo(const QString& path, QString* error = nullptr);
  // Why Export G-code cannot run now ("" when it can).
  QString exportProblem() const;
  void fillRecentMenu(QMenu* menu);

  // The remembered machine profile (JSON), empty if none.
  static QString rememberedProfileJson();

 public slots:
  bool save();
  bool saveAs();
  void open();
  void openPath(const QString& path);
  void exportGcode();

 signals:
  void message(const QString& text);

 private:
  void rememberProfile();

  widgets::StudioDocument& doc_;
  widgets::PreviewController& preview_;
  widgets::ImportController& importer_;
  QWidget* window_;
  AskFn ask_;
  PathFn askPath_;
};

}  // namespace fivebar::studio
