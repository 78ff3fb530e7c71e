// fivebar-studio: the desktop application. Composition and start-up only:
//   fivebar-studio [--demo] [--machine PRESET|FILE] [--lang LANG] [--screenshot FILE.png]
//                  [FILE.svg|PROJECT.fivebar]
//   fivebar-studio FILE.svg|PROJECT.fivebar [--machine PRESET|FILE] --export-gcode OUT.gcode
//     (headless: no display needed; app/studio/headless.hpp)
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QTimer>
#include <QTranslator>
#include <cstdio>

#include "app/studio/headless.hpp"
#include "app/studio/main_window.hpp"
#include "app/studio/startup.hpp"
#include "widgets/panels/fill_options_box.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/machine/machine_ui.hpp"

using fivebar::studio::MainWindow;

int main(int argc, char** argv) {
  if (fivebar::studio::wantsHeadlessExport(argc, argv)) return fivebar::studio::runHeadlessExport(argc, argv);
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("FiveBar"));
  QApplication::setApplicationName(QStringLiteral("FiveBar Studio"));
  QApplication::setApplicationVersion(QStringLiteral(FIVEBAR_VERSION));
  QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/fivebar-studio.svg")));
  QApplication::setDesktopFileName(QStringLiteral("fivebar-studio"));

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QApplication::translate("main", "Plan and simulate drawings for five-bar robots."));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption demo(QStringLiteral("demo"),
                                QApplication::translate("main", "Open the demo drawing on the "
                                                                "default maker plotter."));
  const QCommandLineOption machine(
      QStringLiteral("machine"),
      QApplication::translate("main", "Machine profile: a preset name or a profile JSON file "
                                      "(default: the last one used, else maker-plotter)."),
      QStringLiteral("PRESET|FILE"));
  const QCommandLineOption lang(
      QStringLiteral("lang"),
      QApplication::translate("main", "User interface language (e.g. de, en); default: system."),
      QStringLiteral("LANG"));
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QApplication::translate("main", "Save a picture of the window once the job is planned, "
                                      "then quit."),
      QStringLiteral("FILE.png"));
  const QCommandLineOption overlay(
      QStringLiteral("overlay"),
      QApplication::translate("main", "With --screenshot: show the workspace legend "
                                      "(legend) or a map (transmission, conditioning or "
                                      "resolution)."),
      QStringLiteral("MAP"));
  const QCommandLineOption atTime(
      QStringLiteral("at-time"),
      QApplication::translate("main", "With --screenshot: simulation position as a fraction "
                                      "of the job (0 to 1)."),
      QStringLiteral("FRACTION"));
  const QCommandLineOption exportGcode(
      QStringLiteral("export-gcode"),
      QApplication::translate("main", "Plan the drawing or project as the studio does, write the "
                                      "G-code and exit (no window)."),
      QStringLiteral("OUT.gcode"));
  const QCommandLineOption fill(
      QStringLiteral("fill"),
      QApplication::translate("main", "Filled shapes: outline (default), hatch or none; "
                                      "with hatch: SPACING_MM and ANGLE_DEG after colons."),
      QStringLiteral("MODE[:SPACING[:ANGLE]]"));
  parser.addOptions({demo, machine, lang, screenshot, overlay, atTime, exportGcode, fill});
  parser.addPositionalArgument(QStringLiteral("drawing"),
                               QApplication::translate("main", "SVG drawing or project to open."),
                               QStringLiteral("[FILE.svg|PROJECT.fivebar]"));
  parser.process(app);

  QTranslator translator;
  const QLocale locale = parser.isSet(lang) ? QLocale(parser.value(lang)) : QLocale::system();
  if (translator.load(locale, QStringLiteral("fivebar"), QStringLiteral("_"),
                      QStringLiteral(":/i18n"))) {
    QApplication::installTranslator(&translator);
  }
  QTranslator qtTranslator;
  if (qtTranslator.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                        QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
    QApplication::installTranslator(&qtTranslator);
  }

  std::string error;
  const auto profile = fivebar::studio::startupProfile(
      parser.isSet(machine) ? std::optional<QString>(parser.value(machine)) : std::nullopt, error);
  if (!profile) {
    std::fprintf(stderr, "fivebar-studio: %s\n", error.c_str());
    return 2;
  }
  MainWindow window(*profile);
  window.show();

  if (parser.isSet(fill) && !fivebar::widgets::applyFillOption(window, parser.value(fill))) {
    std::fprintf(stderr, "fivebar-studio: --fill: expected outline, hatch[:SPACING[:ANGLE]] or none, got '%s'\n",
                 qPrintable(parser.value(fill)));
    return 2;
  }
  const QStringList files = parser.positionalArguments();
  if (!files.isEmpty()) {
    window.importer().openFile(files.front());
  } else if (parser.isSet(demo)) {
    QFile demoFile(QStringLiteral(":/demo/fivebar-demo.svg"));
    if (demoFile.open(QIODevice::ReadOnly)) {
      window.importer().openData(demoFile.readAll(), QStringLiteral("fivebar-demo.svg"));
    }
    // --demo also connects the built-in simulated machine.
    window.machine().connectSimulated();
  }
  if (parser.isSet(screenshot)) {
    window.importer().setInteractive(false);
    const QStringList overlayValue = parser.values(overlay);
    const QString atTimeValue = parser.value(atTime);
    fivebar::studio::screenshotWhenReady(
        window, parser.value(screenshot), !files.isEmpty() || parser.isSet(demo),
        [&window, overlayValue, atTimeValue] {
          const QString problem =
              fivebar::studio::applyViewOptions(window, overlayValue, atTimeValue);
          if (!problem.isEmpty()) std::fprintf(stderr, "fivebar-studio: %s\n", qPrintable(problem));
        });
  }
  return QApplication::exec();
}
