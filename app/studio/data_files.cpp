// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/data_files.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QTranslator>
#include <cstring>

#include "app/studio/language_menu.hpp"

namespace fivebar::studio {

QString installedDataDir() {
  // applicationDirPath() needs an application object; before one exists, nothing is installed
  // as far as we can tell.
  if (QCoreApplication::instance() == nullptr) return {};
  const QDir dir(QCoreApplication::applicationDirPath() + QStringLiteral("/../share/fivebar-studio"));
  return dir.exists() ? dir.canonicalPath() : QString();
}

QString demoDrawingPath() {
  const QString installed = installedDataDir();
  const QString file = installed + QStringLiteral("/demo/fivebar-demo.svg");
  if (!installed.isEmpty() && QFileInfo::exists(file)) return file;
  return QStringLiteral(":/demo/fivebar-demo.svg");
}

QString translationsDir() {
  const QString installed = installedDataDir();
  if (!installed.isEmpty() && QFileInfo::exists(installed + QStringLiteral("/translations")))
    return installed + QStringLiteral("/translations");
  return QStringLiteral(":/i18n");
}

QStringList translatedLanguages() {
  return {QStringLiteral("de"), QStringLiteral("es"), QStringLiteral("fr")};
}

QLocale startupLocale(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--lang") == 0 && i + 1 < argc) return QLocale(QString::fromLocal8Bit(argv[i + 1]));
    if (std::strncmp(argv[i], "--lang=", 7) == 0) return QLocale(QString::fromLocal8Bit(argv[i] + 7));
  }
  const QString remembered = LanguageMenu::remembered();
  if (!remembered.isEmpty()) return QLocale(remembered);
  return QLocale::system();
}

bool installTranslations(const QLocale& locale) {
  QLocale::setDefault(locale);
  // Owned by the application object, so they live exactly as long as it.
  auto* qt = new QTranslator(QCoreApplication::instance());
  if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
               QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
    QCoreApplication::installTranslator(qt);
  }
  if (locale.language() == QLocale::English || locale.language() == QLocale::C) {
    // English needs only the plural forms of the "%n ...(s)" texts.
    auto* plurals = new QTranslator(QCoreApplication::instance());
    if (plurals->load(QStringLiteral("plurals_en"), translationsDir())) QCoreApplication::installTranslator(plurals);
    return true;
  }
  auto* own = new QTranslator(QCoreApplication::instance());
  if (!own->load(locale, QStringLiteral("fivebar"), QStringLiteral("_"), translationsDir())) return false;
  QCoreApplication::installTranslator(own);
  return true;
}

}  // namespace fivebar::studio
