// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's simulated imperfect machine and the wizard's measuring forms (issue 13), offscreen:
// the simulated-machine setting applies at once to an open simulated machine, is saved where the
// maker sets it and is not left behind by the wizard; the wizard's preview trace is what the
// simulator draws; the distances form calibrates and names bad rows; the accuracy-lines page
// gives the before/after figures and names bad cells.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QRadioButton>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTabWidget>
#include <QTemporaryDir>

#include "core/calibration/pattern.hpp"
#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "tests/scan/synthetic_scan.hpp"
#include "test_support.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/distances_box.hpp"
#include "widgets/calibration/simulated_machine.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace fivebar {
namespace {

using test::waitUntil;
using widgets::calibration::AccuracyPage;
using widgets::calibration::typedNumber;
using widgets::calibration::CalibrationWizard;
using widgets::calibration::SimulatedTruth;
using widgets::calibration::TrueMachine;

// A rig whose simulated-machine setting is saved in a temporary file, not the user's settings.
struct Rig : test::MachineRig {
  Rig() {
    truth().setSettingsFile(dir.filePath(QStringLiteral("settings.ini")));
  }
  SimulatedTruth& truth() { return simulated; }
  SimulatedTruth simulated{doc, session};  // the studio's one setting, as MainWindow makes it
  QTemporaryDir dir;
};

// Sends a short pen-down stroke on the connected simulated machine; returns the drawn trace's
// last point and the motors' reported angles there once they stand still.
bool drawStroke(Rig& rig, Vec2* endMm, JointAngles* motors) {
  const ToolSettings& tool = rig.doc.profile().tool;
  for (const QString& line : {QStringLiteral("M3 S%1").arg(tool.penDownS), QStringLiteral("G91 G1 X4 Y-3 F300"),
                              QStringLiteral("G1 X-2 Y-2"), QStringLiteral("G90")}) {
    QString refusal;
    const bool settled = waitUntil([&] { return rig.session.bytesInFlight() == 0; }, 5000) && rig.waitIdle();
    if (!settled || !rig.session.sendLine(line, &refusal)) {
      ADD_FAILURE() << line.toStdString() << ": " << refusal.toStdString();
      return false;
    }
  }
  std::optional<JointAngles> last;
  QElapsedTimer still;
  still.start();
  if (!waitUntil([&] {
        const auto q = rig.session.motorAngles();
        if (!(q && last && q->theta1 == last->theta1 && q->theta2 == last->theta2)) still.restart();
        last = q;
        return still.elapsed() > 700 && rig.session.bytesInFlight() == 0 &&
               rig.session.state() == grbl::MachineState::Idle;
      }, 10000))
    return false;
  const auto trace = rig.session.simulatedDrawnTrace();
  if (trace.empty() || trace.back().size() < 2 || !last) return false;
  *endMm = trace.back().back();
  *motors = *last;
  return true;
}

TEST(SimulatedMachine, ATrueMachineSetWhileConnectedAppliesAtOnce) {
  Rig rig;
  ASSERT_TRUE(rig.connect(50.0));
  ASSERT_TRUE(rig.waitIdle());
  TrueMachine t;
  t.db1Mm = 0.5;
  rig.truth().setTruth(t, false);  // the machine is open: no reconnect
  ASSERT_TRUE(rig.session.simulatedTrueMachine().has_value());
  EXPECT_NEAR(rig.session.simulatedTrueMachine()->geometry.b1, rig.doc.profile().geometry.b1 + 0.5, 1e-12);
  Vec2 end = Vec2::Zero();
  JointAngles q;
  ASSERT_TRUE(drawStroke(rig, &end, &q));
  Geometry real = rig.doc.profile().geometry;
  real.b1 += 0.5;
  const FkResult truthFk = forward(real, q, rig.doc.profile().assembly);
  const FkResult planFk = forward(rig.doc.profile().geometry, q, rig.doc.profile().assembly);
  ASSERT_TRUE(truthFk.ok() && planFk.ok());
  EXPECT_LT((end - truthFk.p).norm(), 0.05) << "drawn by the true machine set after connecting";
  EXPECT_GT((end - planFk.p).norm(), 0.2) << "not by the profile";
  EXPECT_TRUE(rig.truth().describe().contains(QStringLiteral("b1 0.50 mm"))) << rig.truth().describe().toStdString();
}

TEST(SimulatedMachine, IsSavedWhereItIsSetAndKeptAcrossACalibration) {
  Rig rig;
  TrueMachine t = widgets::calibration::TrueMachineForm::example();
  rig.truth().setTruth(t, true);
  {
    test::MachineRig other;  // the next start of the studio
    SimulatedTruth again(other.doc, other.session);
    again.setSettingsFile(rig.dir.filePath(QStringLiteral("settings.ini")));
    EXPECT_FALSE(again.active());
    again.load();
    EXPECT_TRUE(again.active());
    EXPECT_NEAR(again.truth().da2Mm, 0.5, 1e-9);
    EXPECT_NEAR(again.truth().zeroOffsetRad1, radFromDeg(1.0), 1e-9);
    ASSERT_TRUE(other.session.simulatedTrueMachine().has_value());
    EXPECT_NEAR(other.session.simulatedTrueMachine()->geometry.a2, other.doc.profile().geometry.a2 + 0.5, 1e-9);
  }
  // A calibrated profile (same machine, other lengths): the real machine does not change.
  MachineProfile calibrated = rig.doc.profile();
  const Geometry built = calibrated.geometry;
  calibrated.geometry.a2 += 0.5;
  rig.doc.setProfile(calibrated);
  EXPECT_EQ(rig.truth().builtFrom(), built);
  EXPECT_NEAR(rig.session.simulatedTrueMachine()->geometry.a2, built.a2 + 0.5, 1e-9);
  // Another machine: the amounts apply to its geometry.
  MachineProfile other = *preset("hoang2015");
  rig.doc.setProfile(other);
  EXPECT_EQ(rig.truth().builtFrom(), other.geometry);
  // Perfect again: the simulated machine is the profile.
  rig.truth().makePerfect(true);
  EXPECT_FALSE(rig.session.simulatedTrueMachine().has_value());
}

TEST(SimulatedMachine, TheWizardLeavesNoHiddenImperfectMachineBehind) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kDrawPage);
  // The wizard's example machine is the simulated machine at once ...
  EXPECT_TRUE(rig.truth().active());
  ASSERT_TRUE(rig.session.simulatedTrueMachine().has_value());
  w.drawPage()->trueField(1)->setValue(-0.7);  // b1 shorter
  EXPECT_NEAR(rig.session.simulatedTrueMachine()->geometry.b1, rig.doc.profile().geometry.b1 - 0.7, 1e-9);
  // ... and gone when the wizard closes (nothing was saved).
  w.reject();
  EXPECT_FALSE(rig.truth().active());
  EXPECT_FALSE(rig.session.simulatedTrueMachine().has_value());

  // Kept on purpose: it becomes the saved setting.
  w.restart();
  w.show();
  w.next();
  w.drawPage()->keepChoice()->setChecked(true);
  w.reject();
  EXPECT_TRUE(rig.truth().active());
  EXPECT_TRUE(rig.truth().saved().da2Mm == rig.truth().truth().da2Mm && !rig.truth().saved().perfect());
}

