// Importing drawings into the document: runs the SVG import off the UI thread (the import
// library parses in its worker process) with a progress dialog and cancel, places the result
// fitted into the largest singularity-free rectangle of the document's mode, and keeps the
// recent-files list (QSettings). Errors are reported in a message naming the file.
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QProgressDialog>
#include <QStringList>
#include <atomic>
#include <memory>

#include "core/import/svg_import.hpp"
#include "core/planning/hatch.hpp"
#include "widgets/studio_document.hpp"
#include "widgets/workspace_cache.hpp"

namespace fivebar::widgets {

// Placement of `drawing` fitted into `rect` with a small margin; when the fit is impossible
// (empty drawing or no rectangle) the drawing is centred at true size in front of the motors.
Placement initialPlacement(const Drawing& drawing, const std::optional<RectMm>& rect,
                           const Geometry& geometry);

class ImportController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kMaxRecentFiles = 8;
  static constexpr double kFitMarginMm = 2.0;

  ImportController(StudioDocument& doc, WorkspaceCache& workspace, QWidget* dialogParent,
                   QObject* parent = nullptr);

  // false: no dialogs (tests, --screenshot); results only through the signals.
  void setInteractive(bool on) { interactive_ = on; }
  bool busy() const { return watcher_.isRunning(); }
  // How filled shapes of the next imports are drawn (core/planning/hatch.hpp; default outline).
  void setFill(FillMode mode, const HatchSettings& hatch) {
    fill_ = mode;
    hatch_ = hatch;
  }
  FillMode fill() const { return fill_; }
  const HatchSettings& hatch() const { return hatch_; }
  QStringList recentFiles() const;

 public slots:
  void showOpenDialog();
  // Imports a file through the isolated worker process.
  void openFile(const QString& path);
  // Imports an in-memory SVG that the application trusts (the built-in demo), in this process.
  void openData(const QByteArray& svg, const QString& name);
  void cancel();
  void clearRecentFiles();

 signals:
  // ok = the drawing is in the document; message = the error otherwise (names the file).
  void finished(bool ok, const QString& message);
  // After every successful import: the importer's warnings (widgets/import_warnings_panel.hpp).
  void warningsReported(const QString& fileName, const QStringList& warnings);
  void recentFilesChanged();
  void progress(double fraction);

 private:
  void start(std::function<svg::ImportResult(const svg::ImportOptions&, const svg::ProgressFn&)> job,
             const QString& name, bool remember);
  void onFinished();
  void addRecent(const QString& path);

  StudioDocument& doc_;
  WorkspaceCache& workspace_;
  QPointer<QWidget> dialogParent_;
  QFutureWatcher<svg::ImportResult> watcher_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  QPointer<QProgressDialog> dialog_;
  QString pendingName_;
  bool pendingRemember_ = false;
  bool interactive_ = true;
  FillMode fill_ = FillMode::Outline;
  HatchSettings hatch_;
};

}  // namespace fivebar::widgets
