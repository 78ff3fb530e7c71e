// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/import_controller.hpp"

#include "widgets/panels/import_warnings_panel.hpp"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QtConcurrent/QtConcurrentRun>

#include "i18n/translated.hpp"
#include "widgets/document/job_pipeline.hpp"

namespace fivebar::widgets {
namespace {
const char* const kRecentKey = "import/recentFiles";
const char* const kLastDirKey = "import/lastDirectory";

// The options a fresh drawing is loaded with: the document's mode and tolerance, no placement
// (autoPlacement at true size).
PlanOptions importOptions(const StudioDocument& doc) {
  PlanOptions o;
  o.mode = doc.modeSelection();
  o.toleranceMm = doc.toleranceMm();
  return o;
}
}  // namespace

void ImportController::closeProgressDialog() {
  if (!dialog_) return;
  QProgressDialog* dialog = dialog_;
  dialog_ = nullptr;
  disconnect(dialog, nullptr, this, nullptr);
  dialog->reset();  // stops its minimum-duration timer
  dialog->hide();
  dialog->deleteLater();
}

ImportController::ImportController(StudioDocument& doc, QWidget* dialogParent, QObject* parent)
    : QObject(parent), doc_(doc), dialogParent_(dialogParent) {
  connect(&watcher_, &QFutureWatcher<ImportOutcome>::finished, this, &ImportController::onFinished);
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
      dialogParent_, tr("Open drawing or project"), dir,
      tr("Drawings and projects (*.svg *.fivebar);;SVG drawings (*.svg);;FiveBar projects (*.fivebar);;All files (*)"));
  if (!path.isEmpty()) openFile(path);
}

void ImportController::openFile(const QString& path) {
  // A project brings its own machine; a drawing is placed for the document's.
  const std::optional<MachineProfile> profile =
      job::isProjectPath(path) ? std::nullopt : std::optional<MachineProfile>(doc_.profile());
  const PlanOptions options = importOptions(doc_);
  retry_ = [this, path] { openFile(path); };
  start([path, profile, options, fill = fill_, hatch = hatch_, maxPoints = maxPoints_,
         solid = solidDashes_](const std::atomic<bool>* cancel) {
          ImportOutcome out;
          PlanOptions o = options;
          o.cancel = cancel;
          out.job = job::loadJob(path, profile, o, out.error, fill, hatch, maxPoints, solid);
          if (out.job) out.job->options.cancel = nullptr;
          return out;
        },
        path, true);
}

void ImportController::openData(const QByteArray& svg, const QString& name) {
  const MachineProfile profile = doc_.profile();
  const PlanOptions options = importOptions(doc_);
  retry_ = [this, svg, name] { openData(svg, name); };
  start([svg, name, profile, options, fill = fill_, hatch = hatch_, maxPoints = maxPoints_,
         solid = solidDashes_](const std::atomic<bool>* cancel) {
          ImportOutcome out;
          PlanOptions o = options;
          o.cancel = cancel;
          job::DrawingSource source;
          source.svg = svg;
          source.name = name;
          source.fill = fill;
          source.hatch = hatch;
          source.maxPoints = maxPoints;
          source.solidDashes = solid;
          out.job = job::loadDrawing(source, profile, o, out.error);
          if (out.job) out.job->options.cancel = nullptr;
          return out;
        },
        name, false);
}

void ImportController::cancel() {
  if (cancel_) cancel_->store(true);
}

void ImportController::start(std::function<ImportOutcome(const std::atomic<bool>*)> job,
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
                                  tr("Cancel"), 0, 0, dialogParent_);
    dialog_->setWindowTitle(tr("Import"));
    dialog_->setMinimumDuration(300);
    dialog_->setWindowModality(Qt::WindowModal);
    dialog_->setAutoClose(false);
    dialog_->setAutoReset(false);
    connect(dialog_, &QProgressDialog::canceled, this, &ImportController::cancel);
  }
  auto cancelFlag = cancel_;
  watcher_.setFuture(QtConcurrent::run([job = std::move(job), cancelFlag] {
    try {
      ImportOutcome out = job(cancelFlag.get());
      out.cancelled = cancelFlag->load();
      return out;
    } catch (const std::exception& e) {
      ImportOutcome failed;
      failed.error.text = e.what();
      return failed;
    }
  }));
}

