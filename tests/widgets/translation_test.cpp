// SPDX-License-Identifier: GPL-3.0-or-later
// The German translation is complete (every message translated) and is what tr() finds at run
// time from the embedded .qm (the contexts must be the qualified class names).
#include <gtest/gtest.h>

#include <memory>

#include <QAbstractButton>
#include <QAction>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <algorithm>
#include <set>

#include "app/studio/help_menu.hpp"
#include "app/studio/language_menu.hpp"
#include "widgets/canvas/machine_layer.hpp"
#include "widgets/calibration/distances_box.hpp"
#include "widgets/calibration/run_progress_box.hpp"
#include "widgets/calibration/sheet_layer.hpp"
#include "widgets/calibration/sim_trace_layer.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "app/studio/main_window.hpp"
#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/panels/fill_options_box.hpp"
#include "widgets/design/design_dialog.hpp"
#include "widgets/design/pareto_plot.hpp"
#include "core/calibration/measurements.hpp"
#include "core/import/svg_import.hpp"
#include "i18n/translated.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/job_pipeline.hpp"
#include "widgets/panels/import_warnings_panel.hpp"
#include "session/jog_controller.hpp"
#include "widgets/machine/jog_goto_tool.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/panels/layers_panel.hpp"
#include "widgets/machine/machine_banner.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/port_box.hpp"
#include "session/machine_session.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"
#include "widgets/machine/machine_panels.hpp"
#include "widgets/panels/mode_panel.hpp"
#include "widgets/panels/placement_panel.hpp"
#include "widgets/panels/preview_panel.hpp"
#include "widgets/panels/profile_editor.hpp"
#include "app/studio/file_actions.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "session/run_controller.hpp"
#include "widgets/machine/override_controls.hpp"
#include "widgets/machine/run_panel.hpp"
#include "widgets/machine/alarm_strip.hpp"
#include "widgets/machine/recovery_bar.hpp"
#include "drivers/check/motion_check.hpp"
#include "session/board_preflight.hpp"
#include "widgets/panels/simulation_panel.hpp"
#include "widgets/document/studio_document.hpp"

namespace {

// The contexts tr() uses at run time: the QObject classes' meta-object names (qualified) and
// the explicit contexts of QCoreApplication::translate calls.
std::set<QString> runtimeContexts() {
  using namespace fivebar::widgets;
  std::set<QString> names;
  for (const QMetaObject* m :
       {&fivebar::studio::MainWindow::staticMetaObject, &fivebar::studio::FileActions::staticMetaObject,
        &ConsolePanel::staticMetaObject, &JobLayer::staticMetaObject,
        &ImportController::staticMetaObject, &fivebar::session::JogController::staticMetaObject,
        &GoToTool::staticMetaObject, &JogPanel::staticMetaObject, &LayersPanel::staticMetaObject,
        &MachineBanner::staticMetaObject, &MachinePanel::staticMetaObject, &RecoveryBar::staticMetaObject,
        &AlarmStrip::staticMetaObject, &PortBox::staticMetaObject,
        &MachineLayer::staticMetaObject,
        &fivebar::session::MachineSession::staticMetaObject, &MachineSettingsDialog::staticMetaObject,
        &MachinePanels::staticMetaObject,
        &ModePanel::staticMetaObject, &PlacementPanel::staticMetaObject,
        &PreviewPanel::staticMetaObject, &SpeedLegend::staticMetaObject,
        &ProfileEditor::staticMetaObject, &fivebar::session::RunController::staticMetaObject,
        &RunPanel::staticMetaObject, &OverrideControls::staticMetaObject, &SimulationPanel::staticMetaObject,
        &StudioDocument::staticMetaObject, &FillOptionsBox::staticMetaObject,
        &ImportWarningsPanel::staticMetaObject, &DesignDialog::staticMetaObject,
        &ParetoPlot::staticMetaObject, &fivebar::studio::LanguageMenu::staticMetaObject,
        &calibration::CalibrationWizard::staticMetaObject,
        &calibration::PatternPage::staticMetaObject, &calibration::DrawPage::staticMetaObject,
        &calibration::MeasurePage::staticMetaObject, &calibration::FitPage::staticMetaObject,
        &calibration::ApplyPage::staticMetaObject, &calibration::VerifyPage::staticMetaObject,
        &calibration::CalibrationPreview::staticMetaObject,
        &calibration::SheetLayer::staticMetaObject, &calibration::AccuracyPage::staticMetaObject,
        &calibration::DistancesBox::staticMetaObject, &calibration::SimTraceLayer::staticMetaObject,
        &calibration::SimulatedMachineDialog::staticMetaObject, &calibration::SimulatedTruth::staticMetaObject,
        &calibration::SimulatedTruthBadge::staticMetaObject, &calibration::TrueMachineForm::staticMetaObject,
        &fivebar::session::BoardPreflight::staticMetaObject, &calibration::RunProgressBox::staticMetaObject,
        &fivebar::studio::HelpMenu::staticMetaObject})
    names.insert(QString::fromLatin1(m->className()));
  for (const char* c : {"QObject", "main", "DocumentCommands", "JobPipeline", "MapPainter",
                        "WorkspaceLegend", "ImportWarningsPanel", "DesignPainter", "ImportWarning",
                        "fivebar::widgets::MachineDialogs", "fivebar::session::SettingsAdvice",
                        "CalibrationWizard", "ProfileField", "GrblSetting",
                        // the core's messages (core/support/message.hpp, widgets::translated)
                        "Placement", "Planner", "Preflight", "Safety", "Profile", "CalibrationFit",
                        "CalibrationPattern", "CalibrationScan", "CalibrationFile", "Design", "ImportError",
                        // the drivers' messages the studio translates (session::translated)
                        "Jog", "MotionCheck", "SoftLimits"})
    names.insert(QString::fromLatin1(c));
  return names;
}

// Every context of the .ts file must be one tr() looks up; an unqualified "ModePanel" (lupdate
// not resolving "namespace fivebar::widgets {") would never be found at run time.
TEST(Translations, ContextsAreTheRuntimeOnes) {
  QFile ts(QStringLiteral(FIVEBAR_TS_DE));
  ASSERT_TRUE(ts.open(QIODevice::ReadOnly)) << FIVEBAR_TS_DE;
  QXmlStreamReader xml(&ts);
  const std::set<QString> known = runtimeContexts();
  QStringList unknown;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && xml.name() == QLatin1String("name")) {
      const QString context = xml.readElementText();
      if (!known.count(context)) unknown << context;
    }
  }
  EXPECT_TRUE(unknown.isEmpty()) << unknown.join(QLatin1Char(' ')).toStdString();
}

