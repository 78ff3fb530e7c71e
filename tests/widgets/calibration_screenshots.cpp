// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_calibration_screenshots OUTDIR [de]: screenshots of Machine > Calibrate... for the docs,
// from the real main window (not a test; run it under xvfb-run -a -s "-screen 0 1600x1000x24"):
// calibration-1-pattern.png ... calibration-7-accuracy.png, one per step of the wizard, walked
// through on the simulated imperfect machine (the form's defaults), plus the distances form
// (calibration-3b-distances.png), the simulated-machine setting (simulated-machine-dialog.png) and
// the studio drawing the demo on the imperfect simulated machine, its true trace beside the plan
// (simulated-machine-canvas.png). With "de" the German translation is installed first
// (...-de.png).
#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QDir>
#include <QFile>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QThread>
#include <QTranslator>
#include <cstdio>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "app/studio/main_window.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/distances_box.hpp"
#include "widgets/calibration/simulated_machine.hpp"
#include "session/machine_side.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace {

using fivebar::test::grab;
using fivebar::test::settle;
using fivebar::test::waitUntil;

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
  {
    auto* m = w->measurePage();
    m->tabs()->setCurrentWidget(m->distances());
    m->distances()->fillFromSimulatedSheet();
    m->distances()->table()->setCurrentCell(3, 2);
    ok = grab(*w, out + QStringLiteral("/calibration-3b-distances") + suffix) && ok;
    m->tabs()->setCurrentIndex(0);
  }
  w->next();
  ok = grab(*w, out + QStringLiteral("/calibration-4-fit") + suffix) && ok;
  w->next();
  w->applyPage()->apply();
  ok = grab(*w, out + QStringLiteral("/calibration-5-apply") + suffix) && ok;
  w->next();
  ok = grab(*w, out + QStringLiteral("/calibration-6-verify") + suffix) && ok;
  w->next();
  w->accuracyPage()->fillFromSimulatedSheet();
  ok = grab(*w, out + QStringLiteral("/calibration-7-accuracy") + suffix) && ok;
  w->reject();
  window.document().undoStack()->undo();  // the profile as it was

  // The studio's simulated-machine setting, and the demo drawn by the imperfect simulated machine.
  using fivebar::widgets::calibration::SimulatedMachineDialog;
  auto* dialog = window.findChild<SimulatedMachineDialog*>();
  fivebar::session::MachineSide* machine = &window.machine();
  if (!dialog) return 1;
  QTemporaryDir jobs;
  machine->run().setJobDirectory(jobs.filePath(QStringLiteral("jobs")));
  dialog->form()->setAmounts(fivebar::widgets::calibration::TrueMachineForm::example());
  dialog->show();
  ok = grab(*dialog, out + QStringLiteral("/simulated-machine-dialog") + suffix) && ok;
  dialog->applyForm();
  dialog->accept();
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  if (!demo.open(QIODevice::ReadOnly)) return 1;
  window.importer().setInteractive(false);
  window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  machine->connectSimulated(40.0);
  auto& session = machine->session();
  if (!waitUntil([&] {
        return window.preview().result().status == fivebar::widgets::PreviewStatus::Planned &&
               !window.preview().busy() && session.state() == fivebar::grbl::MachineState::Idle;
      }, 60000))
    return 1;
  if (!machine->run().start()) return 1;
  waitUntil([&] { return !machine->run().running(); }, 240000);
  ok = grab(window, out + QStringLiteral("/simulated-machine-canvas") + suffix) && ok;
  // Leave the saved setting as it was before (the screenshots' own settings folder).
  window.simulatedTruth().makePerfect(true);
  return ok ? 0 : 1;
}
