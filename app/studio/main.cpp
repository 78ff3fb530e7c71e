// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-studio: the desktop application. Composition and start-up only:
//   fivebar-studio --help | --version     (no display needed)
//   fivebar-studio [--demo] [--machine PRESET|FILE] [--port PORT [--baud N]] [--lang LANG]
//                  [--screenshot FILE.png] [FILE.svg|PROJECT.fivebar]
//   fivebar-studio FILE.svg|PROJECT.fivebar [--machine PRESET|FILE] --export-gcode OUT.gcode
//     (headless: no display needed; app/studio/headless.hpp)
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QIcon>
#include <QLocale>
#include <QTimer>
#include <clocale>
#include <cstdio>
#include <cstring>

#include "app/studio/data_files.hpp"
#include "app/studio/headless.hpp"
#include "app/studio/main_window.hpp"
#include "app/studio/plan_timings.hpp"
#include "app/studio/startup.hpp"
#include "widgets/panels/fill_options_box.hpp"
#include "widgets/document/import_controller.hpp"
#include "session/machine_side.hpp"

using fivebar::studio::MainWindow;

namespace {

struct StudioOptions {
  QCommandLineOption demo{QStringLiteral("demo"),
                          QCoreApplication::translate("main", "Open the demo drawing on the "
                                                              "default maker plotter.")};
  QCommandLineOption machine{
      QStringLiteral("machine"),
      QCoreApplication::translate("main", "Machine profile: a preset name or a profile JSON file "
                                          "(default: the last one used, else maker-plotter)."),
      QStringLiteral("PRESET|FILE")};
  QCommandLineOption port{
      QStringLiteral("port"),
      QCoreApplication::translate("main", "Connect to the board on this port at start, as the "
                                          "Connect button does: a serial device, a pseudo-terminal "
                                          "or tcp:HOST:PORT."),
      QStringLiteral("PORT")};
  QCommandLineOption baud{
      QStringLiteral("baud"),
      QCoreApplication::translate("main", "With --port: the baud rate (default: the machine "
                                          "profile's, usually 115200)."),
      QStringLiteral("N")};
  QCommandLineOption lang{
      QStringLiteral("lang"),
      QCoreApplication::translate("main", "User interface language: de, en, es or fr (default: "
                                          "View > Language, else the system's)."),
      QStringLiteral("LANG")};
  QCommandLineOption screenshot{
      QStringLiteral("screenshot"),
      QCoreApplication::translate("main", "Save a picture of the window once the job is planned, "
                                          "then quit."),
      QStringLiteral("FILE.png")};
  QCommandLineOption overlay{
      QStringLiteral("overlay"),
      QCoreApplication::translate("main", "With --screenshot: show the workspace legend "
                                          "(legend) or a map (transmission, conditioning or "
                                          "resolution)."),
      QStringLiteral("MAP")};
  QCommandLineOption atTime{
      QStringLiteral("at-time"),
      QCoreApplication::translate("main", "With --screenshot: simulation position as a fraction "
                                          "of the job (0 to 1)."),
      QStringLiteral("FRACTION")};
  QCommandLineOption exportGcode{
      QStringLiteral("export-gcode"),
      QCoreApplication::translate("main", "Plan the drawing or project as the studio does, write "
                                          "the G-code and exit (no window)."),
      QStringLiteral("OUT.gcode")};
  QCommandLineOption timings{
      QStringLiteral("timings"),
      QCoreApplication::translate("main", "Print how long opening and planning the drawing took, "
                                          "stage by stage, to stderr (as fivebar plan --timings).")};
  QCommandLineOption fill{
      QStringLiteral("fill"),
      QCoreApplication::translate("main", "Filled shapes: outline (default), hatch or none; "
                                          "with hatch: SPACING_MM and ANGLE_DEG after colons."),
      QStringLiteral("MODE[:SPACING[:ANGLE]]")};