// The wizard's preview of the simulated sheet is what the simulated machine then really draws.
TEST(SimulatedMachine, TheWizardPreviewIsWhatTheSimulatedMachineDraws) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.patternPage()->accuracyChoice()->setChecked(true);  // a short pattern
  ASSERT_TRUE(rig.connect(400.0));
  ASSERT_TRUE(rig.waitIdle());
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kDrawPage);
  const auto predicted = widgets::calibration::simulatedTrace(w.gcode, w.nominal, w.truth);
  ASSERT_EQ(predicted.size(), 10u);
  ASSERT_TRUE(w.drawPage()->sendButton()->isEnabled());
  w.drawPage()->sendButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.jobActive(); }, 5000)) << w.drawPage()->status()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jobActive(); }, 60000));
  const auto drawn = rig.session.simulatedDrawnTrace();
  ASSERT_EQ(drawn.size(), predicted.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    worst = std::max(worst, (drawn[k].front() - predicted[k].front()).norm());
    worst = std::max(worst, (drawn[k].back() - predicted[k].back()).norm());
  }
  // The stream's safe approach to the start leaves the play a little differently taken up than
  // the preview's start at the home pose: within a few hundredths of a millimetre.
  EXPECT_LT(worst, 0.05) << "the preview's line ends against the simulated machine's";
  // The imperfect machine really bends the lines: the preview is not the plan.
  EXPECT_GT((predicted.front().front() - w.pattern->strokes.front().points.front()).norm(), 0.2);
}

