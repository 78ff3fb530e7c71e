// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_design_screenshots OUTDIR [de]: screenshots of Machine > Design... for the docs, from
// the real main window (not a test; run it under xvfb-run -a -s "-screen 0 1600x1000x24"):
//   design-dialog.png   the dialog after an A5 search (10 mm margin), best design selected
//   design-canvas.png   the main window's canvas previewing that design with its condition map
// With "de" the German translation is installed first (design-dialog-de.png).
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QSettings>
#include <QThread>
#include <QTranslator>
#include <cstdio>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "app/studio/main_window.hpp"
#include "widgets/design/design_dialog.hpp"

namespace {

using fivebar::test::grab;
using fivebar::test::waitUntil;

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: fivebar_design_screenshots OUTDIR [de]\n");
    return 2;
  }
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QSettings::setDefaultFormat(QSettings::IniFormat);
  const QString out = QString::fromLocal8Bit(argv[1]);
  const bool german = argc > 2 && QString::fromLatin1(argv[2]) == QLatin1String("de");
  QTranslator translator;
  if (german && translator.load(QStringLiteral(":/i18n/fivebar_de.qm"))) QCoreApplication::installTranslator(&translator);
  fivebar::studio::MainWindow window(*fivebar::preset("maker-plotter"));
  window.resize(1500, 950);
  window.show();
  QAction* action = window.findChild<QAction*>(QStringLiteral("designAction"));
  if (!action) return 1;
  action->trigger();
  auto* dialog = window.findChild<fivebar::widgets::DesignDialog*>();
  if (!dialog) return 1;
  dialog->resize(1100, 720);
  dialog->move(window.pos() + QPoint(380, 120));
  const auto combos = dialog->findChildren<QComboBox*>();
  combos[0]->setCurrentIndex(1);  // A5, landscape, 10 mm margin: 190 x 128 mm
  dialog->startSearch();
  if (!waitUntil([&] { return !dialog->searching(); }, 120000)) return 1;
  waitUntil([&] { return false; }, 300);
  bool ok = grab(*dialog, out + (german ? "/design-dialog-de.png" : "/design-dialog.png"));
  if (!german) {
    dialog->hide();
    dialog->show();  // hiding cleared the preview: select the best design again
    dialog->selectDesign(0);
    dialog->selectDesign(dialog->designCount() - 1);  // the lowest condition number
    dialog->move(window.pos() + QPoint(2000, 0));
    ok = grab(window, out + "/design-canvas.png") && ok;
  }
  return ok ? 0 : 1;
}