// Samples through the real run-time path: the installed German translator and tr() of the
// classes (whose context is their meta-object name).
TEST(Translations, RuntimeTrReturnsGerman) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  using namespace fivebar::widgets;
  EXPECT_EQ(ModePanel::tr("Working mode"), QStringLiteral("Arbeitsmodus"));
  EXPECT_EQ(fivebar::studio::MainWindow::tr("&File"), QStringLiteral("&Datei"));
  EXPECT_EQ(MachinePanels::tr("Jog"), QStringLiteral("Verfahren"));
  EXPECT_EQ(calibration::MeasurePage::tr("3. Measure the marks"), QStringLiteral("3. Die Marken vermessen"));
  EXPECT_EQ(LayersPanel::tr("%n path(s)", nullptr, 2), QStringLiteral("2 Pfade"));
  EXPECT_EQ(QCoreApplication::translate("WorkspaceLegend", "reach boundary"),
            QStringLiteral("Reichweitengrenze"));
  QCoreApplication::removeTranslator(&translator);
}

// The importer's warnings (core Messages, context "ImportWarning") reach the warnings panel in
// German: the real importer's messages, translated with their line, element and counts kept.
TEST(Translations, ImportWarningsAreShownInGerman) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QByteArray svg =
      "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' viewBox='0 0 100 100'>\n"
      "<image href='a.png' width='5' height='5'/>\n"
      "<image href='b.png' width='5' height='5'/>\n"
      "<path id='wave' d='M 0 0 L 10 10 x 5'/>\n"
      "<path d='M 0 0 L 20 10' clip-path='url(#c)'/>\n"
      "</svg>\n";
  const fivebar::svg::ImportResult r = fivebar::svg::importSvgData(svg, QStringLiteral("a.svg"));
  ASSERT_TRUE(r.ok()) << r.message;
  const QStringList shown = fivebar::translated(r.warnings);
  EXPECT_TRUE(shown.contains(QStringLiteral(
      "Zeile 4: <path id=\"wave\"> Attribut d: ungültige Pfaddaten bei Zeichen 17 (\"5\"): "
      "bis zum Fehler gezeichnet"))) << shown.join(QLatin1Char('\n')).toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("Element <image> entfernt (2x, zuerst in Zeile 2)")))
      << shown.join(QLatin1Char('\n')).toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("Zeile 5: <path> clip-path #c nicht gefunden: unbeschnitten gezeichnet")))
      << shown.join(QLatin1Char('\n')).toStdString();
  // The CLI's English is the same message's text().
  std::vector<std::string> english;
  for (const fivebar::Message& w : r.warnings) english.push_back(w.text());
  EXPECT_NE(std::find(english.begin(), english.end(), "<image> element removed (2x, first at line 2)"),
            english.end());
  // The panel shows them so.
  fivebar::widgets::ImportWarningsPanel panel;
  panel.showWarnings(QStringLiteral("a.svg"), shown);
  ASSERT_EQ(panel.list()->count(), shown.size());
  EXPECT_EQ(panel.list()->item(0)->text(), shown.front());
  QCoreApplication::removeTranslator(&translator);
}