TEST(CalibrationDistances, TheRulerFormCalibratesTheSimulatedMachine) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.next();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  auto* m = w.measurePage();
  m->tabs()->setCurrentWidget(m->distances());
  m->distances()->fillFromSimulatedSheet();
  EXPECT_GE(m->distances()->table()->rowCount(), 80);
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kFitPage) << m->distances()->problem()->text().toStdString();
  ASSERT_TRUE(w.useDistances);
  ASSERT_TRUE(w.fit && w.fit->ok()) << (w.fit ? w.fit->reason.text() : std::string());
  EXPECT_LT(w.fit->afterRmsMm, 0.1);
  ASSERT_TRUE(w.calibrated.has_value());
  EXPECT_NEAR(w.calibrated->geometry.a2, w.nominal.geometry.a2 + 0.5, 0.15);
  EXPECT_NEAR(degFromRad(w.calibrated->calibration->zeroOffsetRad1), 1.0, 0.2);
  EXPECT_TRUE(w.fitPage()->summary()->text().contains(QStringLiteral("distances")));
}

TEST(CalibrationDistances, NamesTheBadRow) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.next();
  w.next();
  auto* box = w.measurePage()->distances();
  w.measurePage()->tabs()->setCurrentWidget(box);
  int grid = -1, backlash = -1;
  for (const PatternMark& mk : w.pattern->marks) (mk.kind == MarkKind::Grid ? grid : backlash) = mk.id;
  ASSERT_GT(grid, 0);
  ASSERT_GT(backlash, 0);
  const auto check = [&](const QString& a, const QString& b, const QString& d, const QString& expected) {
    box->setRows({});
    box->table()->setRowCount(2);
    for (int c = 0; c < 3; ++c) box->table()->setItem(0, c, new QTableWidgetItem);  // an empty row is skipped
    box->table()->setItem(1, 0, new QTableWidgetItem(a));
    box->table()->setItem(1, 1, new QTableWidgetItem(b));
    box->table()->setItem(1, 2, new QTableWidgetItem(d));
    w.next();
    EXPECT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
    EXPECT_TRUE(box->problem()->text().contains(expected))
        << box->problem()->text().toStdString() << " / expected " << expected.toStdString();
  };
  const QString g = QString::number(grid);
  check(QStringLiteral("7x"), g, QStringLiteral("50"), QStringLiteral("Row 2, mark A: '7x' is not a number"));
  check(g, QStringLiteral("999"), QStringLiteral("50"), QStringLiteral("Row 2: there is no mark 999"));
  check(g, g, QStringLiteral("50"), QStringLiteral("Row 2: a distance from mark %1 to itself").arg(grid));
  check(g, QString::number(backlash), QStringLiteral("50"),
        QStringLiteral("Row 2: mark %1 is in a backlash row").arg(backlash));
  check(g, QStringLiteral("1"), QString(), QStringLiteral("Row 2: distance is empty"));
  check(g, QStringLiteral("1"), QStringLiteral("12,5"), QStringLiteral("Only 1 distances"));  // a decimal comma is fine

  // A distances file with a bad line is named by file and line.
  const QString path = rig.dir.filePath(QStringLiteral("d.csv"));
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("id_a,id_b,distance_mm\n1,2,30.5\n1,3,abc\n");
  f.close();
  QString error;
  EXPECT_FALSE(box->loadCsv(path, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("d.csv:3"))) << error.toStdString();
}

TEST(CalibrationAccuracy, TypedLinesGiveTheFigureAndBadCellsAreNamed) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.patternPage()->accuracyChoice()->setChecked(true);
  w.next();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kAccuracyPage);
  AccuracyPage* page = w.accuracyPage();
  QTableWidget* t = page->table();
  for (int r = 0; r < 10; ++r) {
    t->item(r, AccuracyPage::kLengthBefore)->setText(QString::number(40.0 + 0.1 * r, 'f', 1));
    t->item(r, AccuracyPage::kStraightBefore)->setText(QStringLiteral("0.2"));
  }
  t->item(3, AccuracyPage::kStraightBefore)->setText(QStringLiteral("0,6"));
  ASSERT_TRUE(page->before().has_value());
  EXPECT_EQ(page->before()->lines, 10);
  EXPECT_NEAR(page->before()->maxAbsLengthErrorMm, 0.9, 1e-9);
  EXPECT_NEAR(page->before()->maxStraightnessMm, 0.6, 1e-9);
  EXPECT_FALSE(page->after().has_value());
  EXPECT_TRUE(page->figures()->text().contains(QStringLiteral("0.60 mm"))) << page->figures()->text().toStdString();
  t->item(5, AccuracyPage::kLengthAfter)->setText(QStringLiteral("forty"));
  EXPECT_TRUE(page->figures()->text().contains(QStringLiteral("Line 6, Length after (mm): 'forty'")))
      << page->figures()->text().toStdString();
}

