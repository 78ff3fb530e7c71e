// SPDX-License-Identifier: GPL-3.0-or-later
// Where fivebar-studio finds its data files (demo drawing, compiled translations, presets) and
// which user interface language it starts in.
//
// Installed (cmake --install, the Debian package) the executable is PREFIX/bin/fivebar-studio and
// its data PREFIX/share/fivebar-studio/{demo,translations,presets}: found relative to the
// executable, so any prefix works. In a build tree that directory does not exist and the copies
// embedded in the executable are used (:/demo, :/i18n).
#pragma once

#include <QLocale>
#include <QString>

namespace fivebar::studio {

// PREFIX/share/fivebar-studio when the executable runs from an installed tree, else empty.
QString installedDataDir();

// The demo drawing: the installed file, else the embedded copy.
QString demoDrawingPath();

// The directory holding fivebar_LANG.qm: installed, else embedded.
QString translationsDir();

// Language codes the studio is translated into (besides English).
QStringList translatedLanguages();

// The language to start in: "--lang LANG" (or --lang=LANG) on the command line, else View >
// Language as remembered in QSettings ("" = system), else the system locale. Scans argv itself
// so it can run before any QCoreApplication exists; QSettings needs the application names set.
QLocale startupLocale(int argc, char** argv);

// Installs the studio's and Qt's translations for `locale` into the running application and
// makes `locale` the default for number formatting. Returns true when the studio's own
// translation was found (always true for English).
bool installTranslations(const QLocale& locale);

}  // namespace fivebar::studio
