// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar_dialog_screenshots OUTDIR LANG: screenshots of the studio's dialogs and panels other than
// the main window in one language (de, fr, es or en), to look for clipped or untranslated labels.
// Not a test; run it under xvfb-run -a -s "-screen 0 1600x1000x24". Writes into OUTDIR:
//   dialog-profile-LANG.png      the machine profile editor (its dock)
//   dialog-design-LANG.png       Machine > Design... before a search
//   dialog-calibration-LANG.png  Machine > Calibrate..., first page
//   dialog-settings-LANG.png     Machine > Machine settings..., board read on the simulated machine
//   dialog-preflight-LANG.png    the job preview with its pre-flight problems (the demo drawing
//                                moved partly out of reach)
//   dialog-profile-error-LANG.png the profile editor showing validation problems (a1 negative)
//   dialog-placement-LANG.png    the placement panel with the demo drawing
//   dialog-console-LANG.png      the machine console after connecting the simulated machine
// The language is installed as the studio installs it (translations and number format).
// With FIVEBAR_DEBUG_WIDTHS set, the profile editor's widgets wider than 250 px are listed (the
// ones that make the dock clip at the window's left dock width).
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QListWidget>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "app/studio/data_files.hpp"
#include "app/studio/main_window.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/design/design_dialog.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"
#include "widgets/document/studio_document.hpp"
#include "session/machine_side.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/panels/placement_panel.hpp"
#include "widgets/panels/preview_panel.hpp"
#include "widgets/panels/profile_editor.hpp"

namespace {

using fivebar::test::grab;
using fivebar::test::waitUntil;

// The dock holding `widget`, raised and shown.
QDockWidget* raisedDockOf(QWidget* widget) {
  for (QWidget* p = widget; p != nullptr; p = p->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(p)) {
      dock->show();
      dock->raise();
      return dock;
    }
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: fivebar_dialog_screenshots OUTDIR de|fr|es|en\n");
    return 2;
  }
  QTemporaryDir settingsDir;  // a fresh dock layout, not the user's
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  QApplication::setOrganizationName(QStringLiteral("FiveBarScreenshots"));
  QApplication::setApplicationName(QStringLiteral("FiveBar Studio"));
  const QString out = QString::fromLocal8Bit(argv[1]);
  const QString lang = QString::fromLatin1(argv[2]);
  if (!fivebar::studio::installTranslations(QLocale(lang))) {
    std::fprintf(stderr, "no translation for %s\n", argv[2]);
    return 1;
  }
  const QString suffix = QStringLiteral("-%1.png").arg(lang);
  using namespace fivebar;
  studio::MainWindow window(*preset("maker-plotter"));
  window.resize(1500, 950);
  window.show();
  session::MachineSide* machine = &window.machine();
  bool ok = true;

  // The profile editor, in its dock.
  if (auto* editor = window.findChild<widgets::ProfileEditor*>()) {
    QDockWidget* dock = raisedDockOf(editor);
    if (dock) dock->setFloating(true), dock->resize(330, 940);  // the width of the window's left docks
    ok = grab(dock ? static_cast<QWidget&>(*dock) : *editor, out + "/dialog-profile" + suffix) && ok;
    if (QDoubleSpinBox* a1 = editor->numberField("geometry.a1")) {
      const double before = a1->value();
      a1->setValue(-5.5);
      ok = grab(dock ? static_cast<QWidget&>(*dock) : *editor, out + "/dialog-profile-error" + suffix) && ok;
      a1->setValue(before);
    }
    if (dock) dock->setFloating(false);
    if (qEnvironmentVariableIsSet("FIVEBAR_DEBUG_WIDTHS"))
      for (QWidget* w : editor->findChildren<QWidget*>())
        if (w->isVisible() && w->minimumSizeHint().width() > 250)
          std::printf("%d %s %s\n", w->minimumSizeHint().width(), w->metaObject()->className(),
                      qPrintable(w->property("text").toString()));
  }

  // Machine > Design..., before a search.
  if (QAction* design = window.findChild<QAction*>(QStringLiteral("designAction"))) {
    design->trigger();
    if (auto* dialog = window.findChild<widgets::DesignDialog*>()) {
      dialog->resize(1100, 720);
      ok = grab(*dialog, out + "/dialog-design" + suffix) && ok;
      dialog->hide();
    }
  }

  // Machine > Calibrate..., first page.
  if (QAction* calibrate = window.calibrateAction()) {
    calibrate->trigger();
    if (auto* wizard = window.calibrationWizard()) {
      wizard->resize(1060, 720);
      ok = grab(*wizard, out + "/dialog-calibration" + suffix) && ok;
      wizard->hide();
    }
  }

  // Machine settings, read from the simulated machine.
  machine->connectSimulated(6.0);
  session::MachineSession& session = machine->session();
  waitUntil([&] { return session.state() == grbl::MachineState::Idle; }, 20000);
  widgets::MachineSettingsDialog* settings = window.machinePanels().openSettingsDialog();
  waitUntil([&] { return settings->table()->rowCount() > 0; }, 10000);
  waitUntil([] { return false; }, 500);
  ok = grab(*settings, out + "/dialog-settings" + suffix) && ok;
  settings->hide();
  if (auto* console = window.machinePanels().consolePanel()) {
    QDockWidget* dock = raisedDockOf(console);
    if (dock) dock->setFloating(true), dock->resize(620, 360);
    waitUntil([] { return false; }, 300);
    ok = grab(dock ? static_cast<QWidget&>(*dock) : static_cast<QWidget&>(*console),
              out + "/dialog-console" + suffix) && ok;
    if (dock) dock->setFloating(false);
  }

  // The job preview of the demo drawing, moved so that part of it is out of reach.
  QFile demo(QStringLiteral(FIVEBAR_DEMO_SVG));
  if (!demo.open(QIODevice::ReadOnly)) return 1;
  window.importer().setInteractive(false);
  window.importer().openData(demo.readAll(), QStringLiteral("fivebar-demo.svg"));
  waitUntil([&] { return window.preview().result().status == widgets::PreviewStatus::Planned; }, 60000);
  if (auto* placement = window.findChild<widgets::PlacementPanel*>()) {
    QDockWidget* dock = raisedDockOf(placement);
    if (dock) dock->setFloating(true), dock->resize(330, 420);
    waitUntil([] { return false; }, 300);
    ok = grab(dock ? static_cast<QWidget&>(*dock) : *placement, out + "/dialog-placement" + suffix) && ok;
    if (dock) dock->setFloating(false);
  }
  Placement far = window.document().placement();
  far.centerMm += Vec2(0.0, 90.0);
  window.document().setPlacement(far);
  waitUntil([&] {
    return !window.preview().busy() && window.preview().result().status == widgets::PreviewStatus::Infeasible;
  }, 60000);
  if (auto* panel = window.findChild<widgets::PreviewPanel*>()) {
    QDockWidget* dock = raisedDockOf(panel);
    if (dock) dock->setFloating(true), dock->resize(520, 620);
    ok = grab(dock ? static_cast<QWidget&>(*dock) : *panel, out + "/dialog-preflight" + suffix) && ok;
  }
  return ok ? 0 : 1;
}