// A pre-flight problem of the studio's planning (a drawing out of reach) is listed in German,
// its coordinates with a decimal comma; the same problem's English text (the CLI's) is unchanged.
TEST(Translations, PreflightProblemIsShownInGermanWithDecimalComma) {
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QLocale before;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  fivebar::widgets::PipelineInput input;
  fivebar::Layer layer;
  layer.id = layer.name = "ink";
  layer.paths.push_back({{fivebar::Vec2(0.0, 0.0), fivebar::Vec2(10.5, 0.0)}});
  auto drawing = std::make_shared<fivebar::Drawing>();
  drawing->layers.push_back(layer);
  drawing->source = "far.svg";
  input.drawing = drawing;
  input.placement.centerMm = fivebar::Vec2(0.0, 700.0);  // far beyond every leg's reach
  input.profile = *profile;
  const fivebar::widgets::PreviewResult r = fivebar::widgets::runPipeline(input);
  QLocale::setDefault(before);
  QCoreApplication::removeTranslator(&translator);
  ASSERT_EQ(r.status, fivebar::widgets::PreviewStatus::Infeasible) << r.message.toStdString();
  ASSERT_FALSE(r.problems.empty());
  const QString text = r.problems.front().text;
  // The layer and path once, by the layer's name (the CLI's sentence repeats them by index).
  EXPECT_TRUE(text.startsWith(QStringLiteral("Ebene 'ink' Pfad 0: Punkt 0 bei (")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(QStringLiteral("außerhalb der Reichweite von Arm"))) << text.toStdString();
  EXPECT_TRUE(text.contains(QRegularExpression(QStringLiteral("\\(-?\\d+,\\d\\d; -?\\d+,\\d\\d\\) mm"))))
      << text.toStdString();
  EXPECT_FALSE(text.contains(QRegularExpression(QStringLiteral("\\d\\.\\d")))) << text.toStdString();
  ASSERT_FALSE(r.problems.front().fixes.isEmpty());
  const QString fixes = r.problems.front().fixes.join(QLatin1Char(' '));
  EXPECT_FALSE(fixes.contains(QStringLiteral("fit the drawing"))) << fixes.toStdString();
  // In the studio's words: its panels' names, no command-line option.
  EXPECT_FALSE(fixes.contains(QStringLiteral("--"))) << fixes.toStdString();
  EXPECT_TRUE(fixes.contains(QStringLiteral("Platzierung"))) << fixes.toStdString();
  EXPECT_TRUE(r.message.startsWith(QStringLiteral("Arbeitsmodus "))) << r.message.toStdString();
}

// Profile validation reaches the profile editor in the user's language with the locale's
// decimal comma, and so do a broken profile file's problems (line and field names kept); the
// CLI's English (message.text()) is unchanged.
TEST(Translations, ProfileProblemsAreShownInFrench) {
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_fr.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QLocale before;
  QLocale::setDefault(QLocale(QLocale::French, QLocale::France));
  fivebar::MachineProfile bad = *profile;
  bad.geometry.a1 = -1.5;
  fivebar::widgets::StudioDocument doc(*profile);
  fivebar::widgets::ProfileEditor editor(doc);
  editor.numberField("geometry.a1")->setValue(-1.5);
  const QString shown = editor.messageFor("geometry.a1")->text();
  // A range's unit is the studio's too ("deg" is "°"); a range without a unit has none.
  const QString offset = fivebar::translated(
      fivebar::checkField(*fivebar::findProfileField("calibration.zeroOffsetDeg1"), 200.0).at(0).message);
  const QString version = fivebar::translated(
      fivebar::checkField(*fivebar::findProfileField("calibration.version"), 5.0).at(0).message);
  std::string english;
  for (const fivebar::ValidationIssue& i : fivebar::validate(bad))
    if (i.field == "geometry.a1" && english.empty()) english = i.message.text();
  const fivebar::ProfileLoad load = fivebar::profileFromJson("{\n  \"schema\": 3\n}\n", "p.json");
  const fivebar::ProfileLoad broken = fivebar::profileFromJson("{\n  \"schema\": ,\n}\n", "p.json");
  QLocale::setDefault(before);
  QCoreApplication::removeTranslator(&translator);
  EXPECT_EQ(english, "geometry.a1 must be positive, got -1.5");
  EXPECT_TRUE(offset.contains(QStringLiteral(" et 180 °, et non 200"))) << offset.toStdString();
  EXPECT_TRUE(version.endsWith(QStringLiteral(" et 1, et non 5"))) << version.toStdString();
  EXPECT_TRUE(shown.startsWith(QStringLiteral("geometry.a1 doit être positif, et non -1,5\n")))
      << shown.toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("a1 vaut -1,5 mm ; la valeur doit être positive")))
      << shown.toStdString();
  ASSERT_FALSE(load.issues.empty());
  ASSERT_FALSE(broken.issues.empty());
  QCoreApplication::installTranslator(&translator);
  const QString type = fivebar::translated(load.issues.front().message);
  const QString json = fivebar::translated(broken.issues.front().message);
  QCoreApplication::removeTranslator(&translator);
  EXPECT_EQ(type, QStringLiteral("schema doit être une chaîne, et non un nombre")) << type.toStdString();
  EXPECT_TRUE(json.startsWith(QStringLiteral("p.json:2:13 : JSON invalide : "))) << json.toStdString();
}

