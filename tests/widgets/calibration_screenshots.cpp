// fivebar_calibration_screenshots OUTDIR [de]: screenshots of Machine > Calibrate... for the docs,
// from the real main window (not a test; run it under xvfb-run -a -s "-screen 0 1600x1000x24"):
// calibration-1-pattern.png ... calibration-6-verify.png, one per step of the wizard, walked
// through on the simulated imperfect machine (the form's defaults). With "de" the German
// translation is installed first (calibration-N-...-de.png).
#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QTableWidget>
#include <QThread>
#include <QTranslator>
#include <cstdio>
#include <functional>

#include "app/studio/main_window.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace {

void settle(int ms) {
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < ms) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    QThread::msleep(2);
  }
}

bool grab(QWidget& w, const QString& path) {
  settle(300);
  const bool ok = w.grab().save(path);
  std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: fivebar_calibration_screenshots OUTDIR [de]\n");
    return 2;
  }
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QSettings::setDefaultFormat(QSettings::IniFormat);
  const QString out = QString::fromLocal8Bit(argv[1]);
  const bool german = argc > 2 && QString::fromLatin1(argv[2]) == QLatin1String("de");
  QTranslator translator;
  if (german && translator.load(QStringLiteral(":/i18n/fivebar_de.qm"))) QCoreApplication::installTranslator(&translator);
  const QString suffix = german ? QStringLiteral("-de.png") : QStringLiteral(".png");
  fivebar::studio::MainWindow window(*fivebar::preset("maker-plotter"));
  window.resize(1500, 950);
  window.show();
  window.calibrateAction()->trigger();
  auto* w = window.calibrationWizard();
  if (!w) return 1;
  w->resize(1060, 720);
  bool ok = grab(*w, out + QStringLiteral("/calibration-1-pattern") + suffix);
  w->next();
  ok = grab(*w, out + QStringLiteral("/calibration-2-draw") + suffix) && ok;
  w->next();
  w->measurePage()->fillFromSimulatedSheet();
  w->measurePage()->table()->setCurrentCell(6, 4);
  ok = grab(*w, out + QStringLiteral("/calibration-3-measure") + suffix) && ok;
  w->next();
  ok = grab(*w, out + QStringLiteral("/calibration-4-fit") + suffix) && ok;
  w->next();
  w->applyPage()->apply();
  ok = grab(*w, out + QStringLiteral("/calibration-5-apply") + suffix) && ok;
  w->next();
  ok = grab(*w, out + QStringLiteral("/calibration-6-verify") + suffix) && ok;
  return ok ? 0 : 1;
}
