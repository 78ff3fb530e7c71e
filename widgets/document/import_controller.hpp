// SPDX-License-Identifier: GPL-3.0-or-later
// Importing drawings and opening projects into the document: runs the SVG import off the UI
// thread (the import library parses in its worker process) with a progress dialog and cancel,
// places a drawing by core's autoPlacement (true size when it fits, centred in the largest
// singularity-free rectangle; job/job_source.hpp, as `fivebar plan` does), and keeps the
// recent-files list (drawings and projects, QSettings). Errors are reported in a message naming
// the file.
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>
#include <QStringList>
#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "job/job_source.hpp"
#include "core/planning/hatch.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

// What an import gives back: the loaded job or the error.
struct ImportOutcome {
  std::optional<job::LoadedJob> job;
  job::JobError error;
  bool cancelled = false;
};

class ImportController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kMaxRecentFiles = 8;

  ImportController(StudioDocument& doc, QWidget* dialogParent, QObject* parent = nullptr);

  // false: no dialogs (tests, --screenshot); results only through the signals.
  void setInteractive(bool on) { interactive_ = on; }
  // Asked (interactive only) when a drawing passes the points budget: true imports it whole
  // anyway. The composition root words the answer's box; unset, such a drawing is refused.
  using BudgetQuestion = std::function<bool(const QString& title, const QString& question)>;
  void setBudgetQuestion(BudgetQuestion ask) { askBudget_ = std::move(ask); }
  bool busy() const { return watcher_.isRunning(); }
  // How filled shapes of the next imports are drawn (core/planning/hatch.hpp; default outline).
  void setFill(FillMode mode, const HatchSettings& hatch) {
    fill_ = mode;
    hatch_ = hatch;
  }
  FillMode fill() const { return fill_; }
  // Dashed strokes of the next imports drawn whole (true) or as their dashes (default).
  void setSolidDashes(bool solid) { solidDashes_ = solid; }
  bool solidDashes() const { return solidDashes_; }
  const HatchSettings& hatch() const { return hatch_; }
  QStringList recentFiles() const;
  // Puts a file at the top of the recent list (drawings on import, projects on save).
  void addRecent(const QString& path);
  // The last placement note ("scaled to 62 % to fit the workspace"), empty when true size.
  QString placementNote() const { return note_; }

 public slots:
  void showOpenDialog();
  // Imports a drawing (SVG) or opens a project (.fivebar) through the isolated worker process.
  void openFile(const QString& path);
  // Imports an in-memory SVG (the built-in demo).
  void openData(const QByteArray& svg, const QString& name);
  void cancel();
  void clearRecentFiles();

 signals:
  // ok = the drawing is in the document; message = the error otherwise (names the file), or
  // the placement note when ok.
  void finished(bool ok, const QString& message);
  // After every successful import: the importer's warnings (widgets/panels/import_warnings_panel.hpp).
  void warningsReported(const QString& fileName, const QStringList& warnings);
  void recentFilesChanged();

 private:
  void start(std::function<ImportOutcome(const std::atomic<bool>*)> job, const QString& name,
             bool remember);
  void onFinished();

  StudioDocument& doc_;
  QPointer<QWidget> dialogParent_;
  QFutureWatcher<ImportOutcome> watcher_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  QPointer<QProgressDialog> dialog_;
  void closeProgressDialog();
  QString pendingName_;
  QString note_;
  bool pendingRemember_ = false;
  bool interactive_ = true;
  // The points budget (kDefaultMaxPoints after flattening) stops an import early; the user may
  // then import the same file again without it (retry_), and is not asked twice.
  std::size_t maxPoints_ = kDefaultMaxPoints;
  bool budgetWaived_ = false;
  BudgetQuestion askBudget_;
  std::function<void()> retry_;
  FillMode fill_ = FillMode::Outline;
  bool solidDashes_ = false;
  HatchSettings hatch_;
};

}  // namespace fivebar::widgets