// A measurements file the wizard cannot read is named, with its line and column, in the user's
// language; the CLI's English is unchanged.
TEST(Translations, CalibrationFileProblemsAreShownInGerman) {
  const fivebar::calibration::MeasurementRead read = fivebar::calibration::readMeasurements(
      "id,theta1_deg,theta2_deg,x_mm,y_mm\n1,100,60,abc,5\n", "m.csv");
  ASSERT_FALSE(read.ok());
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QString shown = fivebar::translated(read.error);
  QCoreApplication::removeTranslator(&translator);
  EXPECT_EQ(read.error.text(), "m.csv:2: x_mm is not a number: \"abc\"");
  EXPECT_EQ(shown, QStringLiteral("m.csv:2: x_mm ist keine Zahl: „abc“"));
}

// An SVG that cannot be imported is refused in the user's language (the file, line and element
// kept as they are), through the worker process as in the studio; the CLI's text stays English.
TEST(Translations, ImportErrorsAreShownInSpanish) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString path = dir.filePath(QStringLiteral("roto.svg"));
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10mm\" height=\"10mm\">\n"
             "<circle id=\"p\" cx=\"NaN\" cy=\"5\" r=\"2\"/>\n</svg>\n");
  file.close();
  const fivebar::svg::ImportResult r = fivebar::svg::importSvgFile(path);
  ASSERT_FALSE(r.ok());
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_es.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QString shown = fivebar::translated(r.message);
  QCoreApplication::removeTranslator(&translator);
  const std::string english = r.message.text();
  EXPECT_NE(english.find("line 2: <circle id=\"p\"> attribute cx contains"), std::string::npos) << english;
  EXPECT_TRUE(shown.startsWith(path + QStringLiteral(": "))) << shown.toStdString();
  EXPECT_TRUE(shown.contains(QStringLiteral("línea 2: <circle id=\"p\"> atributo cx"))) << shown.toStdString();
  EXPECT_FALSE(shown.contains(QStringLiteral("line 2"))) << shown.toStdString();
}

