// SPDX-License-Identifier: GPL-3.0-or-later
// The machine profile editor: inline validation messages from core validate(), live updates of
// the document (undoable), presets, and JSON export / import.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFile>
#include <QLabel>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"
#include "machine_test_support.hpp"
#include "widgets/panels/profile_editor.hpp"

namespace fivebar {
namespace {

// The message validate() gives for this profile's field, as the editor must show it.
QString expectedMessage(const MachineProfile& p, const std::string& field) {
  for (const ValidationIssue& issue : validate(p))
    if (issue.field == field) return QString::fromStdString(issue.message.text());
  return {};
}

TEST(ProfileEditor, BadValueShowsTheValidationMessageNextToTheField) {
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  QDoubleSpinBox* a1 = editor.numberField("geometry.a1");
  ASSERT_NE(a1, nullptr);
  QLabel* message = editor.messageFor("geometry.a1");
  ASSERT_NE(message, nullptr);
  EXPECT_TRUE(message->isHidden());
  const double before = doc.profile().geometry.a1;
  a1->setValue(0.0);
  EXPECT_FALSE(message->isHidden());
  MachineProfile bad = doc.profile();
  bad.geometry.a1 = 0.0;
  const QString expected = expectedMessage(bad, "geometry.a1");
  ASSERT_FALSE(expected.isEmpty());
  EXPECT_TRUE(message->text().contains(expected)) << message->text().toStdString();
  EXPECT_FALSE(editor.valid());
  // The invalid value never reaches the document.
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, before);
  // Fixing it hides the message and applies the profile.
  a1->setValue(before + 5.0);
  EXPECT_TRUE(message->isHidden());
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, before + 5.0);
}

// The rows come from core's one table of profile fields: every field but the calibration ones
// (written by the calibration tools) has its spin box with the table's range, decimals, value
// and (translated) label and unit.
TEST(ProfileEditor, RowsAreBuiltFromTheProfileFieldTable) {
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  int rows = 0;
  for (const ProfileField& f : profileFields()) {
    QDoubleSpinBox* box = editor.numberField(f.path);
    if (sectionOf(f) == "calibration") {
      EXPECT_EQ(box, nullptr) << f.path;
      continue;
    }
    ASSERT_NE(box, nullptr) << f.path;
    ++rows;
    EXPECT_EQ(box->minimum(), f.inputMin) << f.path;
    EXPECT_EQ(box->maximum(), f.inputMax) << f.path;
    EXPECT_EQ(box->decimals(), f.decimals) << f.path;
    EXPECT_EQ(box->suffix(), widgets::profileUnitSuffix(f)) << f.path;
    if (std::string(f.path).rfind("limits.", 0) != 0) {  // shown at +-180 while unlimited
      EXPECT_NEAR(box->value(), f.get(doc.profile()), 0.5 * std::pow(10.0, -f.decimals)) << f.path;
    }
    // The label in the form row is the table's label in the UI language.
    auto* form = qobject_cast<QFormLayout*>(box->parentWidget()->layout());
    ASSERT_NE(form, nullptr) << f.path;
    auto* label = qobject_cast<QLabel*>(form->labelForField(box));
    ASSERT_NE(label, nullptr) << f.path;
    EXPECT_EQ(label->text(), widgets::profileFieldLabel(f)) << f.path;
    EXPECT_FALSE(label->text().isEmpty()) << f.path;
  }
  EXPECT_GE(rows, 31);
  // Units a maker reads: degrees as a sign, rates per minute.
  EXPECT_EQ(editor.numberField("motors.maxSpeedDegPerMin1")->suffix(), QStringLiteral(" °/min"));
  EXPECT_EQ(editor.numberField("geometry.a1")->suffix(), QStringLiteral(" mm"));
}

TEST(ProfileEditor, ValidEditsUpdateTheDocumentAndUndoRestoresTheField) {
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  int changes = 0;
  QObject::connect(&doc, &widgets::StudioDocument::profileChanged, [&] { ++changes; });
  const double w = doc.profile().geometry.w;
  editor.numberField("geometry.w")->setValue(w + 10.0);
  EXPECT_EQ(changes, 1);
  EXPECT_DOUBLE_EQ(doc.profile().geometry.w, w + 10.0);
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.profile().geometry.w, w);
  EXPECT_DOUBLE_EQ(editor.numberField("geometry.w")->value(), w);
}

TEST(ProfileEditor, CrossFieldProblemIsShownAtTheLimitField) {
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  QDoubleSpinBox* lo = editor.numberField("limits.theta1MinDeg");
  QDoubleSpinBox* hi = editor.numberField("limits.theta1MaxDeg");
  ASSERT_TRUE(lo->isEnabled());  // the preset has joint limits
  lo->setValue(hi->value() + 10.0);
  QLabel* message = editor.messageFor("limits.theta1MinDeg");
  EXPECT_FALSE(message->isHidden());
  EXPECT_TRUE(message->text().contains(QStringLiteral("must be below"))) << message->text().toStdString();
}

TEST(ProfileEditor, ExportThenImportRoundTripsAndBadFilesAreNamed) {
  QTemporaryDir dir;
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  editor.numberField("geometry.b2")->setValue(185.0);
  const QString path = dir.filePath(QStringLiteral("machine.json"));
  QString error;
  ASSERT_TRUE(editor.exportTo(path, &error)) << error.toStdString();
  const ProfileLoad loaded = loadProfile(path.toStdString());
  ASSERT_TRUE(loaded.profile.has_value());
  EXPECT_DOUBLE_EQ(loaded.profile->geometry.b2, 185.0);

  editor.loadPreset(QStringLiteral("hoang2015"));
  EXPECT_DOUBLE_EQ(doc.profile().geometry.w, preset("hoang2015")->geometry.w);
  ASSERT_TRUE(editor.importFrom(path, &error)) << error.toStdString();
  EXPECT_DOUBLE_EQ(doc.profile().geometry.b2, 185.0);
  EXPECT_DOUBLE_EQ(editor.numberField("geometry.b2")->value(), 185.0);

  const QString broken = dir.filePath(QStringLiteral("broken.json"));
  QFile f(broken);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("{ \"geometry\": ");
  f.close();
  EXPECT_FALSE(editor.importFrom(broken, &error));
  EXPECT_TRUE(error.contains(broken)) << error.toStdString();
}

}  // namespace
}  // namespace fivebar

namespace fivebar {
namespace {

// Typing a number is one change (one undo step), applied when editing finishes, not one per key.
TEST(ProfileEditor, TypedValueIsAppliedWhenEditingFinishesAsOneUndoStep) {
  widgets::StudioDocument doc(test::makerPlotter());
  widgets::ProfileEditor editor(doc);
  editor.show();
  QDoubleSpinBox* a1 = editor.numberField("geometry.a1");
  ASSERT_NE(a1, nullptr);
  const int steps = doc.undoStack()->count();
  a1->setFocus();
  a1->selectAll();
  QTest::keyClicks(a1, QStringLiteral("104.5"));
  EXPECT_EQ(doc.undoStack()->count(), steps);  // nothing applied while typing
  QTest::keyClick(a1, Qt::Key_Return);
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, 104.5);
  doc.undoStack()->undo();
  EXPECT_DOUBLE_EQ(doc.profile().geometry.a1, test::makerPlotter().geometry.a1);
}

}  // namespace
}  // namespace fivebar
