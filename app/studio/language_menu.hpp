// SPDX-License-Identifier: GPL-3.0-or-later
// View > Language: the user interface language, remembered in QSettings ("view/language": "",
// "en", "de", "es" or "fr"; "" follows the system). The choice applies at the next start (the
// menu says so); --lang overrides it for one run (app/studio/data_files.hpp startupLocale).
#pragma once

#include <QObject>
#include <QString>

class QMenu;
class QWidget;

namespace fivebar::studio {

class LanguageMenu : public QObject {
  Q_OBJECT
 public:
  // Adds the "Language" submenu to `view`; `window` parents the restart note.
  LanguageMenu(QMenu* view, QWidget* window);

  // The remembered choice ("" = system).
  static QString remembered();
  // Remembers `code` ("" = system) for the next start.
  static void remember(const QString& code);

 private:
  QWidget* window_;
};

}  // namespace fivebar::studio
