// The German translation is complete (every message translated) and is what tr() finds at run
// time from the embedded .qm (the contexts must be the qualified class names).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QRegularExpression>
#include <QTranslator>
#include <QXmlStreamReader>
#include <set>

#include "app/studio/language_menu.hpp"
#include "widgets/calibration/distances_box.hpp"
#include "widgets/calibration/sheet_layer.hpp"
#include "widgets/calibration/sim_trace_layer.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "app/studio/main_window.hpp"
#include "core/machine/profile.hpp"
#include "widgets/machine/console_panel.hpp"
#include "widgets/panels/fill_options_box.hpp"
#include "widgets/design/design_dialog.hpp"
#include "widgets/design/pareto_plot.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/panels/import_warnings_panel.hpp"
#include "widgets/machine/jog_controller.hpp"
#include "widgets/machine/jog_goto_tool.hpp"
#include "widgets/machine/jog_panel.hpp"
#include "widgets/panels/layers_panel.hpp"
#include "widgets/machine/machine_banner.hpp"
#include "widgets/machine/machine_panel.hpp"
#include "widgets/machine/machine_session.hpp"
#include "widgets/machine/machine_settings_dialog.hpp"
#include "widgets/machine/machine_ui.hpp"
#include "widgets/panels/mode_panel.hpp"
#include "widgets/panels/placement_panel.hpp"
#include "widgets/panels/preview_panel.hpp"
#include "widgets/panels/profile_editor.hpp"
#include "app/studio/file_actions.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/machine/run_controller.hpp"
#include "widgets/machine/run_panel.hpp"
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
        &ImportController::staticMetaObject, &JogController::staticMetaObject,
        &GoToTool::staticMetaObject, &JogPanel::staticMetaObject, &LayersPanel::staticMetaObject,
        &MachineBanner::staticMetaObject, &MachinePanel::staticMetaObject,
        &MachineSession::staticMetaObject, &MachineSettingsDialog::staticMetaObject,
        &MachineUi::staticMetaObject,
        &ModePanel::staticMetaObject, &PlacementPanel::staticMetaObject,
        &PreviewPanel::staticMetaObject, &SpeedLegend::staticMetaObject,
        &ProfileEditor::staticMetaObject, &RunController::staticMetaObject,
        &RunPanel::staticMetaObject, &SimulationPanel::staticMetaObject,
        &StudioDocument::staticMetaObject, &FillOptionsBox::staticMetaObject,
        &ImportWarningsPanel::staticMetaObject, &DesignDialog::staticMetaObject,
        &ParetoPlot::staticMetaObject, &fivebar::studio::LanguageMenu::staticMetaObject,
        &calibration::CalibrationWizard::staticMetaObject,
        &calibration::PatternPage::staticMetaObject, &calibration::DrawPage::staticMetaObject,
        &calibration::MeasurePage::staticMetaObject, &calibration::FitPage::staticMetaObject,
        &calibration::ApplyPage::staticMetaObject, &calibration::VerifyPage::staticMetaObject,
        &calibration::PatternSender::staticMetaObject, &calibration::CalibrationPreview::staticMetaObject,
        &calibration::SheetLayer::staticMetaObject, &calibration::AccuracyPage::staticMetaObject,
        &calibration::DistancesBox::staticMetaObject, &calibration::SimTraceLayer::staticMetaObject,
        &calibration::SimulatedMachineDialog::staticMetaObject, &calibration::SimulatedTruth::staticMetaObject,
        &calibration::SimulatedTruthBadge::staticMetaObject, &calibration::TrueMachineForm::staticMetaObject})
    names.insert(QString::fromLatin1(m->className()));
  for (const char* c : {"QObject", "main", "DocumentCommands", "JobPipeline", "MapPainter",
                        "WorkspaceLegend", "ImportWarningsPanel", "DesignPainter", "ImportWarning",
                        "fivebar::widgets::MachineDialogs", "fivebar::widgets::SettingsAdvice",
                        "CalibrationWizard"})
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
  EXPECT_EQ(MachineUi::tr("Jog"), QStringLiteral("Verfahren"));
  EXPECT_EQ(calibration::MeasurePage::tr("3. Measure the marks"), QStringLiteral("3. Die Marken vermessen"));
  EXPECT_EQ(LayersPanel::tr("%n path(s)", nullptr, 2), QStringLiteral("2 Pfade"));
  EXPECT_EQ(QCoreApplication::translate("WorkspaceLegend", "reach boundary"),
            QStringLiteral("Reichweitengrenze"));
  QCoreApplication::removeTranslator(&translator);
}

// The importer's warnings (core, English) reach the warnings panel in German: the message
// translated, the line, element and counts kept; an unknown message stays as it is.
TEST(Translations, ImportWarningsAreShownInGerman) {
  QTranslator translator;
  ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/fivebar_de.qm")));
  ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
  using fivebar::widgets::translatedImportWarning;
  EXPECT_EQ(translatedImportWarning(QStringLiteral(
                "line 9: <path id=\"wave\"> attribute d: invalid path data at character 53 (\"x\"): drawn up to the error")),
            QStringLiteral("Zeile 9: <path id=\"wave\"> Attribut d: ungültige Pfaddaten bei Zeichen 53 (\"x\"): "
                           "bis zum Fehler gezeichnet"));
  EXPECT_EQ(translatedImportWarning(QStringLiteral("<image> element removed (2x, first at line 3)")),
            QStringLiteral("Element <image> entfernt (2x, zuerst in Zeile 3)"));
  EXPECT_EQ(translatedImportWarning(QStringLiteral("clip-path not applied: clipped shapes are drawn whole")),
            QStringLiteral("clip-path nicht angewandt: beschnittene Formen werden ganz gezeichnet"));
  EXPECT_EQ(translatedImportWarning(QStringLiteral("something new")), QStringLiteral("something new"));
  // The panel shows them so.
  fivebar::widgets::ImportWarningsPanel panel;
  panel.showWarnings(QStringLiteral("a.svg"), {QStringLiteral("CSS @import removed (1x, first at line 2)")});
  ASSERT_EQ(panel.list()->count(), 1);
  EXPECT_EQ(panel.list()->item(0)->text(), QStringLiteral("CSS-@import entfernt (1x, zuerst in Zeile 2)"));
  QCoreApplication::removeTranslator(&translator);
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
TEST(Translations, MainWindowShowsNoEnglish) {
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  QStringList english;
  {
    fivebar::studio::MainWindow window(*profile);
    english = visibleTexts(window);
  }
  for (const QString lang : {QStringLiteral("de"), QStringLiteral("fr"), QStringLiteral("es")}) {
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
