// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/help_menu.hpp"

#include <QAction>
#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QUrl>

namespace fivebar::studio {

QString documentationDir() {
  if (QCoreApplication::instance() != nullptr) {
    const QDir installed(QCoreApplication::applicationDirPath() + QStringLiteral("/../share/doc/fivebar-studio/docs"));
    if (installed.exists()) return installed.canonicalPath();
  }
#ifdef FIVEBAR_SOURCE_DOCS_DIR
  // Run from the build tree: the docs of the sources it was built from.
  const QDir source(QStringLiteral(FIVEBAR_SOURCE_DOCS_DIR));
  if (source.exists()) return source.canonicalPath();
#endif
  return {};
}

QString documentationFile(const QString& name) {
  const QString dir = documentationDir();
  if (dir.isEmpty()) return {};
  const QString path = QDir(dir).filePath(name);
  return QFileInfo::exists(path) ? path : QString();
}

HelpMenu::HelpMenu(QMenu* help, QWidget* window)
    : QObject(window), window_(window),
      open_([](const QString& path) { return QDesktopServices::openUrl(QUrl::fromLocalFile(path)); }) {
  QAction* guide = new QAction(tr("&First job guide"), help);
  guide->setObjectName(QStringLiteral("actionFirstJobGuide"));
  guide->setToolTip(tr("Connect, load a drawing, place it, preview and run: step by step"));
  connect(guide, &QAction::triggered, this, [this] { openDocument(QStringLiteral("first-job.md")); });
  QAction* docs = new QAction(tr("&Documentation"), help);
  docs->setObjectName(QStringLiteral("actionDocumentation"));
  docs->setShortcut(QKeySequence::HelpContents);
  connect(docs, &QAction::triggered, this, [this] { openDocument(QStringLiteral("studio.md")); });
  QAction* first = help->actions().isEmpty() ? nullptr : help->actions().front();
  help->insertAction(first, guide);
  help->insertAction(first, docs);
  if (first != nullptr) help->insertSeparator(first);
}

bool HelpMenu::openDocument(const QString& name) {
  const QString path = documentationFile(name);
  if (path.isEmpty()) {
    QMessageBox::information(window_, tr("Documentation"),
                             tr("The documentation file %1 is not installed. It is also on the "
                                "project's pages, in the docs folder.").arg(name));
    return false;
  }
  return open_(path);
}

}  // namespace fivebar::studio
