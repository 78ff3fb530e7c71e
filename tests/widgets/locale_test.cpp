// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers in the studio follow the user interface locale (QLocale::setDefault, as the studio's
// start-up does): "12,5 s" in German, French and Spanish, "12.5 s" in English; the spin boxes
// take "12,5" in those languages. The French and Spanish translations are found at run time
// like the German one (translation_test.cpp checks German in depth).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QLocale>
#include <QTranslator>

#include "app/studio/main_window.hpp"
#include "core/machine/profile.hpp"
#include "widgets/panels/mode_panel.hpp"
#include "widgets/panels/preview_panel.hpp"

namespace {

// Sets the default locale for one test and restores the previous one.
struct DefaultLocale {
  QLocale previous;
  explicit DefaultLocale(const QLocale& l) { QLocale::setDefault(l); }
  ~DefaultLocale() { QLocale::setDefault(previous); }
};

TEST(LocaleNumbers, JobTimeUsesTheDecimalCommaOfTheLanguage) {
  for (const char* name : {"de_DE", "fr_FR", "es_ES"}) {
    const DefaultLocale scoped{QLocale(QString::fromLatin1(name))};
    EXPECT_EQ(fivebar::widgets::formatJobTime(12.5), QStringLiteral("12,5 s")) << name;
  }
  const DefaultLocale english{QLocale(QLocale::English, QLocale::UnitedStates)};
  EXPECT_EQ(fivebar::widgets::formatJobTime(12.5), QStringLiteral("12.5 s"));
}

// A placement field typed the German way is read as the number the user meant.
TEST(LocaleNumbers, SpinBoxesAcceptTheDecimalComma) {
  const DefaultLocale scoped{QLocale(QLocale::German, QLocale::Germany)};
  const auto profile = fivebar::preset("maker-plotter");
  ASSERT_TRUE(profile.has_value());
  fivebar::studio::MainWindow window(*profile);
  auto* rotation = window.findChild<QDoubleSpinBox*>(QStringLiteral("placementRotation"));
  ASSERT_NE(rotation, nullptr);
  rotation->setValue(0.0);
  auto* edit = rotation->findChild<QLineEdit*>();  // the spin box's own line edit
  ASSERT_NE(edit, nullptr);
  edit->selectAll();
  edit->insert(QStringLiteral("12,5"));
  rotation->interpretText();
  EXPECT_DOUBLE_EQ(rotation->value(), 12.5);
  EXPECT_TRUE(rotation->text().contains(QStringLiteral("12,5"))) << rotation->text().toStdString();
}

TEST(LocaleNumbers, FrenchAndSpanishAreFoundAtRunTime) {
  struct Sample {
    const char* qm;
    const char* workingMode;
    const char* file;
  };
  for (const Sample& s : {Sample{":/i18n/fivebar_fr.qm", "Mode de travail", "&Fichier"},
                          Sample{":/i18n/fivebar_es.qm", "Modo de trabajo", "&Archivo"}}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QString::fromLatin1(s.qm))) << s.qm;
    ASSERT_TRUE(QCoreApplication::installTranslator(&translator));
    EXPECT_EQ(fivebar::widgets::ModePanel::tr("Working mode"), QString::fromUtf8(s.workingMode));
    EXPECT_EQ(fivebar::studio::MainWindow::tr("&File"), QString::fromUtf8(s.file));
    QCoreApplication::removeTranslator(&translator);
  }
}

}  // namespace