void ImportController::onFinished() {
  // Gone before any message box: a deleteLater alone waits for the box's own event loop to end,
  // and the dialog's minimum-duration timer could even show it over the error.
  closeProgressDialog();
  ImportOutcome result = watcher_.future().takeResult();  // moved out: the drawing is not copied
  const QString name = pendingName_;
  const bool waived = budgetWaived_;
  budgetWaived_ = false;
  if (!result.cancelled && !result.job && result.error.pointBudgetExceeded() && interactive_ && askBudget_) {
    // Stopped early by the points budget: ask before reading the whole file.
    const bool whole = askBudget_(
        tr("Very large drawing"),
        tr("%1 has more than %2 points after flattening (a runaway file?). Reading it was stopped "
           "there.\n\nPlanning and plotting it may take very long. Import it whole anyway?")
            .arg(QFileInfo(name).fileName(), QLocale().toString(static_cast<qulonglong>(kDefaultMaxPoints))));
    if (whole && retry_) {
      maxPoints_ = 0;
      budgetWaived_ = true;
      retry_();
      maxPoints_ = kDefaultMaxPoints;
      return;
    }
  }
  if (result.cancelled || !result.job) {
    QString message = QString::fromStdString(result.error.text);
    if (result.cancelled) message = tr("Import of %1 cancelled.").arg(name);
    if (message.isEmpty()) message = tr("%1 could not be imported.").arg(name);
    if (interactive_ && !result.cancelled)
      QMessageBox::warning(dialogParent_, tr("Import failed"), message);
    emit finished(false, message);
    return;
  }
  job::LoadedJob& loaded = *result.job;
  if (loaded.drawing.layers.empty()) {
    const QString message = tr("%1 contains nothing to draw.").arg(name);
    if (interactive_) QMessageBox::warning(dialogParent_, tr("Import failed"), message);
    emit finished(false, message);
    return;
  }
  Placement placement;
  if (loaded.options.atMm) {
    placement = Placement{*loaded.options.atMm, loaded.options.rotationRad, loaded.options.scale,
                          loaded.options.stretchY};
  } else {  // no singularity-free area: in front of the motors, true size
    placement.centerMm = Vec2(0.0, 0.5 * (doc_.profile().geometry.a1 + doc_.profile().geometry.b1));
  }
  // After hatching the drawing may have grown past the budget: asked here (unless already waived).
  if (const QString excess = waived ? QString() : pointBudgetExcess(loaded.drawing, name); !excess.isEmpty()) {
    const bool anyway =
        interactive_ && askBudget_ &&
        askBudget_(QCoreApplication::translate("ImportWarningsPanel", "Very large drawing"),
                   excess + QStringLiteral("\n\n") +
                       QCoreApplication::translate("ImportWarningsPanel",
                                                   "Planning and plotting it may take very long. Import it anyway?"));
    if (!anyway) {
      emit finished(false, excess);
      return;
    }
  }
  note_ = translated(loaded.note);
  if (loaded.isProject) {
    doc_.loadProject(std::move(loaded.drawing), loaded.source, placement, loaded.options.mode, loaded.options.toleranceMm,
                     loaded.profile, name);
  } else {
    doc_.replaceDrawing(std::move(loaded.drawing), name, placement, loaded.source);
  }
  if (pendingRemember_) addRecent(name);
  emit warningsReported(name, translated(loaded.warnings));
  emit finished(true, note_);
}

}  // namespace fivebar::widgets
