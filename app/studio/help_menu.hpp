// SPDX-License-Identifier: GPL-3.0-or-later
// Help > Documentation and Help > First job guide: the documentation opened locally (the
// system's viewer for the file, QDesktopServices), no network. The files: installed with the
// package under PREFIX/share/doc/fivebar-studio/docs (resources/CMakeLists.txt); run from a
// build tree, the source tree's docs/.
#pragma once

#include <QObject>
#include <QString>
#include <functional>

class QMenu;
class QWidget;

namespace fivebar::studio {

// The documentation directory: installed, else the source tree's docs/ (when it exists), else "".
QString documentationDir();
// A file of the documentation ("first-job.md"), or "" when it cannot be found.
QString documentationFile(const QString& name);

class HelpMenu : public QObject {
  Q_OBJECT
 public:
  // Adds the two actions at the top of `help` (before About).
  HelpMenu(QMenu* help, QWidget* window);
  // How a file is opened (tests replace QDesktopServices::openUrl); returns whether it opened.
  void setOpener(std::function<bool(const QString& path)> open) { open_ = std::move(open); }
  // Opens the documentation's file `name` (or says in a message box where it is missing).
  bool openDocument(const QString& name);

 private:
  QWidget* window_;
  std::function<bool(const QString&)> open_;
};

}  // namespace fivebar::studio