// The fixes of a pre-flight problem name the studio's controls in every language: no
// command-line option, the placement panel by its translated title.
TEST(Translations, PreflightFixesUseTheStudiosWordsInEveryLanguage) {
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  fivebar::widgets::PipelineInput input;
  fivebar::Layer layer;
  layer.id = layer.name = "Dial";
  layer.paths.push_back({{fivebar::Vec2(0.0, 0.0), fivebar::Vec2(10.5, 0.0)}});
  auto drawing = std::make_shared<fivebar::Drawing>();
  drawing->layers.push_back(layer);
  drawing->source = "far.svg";
  input.drawing = drawing;
  input.placement.centerMm = fivebar::Vec2(0.0, 700.0);  // far beyond every leg's reach
  input.profile = *profile;
  const std::pair<const char*, const char*> languages[] = {
      {"de", "Platzierung"}, {"fr", "Placement"}, {"es", "Colocación"}, {"en", "Placement"}};
  for (const auto& [lang, panel] : languages) {
    QTranslator translator;
    if (std::string(lang) != "en") {
      ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_%1.qm").arg(QLatin1String(lang))));
      ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
    }
    const fivebar::widgets::PreviewResult r = fivebar::widgets::runPipeline(input);
    QCoreApplication::removeTranslator(&translator);
    ASSERT_EQ(r.status, fivebar::widgets::PreviewStatus::Infeasible) << lang << ": " << r.message.toStdString();
    ASSERT_FALSE(r.problems.empty()) << lang;
    const QString fixes = r.problems.front().fixes.join(QStringLiteral("; "));
    EXPECT_FALSE(fixes.contains(QStringLiteral("--"))) << lang << ": " << fixes.toStdString();
    EXPECT_TRUE(fixes.contains(QString::fromUtf8(panel))) << lang << ": " << fixes.toStdString();
    // The layer is named once, by its name (the CLI's "layer 0 path 0 point" is not repeated).
    const QString text = r.problems.front().text;
    EXPECT_EQ(text.count(QStringLiteral("Dial")), 1) << lang << ": " << text.toStdString();
    EXPECT_FALSE(text.contains(QRegularExpression(QStringLiteral("\\w+ 0 \\w+ 0 \\w+ \\d+"))))
        << lang << ": " << text.toStdString();
  }
}

// The texts a user reads in the main window: actions, menus, dock titles, labels, group boxes,
// buttons, in a fixed order (children order of one construction).
QStringList visibleTexts(const QWidget& window) {
  QStringList out;
  for (const QAction* a : window.findChildren<QAction*>()) out << a->text();
  for (const QMenu* m : window.findChildren<QMenu*>()) out << m->title();
  for (const QDockWidget* d : window.findChildren<QDockWidget*>()) out << d->windowTitle();
  for (const QLabel* l : window.findChildren<QLabel*>()) out << l->text();
  for (const QGroupBox* g : window.findChildren<QGroupBox*>()) out << g->title();
  for (const QAbstractButton* b : window.findChildren<QAbstractButton*>()) out << b->text();
  return out;
}

// Translations identical to their source in the .ts ("Status", "Alarm", "F5"): legitimately
// the same in that language.
std::set<QString> sameAsEnglish(const QString& tsPath) {
  QFile ts(tsPath);
  std::set<QString> same;
  if (!ts.open(QIODevice::ReadOnly)) return same;
  QXmlStreamReader xml(&ts);
  QString source;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == QLatin1String("source")) source = xml.readElementText();
    if (xml.name() == QLatin1String("translation") &&
        xml.readElementText(QXmlStreamReader::IncludeChildElements) == source)
      same.insert(source);
  }
  return same;
}

// The main window built under each translator (German, French, Spanish) shows no text it shows
// in English, except words that are the same in both languages, texts without letters (numbers,
// units) and file names.
// The motion check's refusals (drivers, English in the CLI) are shown in the user's language in
// the studio, numbers with the decimal comma, the CLI's advice in the studio's words.
TEST(Translations, MotionCheckRefusalIsShownInGerman) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  const QLocale before;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  fivebar::motion::BoardPose pose;
  pose.workDeg = {10.0, 10.0, 0.0};
  pose.wco = {-50.0, -30.0, 0.0};
  pose.softTravelDeg = std::array<double, 2>{100.0, 80.0};
  const fivebar::motion::LinesCheck board = fivebar::motion::checkBoardLines({"G0X50.5Y10"}, pose);
  const fivebar::motion::LineCheck g92 = fivebar::motion::interpretLine("G92X0Y0", pose);
  const QString soft = fivebar::session::MachineSession::studioText(board.reason);
  const QString coords = fivebar::session::MachineSession::studioText(g92.reason);
  QLocale::setDefault(before);
  QCoreApplication::removeTranslator(&translator);
  EXPECT_TRUE(soft.contains(QStringLiteral("Maschinenkoordinaten"))) << soft.toStdString();
  EXPECT_TRUE(soft.contains(QStringLiteral("0,500"))) << soft.toStdString();
  EXPECT_TRUE(soft.contains(QStringLiteral("ALARM:2"))) << soft.toStdString();
  EXPECT_FALSE(coords.contains(QStringLiteral("fivebar reference"))) << coords.toStdString();
  EXPECT_TRUE(coords.contains(QStringLiteral("G10/G92"))) << coords.toStdString();
  EXPECT_NE(coords.toStdString(), g92.reason.text());
}