// Calibrated on the simulated sheet, the accuracy lines come out truer to length and no less straight.
TEST(CalibrationAccuracy, BeforeAndAfterOnTheSimulatedMachine) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.next();
  w.next();
  w.measurePage()->fillFromSimulatedSheet();
  w.next();
  ASSERT_TRUE(w.fit && w.fit->ok());
  w.next();
  w.applyPage()->apply();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kVerifyPage);
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kAccuracyPage);
  w.accuracyPage()->fillFromSimulatedSheet();
  const auto before = w.accuracyPage()->before(), after = w.accuracyPage()->after();
  ASSERT_TRUE(before && after) << w.accuracyPage()->figures()->text().toStdString();
  std::printf("accuracy lines, simulated: length error %.3f -> %.3f mm, straightness %.3f -> %.3f mm\n",
              before->maxAbsLengthErrorMm, after->maxAbsLengthErrorMm, before->maxStraightnessMm,
              after->maxStraightnessMm);
  EXPECT_EQ(before->lines, 10);
  EXPECT_GT(before->maxAbsLengthErrorMm, 0.5);
  // Planned with the calibration applied (zero offsets and backlash compensation): true to 0.1 mm.
  EXPECT_LE(after->maxAbsLengthErrorMm, 0.1);
  EXPECT_LE(after->maxStraightnessMm, 0.1);
}

// A scan of the accuracy lines fills the chosen sheet's columns; a bad scan is named.
TEST(CalibrationAccuracy, AScanOfTheLinesFillsTheChosenColumns) {
  Rig rig;
  CalibrationWizard w(rig.doc, &rig.session, &rig.truth());
  w.show();
  w.patternPage()->accuracyChoice()->setChecked(true);
  w.next();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kAccuracyPage);
  AccuracyPage* page = w.accuracyPage();
  // The lines as drawn: each a little longer than 40 mm (40.0 + 0.1 * i).
  const AccuracyPattern a = accuracyPatternAt(Vec2(0, 150), Vec2(1, 0));
  CalibrationPattern drawn;
  for (std::size_t i = 0; i < a.lines.size(); ++i) {
    const Vec2 u = (a.lines[i].endMm - a.lines[i].startMm).normalized();
    Stroke st;
    st.points = {a.lines[i].startMm, a.lines[i].endMm + 0.1 * static_cast<double>(i) * u};
    drawn.strokes.push_back(st);
  }
  test::SheetOptions o;
  o.dpi = 300;
  o.rotationDeg = 12;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 5;
  o.seed = test::seed();
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("lines.png"));
  ASSERT_TRUE(test::renderSheet(drawn, o).image.save(path));
  QString message;
  ASSERT_TRUE(page->importScan(path, 300.0, true, &message)) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("Found 10 lines"))) << message.toStdString();
  ASSERT_TRUE(page->after().has_value());
  EXPECT_FALSE(page->before().has_value());
  EXPECT_EQ(page->after()->lines, 10);
  EXPECT_NEAR(page->after()->maxAbsLengthErrorMm, 0.9, 0.05);
  EXPECT_LE(page->after()->maxStraightnessMm, 0.03);
  // Lines in the order across the sheet: the lengths run 40.0 ... 40.9 one way or the other.
  const auto length = [&](int r) { return *typedNumber(page->table()->item(r, AccuracyPage::kLengthAfter)->text()); };
  EXPECT_NEAR(std::abs(length(9) - length(0)), 0.9, 0.05);
  EXPECT_FALSE(page->importScan(dir.filePath(QStringLiteral("none.png")), 300.0, false, &message));
  EXPECT_TRUE(message.contains(QStringLiteral("none.png"))) << message.toStdString();
  EXPECT_FALSE(page->importScan(path, 1200.0, false, &message));
  EXPECT_TRUE(message.contains(QStringLiteral("expected 10"))) << message.toStdString();
}

}  // namespace
}  // namespace fivebar