  void addTo(QCommandLineParser& parser) const {
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "Plan and simulate drawings for five-bar robots."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({demo, machine, port, baud, lang, screenshot, overlay, atTime, exportGcode, fill, timings});
    parser.addPositionalArgument(
        QStringLiteral("drawing"),
        QCoreApplication::translate("main", "SVG drawing or project to open."),
        QStringLiteral("[FILE.svg|PROJECT.fivebar]"));
  }
};

// --help and --version print and exit: they need no display, so no QApplication.
bool wantsTextOnly(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h") || !std::strcmp(a, "--help-all") ||
        !std::strcmp(a, "--version") || !std::strcmp(a, "-v"))
      return true;
  }
  return false;
}

void setApplicationNames() {
  QCoreApplication::setOrganizationName(QStringLiteral("FiveBar"));
  QCoreApplication::setApplicationName(QStringLiteral("FiveBar Studio"));
  QCoreApplication::setApplicationVersion(QStringLiteral(FIVEBAR_VERSION));
}

}  // namespace

int main(int argc, char** argv) {
  if (fivebar::studio::wantsHeadlessExport(argc, argv)) return fivebar::studio::runHeadlessExport(argc, argv);
  if (wantsTextOnly(argc, argv)) {
    QCoreApplication app(argc, argv);
    std::setlocale(LC_NUMERIC, "C");
    setApplicationNames();
    fivebar::studio::installTranslations(fivebar::studio::startupLocale(argc, argv));
    QCommandLineParser parser;
    const StudioOptions options;
    options.addTo(parser);
    parser.process(app);  // prints help or version and exits
    return 0;
  }
  QApplication app(argc, argv);
  // Qt set the C library's locale from the environment: G-code, profiles and project files are
  // written with the decimal point whatever the language (the UI formats numbers with QLocale).
  std::setlocale(LC_NUMERIC, "C");
  setApplicationNames();
  QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/fivebar-studio.svg")));
  QApplication::setDesktopFileName(QStringLiteral("fivebar-studio"));
  const QLocale locale = fivebar::studio::startupLocale(argc, argv);
  if (!fivebar::studio::installTranslations(locale)) {
    std::fprintf(stderr, "fivebar-studio: no translation for '%s' (languages: en, %s)\n",
                 qPrintable(locale.name()),
                 qPrintable(fivebar::studio::translatedLanguages().join(QStringLiteral(", "))));
  }

  QCommandLineParser parser;
  const StudioOptions options;
  options.addTo(parser);
  parser.process(app);
  const QCommandLineOption& machine = options.machine;
  const QCommandLineOption& screenshot = options.screenshot;
  const QCommandLineOption& overlay = options.overlay;
  const QCommandLineOption& atTime = options.atTime;
  const QCommandLineOption& fill = options.fill;
  const QCommandLineOption& demo = options.demo;

  std::string error;
  const auto profile = fivebar::studio::startupProfile(
      parser.isSet(machine) ? std::optional<QString>(parser.value(machine)) : std::nullopt, error);
  if (!profile) {
    std::fprintf(stderr, "fivebar-studio: %s\n", error.c_str());
    return 2;
  }
  MainWindow window(*profile);
  // --port PORT [--baud N]: connected once the event loop runs, as the Connect button does.
  if (const QString problem = fivebar::studio::connectAtStart(window, parser.value(options.port),
                                                               parser.value(options.baud));
      !problem.isEmpty()) {
    std::fprintf(stderr, "fivebar-studio: %s\n", qPrintable(problem));
    return 2;
  }
  window.show();

  if (parser.isSet(fill) && !fivebar::widgets::applyFillOption(window.fillOptions(), parser.value(fill))) {
    std::fprintf(stderr, "fivebar-studio: --fill: expected outline, hatch[:SPACING[:ANGLE]] or none, got '%s'\n",
                 qPrintable(parser.value(fill)));
    return 2;
  }
  const QStringList files = parser.positionalArguments();
  if (parser.isSet(options.timings)) fivebar::studio::printPlanTimings(window);
  if (!files.isEmpty()) {
    window.importer().openFile(files.front());
  } else if (parser.isSet(demo)) {
    QFile demoFile(fivebar::studio::demoDrawingPath());
    if (demoFile.open(QIODevice::ReadOnly)) {
      window.importer().openData(demoFile.readAll(), QStringLiteral("fivebar-demo.svg"));
    }
    // --demo also connects the built-in simulated machine, unless --port names the board.
    if (!parser.isSet(options.port)) window.machine().connectSimulated();
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