TEST(Translations, MainWindowShowsNoEnglish) {
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  QStringList english;
  {
    fivebar::studio::MainWindow window(*profile);
    english = visibleTexts(window);
  }
  for (const QString& lang : {QStringLiteral("de"), QStringLiteral("fr"), QStringLiteral("es")}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_%1.qm").arg(lang)));
    QCoreApplication::installTranslator(&translator);
    QStringList translated;
    {
      fivebar::studio::MainWindow window(*profile);
      translated = visibleTexts(window);
    }
    QCoreApplication::removeTranslator(&translator);
    ASSERT_EQ(english.size(), translated.size());
    const std::set<QString> same =
        sameAsEnglish(QStringLiteral(FIVEBAR_TS_DIR "/fivebar_%1.ts").arg(lang));
    const QRegularExpression words(QStringLiteral("[A-Za-z]{3,}"));
    // Data, not UI text: file names (the recent-files menu).
    const QRegularExpression fileName(QStringLiteral("\\.[a-z]{2,7}$"));  // .svg, .fivebar
    // View > Language lists each language in its own name, the same in every translation.
    const std::set<QString> languageNames = {QStringLiteral("Deutsch"), QStringLiteral("English"),
                                             QStringLiteral("Español"), QStringLiteral("Français")};
    QStringList untranslated;
    for (qsizetype i = 0; i < english.size(); ++i)
      if (english[i] == translated[i] && english[i].contains(words) && !same.count(english[i]) &&
          !english[i].contains(fileName) && !languageNames.count(english[i]))
        untranslated << english[i];
    EXPECT_GT(english.size(), 40);
    EXPECT_TRUE(untranslated.isEmpty())
        << lang.toStdString() << ": " << untranslated.join(QStringLiteral(" | ")).toStdString();
  }
}

TEST(Translations, GermanIsComplete) {
  QFile ts(QStringLiteral(FIVEBAR_TS_DE));
  ASSERT_TRUE(ts.open(QIODevice::ReadOnly)) << FIVEBAR_TS_DE;
  QXmlStreamReader xml(&ts);
  int messages = 0;
  QStringList untranslated;
  QString context, source;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == QLatin1String("name")) context = xml.readElementText();
    if (xml.name() == QLatin1String("source")) source = xml.readElementText();
    if (xml.name() == QLatin1String("translation")) {
      ++messages;
      // "unfinished": not translated yet; "vanished"/"obsolete": no longer in the sources (a
      // renamed context or string that the current source no longer finds).
      const bool unfinished = !xml.attributes().value(QLatin1String("type")).isEmpty();
      // Plural messages hold <numerusform> children; readElementText would fail on them.
      const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
      if (unfinished || text.trimmed().isEmpty()) untranslated << context + QStringLiteral(": ") + source;
    }
  }
  ASSERT_FALSE(xml.hasError()) << xml.errorString().toStdString();
  EXPECT_GT(messages, 100);
  EXPECT_TRUE(untranslated.isEmpty()) << untranslated.join(QLatin1Char('\n')).toStdString();
}

TEST(Translations, EmbeddedGermanIsFoundByQualifiedContexts) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  EXPECT_EQ(translator.translate("fivebar::widgets::ModePanel", "Working mode"),
            QStringLiteral("Arbeitsmodus"));
  EXPECT_EQ(translator.translate("fivebar::studio::MainWindow", "&File"), QStringLiteral("&Datei"));
  EXPECT_EQ(translator.translate("DocumentCommands", "Move drawing"),
            QStringLiteral("Zeichnung verschieben"));
  // Plural forms (QCoreApplication::translate substitutes %n afterwards).
  EXPECT_EQ(translator.translate("fivebar::widgets::LayersPanel", "%n path(s)", nullptr, 3),
            QStringLiteral("%n Pfade"));
  EXPECT_EQ(translator.translate("fivebar::widgets::LayersPanel", "%n path(s)", nullptr, 1),
            QStringLiteral("%n Pfad"));
}

}  // namespace
