#include "widgets/import_controller.hpp"

#include "widgets/import_warnings_panel.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QtConcurrent/QtConcurrentRun>

namespace fivebar::widgets {
namespace {
const char* const kRecentKey = "import/recentFiles";
const char* const kLastDirKey = "import/lastDirectory";
}  // namespace

Placement initialPlacement(const Drawing& drawing, const std::optional<RectMm>& rect,
                           const Geometry& geometry) {
  if (rect) {
    if (auto fitted = fitPlacement(drawing, *rect, true, ImportController::kFitMarginMm)) {
      return *fitted;
    }
  }
  Placement p;
  p.centerMm = Vec2(0.0, 0.5 * (geometry.a1 + geometry.b1));
  return p;
}

ImportController::ImportController(StudioDocument& doc, WorkspaceCache& workspace,
                                   QWidget* dialogParent, QObject* parent)
    : QObject(parent), doc_(doc), workspace_(workspace), dialogParent_(dialogParent) {
  connect(&watcher_, &QFutureWatcher<svg::ImportResult>::finished, this,
          &ImportController::onFinished);
}

QStringList ImportController::recentFiles() const {
  return QSettings().value(kRecentKey).toStringList();
}

void ImportController::clearRecentFiles() {
  QSettings().remove(kRecentKey);
  emit recentFilesChanged();
}

void ImportController::addRecent(const QString& path) {
  QStringList list = recentFiles();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  list.removeAll(absolute);
  list.prepend(absolute);
  while (list.size() > kMaxRecentFiles) list.removeLast();
  QSettings settings;
  settings.setValue(kRecentKey, list);
  settings.setValue(kLastDirKey, QFileInfo(absolute).absolutePath());
  emit recentFilesChanged();
}

void ImportController::showOpenDialog() {
  const QString dir = QSettings().value(kLastDirKey).toString();
  const QString path = QFileDialog::getOpenFileName(
      dialogParent_, tr("Open drawing"), dir, tr("SVG drawings (*.svg);;All files (*)"));
  if (!path.isEmpty()) openFile(path);
}

void ImportController::openFile(const QString& path) {
  start([path](const svg::ImportOptions& o, const svg::ProgressFn& f) {
          return svg::importSvgFile(path, o, f);
        },
        path, true);
}

void ImportController::openData(const QByteArray& svg, const QString& name) {
  start([svg, name](const svg::ImportOptions& o, const svg::ProgressFn& f) {
          return svg::importSvgData(svg, name, o, f);
        },
        name, false);
}

void ImportController::cancel() {
  if (cancel_) cancel_->store(true);
}

void ImportController::start(
    std::function<svg::ImportResult(const svg::ImportOptions&, const svg::ProgressFn&)> job,
    const QString& name, bool remember) {
  if (busy()) {
    emit finished(false, tr("%1: another import is still running.").arg(name));
    return;
  }
  pendingName_ = name;
  pendingRemember_ = remember;
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  if (interactive_) {
    dialog_ = new QProgressDialog(tr("Importing %1...").arg(QFileInfo(name).fileName()),
                                  tr("Cancel"), 0, 1000, dialogParent_);
    dialog_->setWindowTitle(tr("Import"));
    dialog_->setMinimumDuration(300);
    dialog_->setWindowModality(Qt::WindowModal);
    dialog_->setAutoClose(false);
    dialog_->setAutoReset(false);
    connect(dialog_, &QProgressDialog::canceled, this, &ImportController::cancel);
  }
  auto cancelFlag = cancel_;
  QPointer<ImportController> self(this);
  watcher_.setFuture(QtConcurrent::run([job = std::move(job), cancelFlag, self] {
    svg::ImportOptions options;
    options.cancel = cancelFlag.get();
    const svg::ProgressFn onProgress = [self](double fraction) {
      // Called on this worker thread: hand the value to the UI thread.
      QMetaObject::invokeMethod(
          self, [self, fraction] { if (self) emit self->progress(fraction); },
          Qt::QueuedConnection);
    };
    try {
      return job(options, onProgress);
    } catch (const std::exception& e) {
      svg::ImportResult failed;
      failed.status = svg::ImportStatus::RenderFailed;
      failed.message = e.what();
      return failed;
    }
  }));
  if (dialog_) {
    connect(this, &ImportController::progress, dialog_,
            [d = dialog_](double f) { if (d) d->setValue(static_cast<int>(f * 1000.0)); });
  }
}

void ImportController::onFinished() {
  if (dialog_) dialog_->deleteLater();
  svg::ImportResult result = watcher_.result();
  if (result.ok() && fill_ != FillMode::Outline)
    for (Layer& layer : result.drawing.layers) layer.paths = applyFill(layer.paths, fill_, hatch_);
  const QString name = pendingName_;
  if (!result.ok()) {
    QString message = QString::fromStdString(result.message);
    if (result.status == svg::ImportStatus::Cancelled) message = tr("Import of %1 cancelled.").arg(name);
    if (message.isEmpty()) message = tr("%1 could not be imported.").arg(name);
    if (interactive_ && result.status != svg::ImportStatus::Cancelled) {
      QMessageBox::warning(dialogParent_, tr("Import failed"), message);
    }
    emit finished(false, message);
    return;
  }
  if (result.drawing.layers.empty()) {
    const QString message = tr("%1 contains nothing to draw.").arg(name);
    if (interactive_) QMessageBox::warning(dialogParent_, tr("Import failed"), message);
    emit finished(false, message);
    return;
  }
  if (QString refusal; !acceptPointBudget(dialogParent_, result.drawing, name, interactive_, refusal)) {
    emit finished(false, refusal);
    return;
  }
  const Placement placement = initialPlacement(
      result.drawing, workspace_.fitRectangle(doc_.effectiveMode()), doc_.profile().geometry);
  doc_.replaceDrawing(result.drawing, name, placement);
  if (pendingRemember_) addRecent(name);
  emit warningsReported(name, toQStringList(result.warnings));
  emit finished(true, QString());
}

}  // namespace fivebar::widgets
