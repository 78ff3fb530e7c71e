// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/file_actions.hpp"

#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QSaveFile>
#include <QSettings>

#include "core/output/gcode.hpp"
#include "core/project/project.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::studio {
namespace {
const char* const kProfileKey = "machine/profileJson";
const char* const kLastDirKey = "project/lastDirectory";
}  // namespace

FileActions::FileActions(widgets::StudioDocument& doc, widgets::PreviewController& preview,
                         widgets::ImportController& importer, QWidget* window)
    : QObject(window), doc_(doc), preview_(preview), importer_(importer), window_(window) {
  ask_ = [this](const QString& text) {
    return QMessageBox::question(window_, tr("Unsaved changes"), text,
                                 QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                 QMessageBox::Save);
  };
  askPath_ = [this](const QString& title, const QString& filter, const QString& suffix) {
    QFileDialog dialog(window_, title, QSettings().value(kLastDirKey).toString(), filter);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(suffix);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty()) return QString();
    const QString path = dialog.selectedFiles().front();
    QSettings().setValue(kLastDirKey, QFileInfo(path).absolutePath());
    return path;
  };
  connect(&doc_, &widgets::StudioDocument::profileChanged, this, &FileActions::rememberProfile);
}

QString FileActions::rememberedProfileJson() { return QSettings().value(kProfileKey).toString(); }

void FileActions::rememberProfile() {
  QSettings().setValue(kProfileKey, QString::fromStdString(toJson(doc_.profile())));
}

bool FileActions::maybeSave() {
  if (!doc_.isModified() || !doc_.hasDrawing()) return true;
  const QString text =
      doc_.projectPath().isEmpty()
          ? tr("The untitled project made from %1 has changes that are not saved. Save it as a "
               "project first?")
                .arg(QFileInfo(doc_.fileName()).fileName())
          : tr("%1 has changes that are not saved. Save them first?").arg(QFileInfo(doc_.projectPath()).fileName());
  switch (ask_(text)) {
    case QMessageBox::Save: return save();
    case QMessageBox::Discard: return true;
    default: return false;
  }
}

bool FileActions::saveTo(const QString& path, QString* error) {
  const Project project = job::projectOf(doc_.source(), doc_.drawing(), doc_.placement(),
                                             doc_.modeSelection(), doc_.toleranceMm(), doc_.profile());
  QSaveFile file(path);
  const QByteArray text = QByteArray::fromStdString(projectToJson(project));
  if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit()) {
    if (error) *error = tr("Cannot save %1: %2").arg(path, file.errorString());
    return false;
  }
  doc_.markSaved(path);
  importer_.addRecent(path);
  return true;
}

bool FileActions::save() {
  if (!doc_.hasDrawing()) {
    emit message(tr("Nothing to save: open a drawing first."));
    return false;
  }
  if (doc_.projectPath().isEmpty()) return saveAs();
  QString error;
  if (!saveTo(doc_.projectPath(), &error)) {
    QMessageBox::warning(window_, tr("Save failed"), error);
    return false;
  }
  emit message(tr("Saved %1").arg(doc_.projectPath()));
  return true;
}

bool FileActions::saveAs() {
  if (!doc_.hasDrawing()) {
    emit message(tr("Nothing to save: open a drawing first."));
    return false;
  }
  const QString path = askPath_(tr("Save project"), tr("FiveBar projects (*.fivebar)"),
                                QStringLiteral("fivebar"));
  if (path.isEmpty()) return false;
  QString error;
  if (!saveTo(path, &error)) {
    QMessageBox::warning(window_, tr("Save failed"), error);
    return false;
  }
  emit message(tr("Saved %1").arg(path));
  return true;
}

void FileActions::open() {
  if (!maybeSave()) return;
  importer_.showOpenDialog();
}

void FileActions::openPath(const QString& path) {
  if (!maybeSave()) return;
  importer_.openFile(path);
}

QString FileActions::exportProblem() const {
  const widgets::PreviewResult& r = preview_.result();
  if (preview_.busy()) return tr("The job is still being planned; export it when planning is done.");
  if (r.status != widgets::PreviewStatus::Planned || !r.job)
    return tr("There is no planned job to export (see the job preview).");
  return {};
}

bool FileActions::exportGcodeTo(const QString& path, QString* error) {
  const widgets::PreviewResult& r = preview_.result();
  if (const QString problem = exportProblem(); !problem.isEmpty()) {
    if (error) *error = problem;
    return false;
  }
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  bool ok = true;
  writeGcode(*r.job, doc_.profile(), [&](std::string_view piece) {
    ok = ok && file.write(piece.data(), static_cast<qint64>(piece.size())) == static_cast<qint64>(piece.size());
  });
  if (!ok || !file.commit()) {
    if (error) *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

void FileActions::exportGcode() {
  QString error = exportProblem();
  if (!error.isEmpty()) {
    QMessageBox::information(window_, tr("Export G-code"), error);
    return;
  }
  const QString path = askPath_(tr("Export G-code"), tr("G-code (*.gcode *.nc);;All files (*)"),
                                QStringLiteral("gcode"));
  if (path.isEmpty()) return;
  if (!exportGcodeTo(path, &error)) {
    QMessageBox::warning(window_, tr("Export G-code"), error);
    return;
  }
  emit message(tr("Exported %1").arg(path));
}

void FileActions::fillRecentMenu(QMenu* menu) {
  menu->clear();
  const QStringList files = importer_.recentFiles();
  for (const QString& path : files)
    menu->addAction(QFileInfo(path).fileName(), this, [this, path] { openPath(path); })->setToolTip(path);
  if (!files.isEmpty()) menu->addSeparator();
  QAction* clear = menu->addAction(tr("Clear list"), &importer_,
                                   &widgets::ImportController::clearRecentFiles);
  clear->setEnabled(!files.isEmpty());
}

}  // namespace fivebar::studio
