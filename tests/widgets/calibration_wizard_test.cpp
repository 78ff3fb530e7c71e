// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration wizard (widgets/calibration) walked through offscreen on the in-process
// simulated machine: a true machine off by known amounts, the pattern streamed, the table filled
// from the simulated sheet, the fit reducing the error, apply changing the profile and undo
// restoring it, and bad table input named.
#include <gtest/gtest.h>

#include "session/run_controller.hpp"

#include <algorithm>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>

#include "core/kinematics/units.hpp"
#include "machine_test_support.hpp"
#include "test_support.hpp"
#include "tests/scan/synthetic_scan.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/run_progress_box.hpp"
#include "widgets/calibration/simulated_machine.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace fivebar {
namespace {

using test::waitUntil;
using widgets::calibration::CalibrationWizard;

constexpr int kX = 4, kY = 5;  // the measure table's x, y columns

struct WizardRig : test::MachineRig {
  WizardRig() : wizard(doc, &session, &truth) { wizard.show(); }
  widgets::calibration::SimulatedTruth truth{doc, session};  // as MainWindow makes it
  CalibrationWizard wizard;
};

TEST(CalibrationWizard, WalksThroughOnTheSimulatedMachineAndTheFitReducesTheError) {
  WizardRig rig;
  CalibrationWizard& w = rig.wizard;
  const MachineProfile before = rig.doc.profile();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kPatternPage);
  ASSERT_TRUE(w.pattern.has_value());
  ASSERT_GE(w.pattern->marks.size(), 25u);

  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kDrawPage);
  ASSERT_FALSE(w.gcode.empty());
  // A true machine off by known amounts (the defaults of the form: links up to 0.5 mm, zeros by
  // 1 and -0.8 deg, some backlash).
  auto* draw = w.drawPage();
  EXPECT_TRUE(draw->simulateChoice()->isChecked());
  EXPECT_NEAR(w.truth.da2Mm, 0.5, 1e-12);
  EXPECT_NEAR(w.truth.zeroOffsetRad1, radFromDeg(1.0), 1e-12);

  // Draw the pattern on the simulated machine through the checked stream.
  ASSERT_TRUE(rig.connect(400.0));
  ASSERT_TRUE(rig.waitIdle());
  w.restart();
  w.next();
  ASSERT_TRUE(draw->sendButton()->isEnabled());
  draw->sendButton()->click();
  ASSERT_TRUE(waitUntil([&] { return rig.session.jobActive(); }, 5000)) << draw->status()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return !rig.session.jobActive(); }, 90000));
  EXPECT_TRUE(draw->status()->text().contains(QStringLiteral("drawn"))) << draw->status()->text().toStdString();
  // The pattern ran through a RunController, as a job does: every line acknowledged.
  ASSERT_NE(w.patternRun(), nullptr);
  EXPECT_EQ(w.patternRun()->state(), stream::RunState::Finished);
  EXPECT_EQ(w.patternRun()->snapshot().linesCompleted, w.patternRun()->snapshot().totalLines);
  EXPECT_GT(w.patternRun()->snapshot().totalLines, 100u);

  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  auto* measure = w.measurePage();
  measure->fillFromSimulatedSheet();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kFitPage) << measure->problem()->text().toStdString();
  ASSERT_TRUE(w.fit.has_value());
  ASSERT_TRUE(w.fit->ok()) << w.fit->reason;
  EXPECT_GT(w.fit->beforeRmsMm, 0.5);
  EXPECT_LT(w.fit->afterRmsMm, 0.1);
  EXPECT_LT(w.fit->heldOutRmsMm, 0.15);
  EXPECT_GT(w.fitPage()->parameters()->rowCount(), 5);
  ASSERT_TRUE(w.calibrated.has_value());
  EXPECT_NEAR(w.calibrated->geometry.a2, before.geometry.a2 + 0.5, 0.15);
  EXPECT_NEAR(degFromRad(w.calibrated->calibration->zeroOffsetRad1), 1.0, 0.2);
  EXPECT_NEAR(degFromRad(w.calibrated->calibration->backlashRad1), 0.3, 0.15);

  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kApplyPage);
  w.applyPage()->apply();
  EXPECT_EQ(rig.doc.profile().geometry.a2, w.calibrated->geometry.a2);
  ASSERT_TRUE(rig.doc.profile().calibration.has_value());

  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kVerifyPage);
  EXPECT_GT(w.verifyPage()->before().rmsMm, 0.5);
  EXPECT_LT(w.verifyPage()->now().rmsMm, 0.1);
  EXPECT_LT(w.verifyPage()->now().rmsMm, w.verifyPage()->before().rmsMm / 5.0);

  rig.doc.undoStack()->undo();
  EXPECT_EQ(rig.doc.profile().geometry, before.geometry);
  EXPECT_FALSE(rig.doc.profile().calibration.has_value());
}

// The drawing step shows the pattern's run as the Run panel shows a job: a progress bar with
// "line N of M", the time left, and Stop, which stops the run cleanly.
TEST(CalibrationWizard, DrawingStepShowsProgressTimeLeftAndStop) {
  WizardRig rig;
  CalibrationWizard& w = rig.wizard;
  ASSERT_TRUE(rig.connect(1.0));  // real time: the pattern takes minutes
  ASSERT_TRUE(rig.waitIdle());
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kDrawPage);
  auto* draw = w.drawPage();
  widgets::calibration::RunProgressBox* progress = draw->progress();
  ASSERT_NE(progress, nullptr);
  EXPECT_FALSE(progress->isVisibleTo(draw)) << "nothing to show before the pattern is sent";
  draw->sendButton()->click();
  ASSERT_TRUE(waitUntil([&] { return w.patternRun() && w.patternRun()->snapshot().linesCompleted > 5; }, 20000))
      << draw->status()->text().toStdString();
  ASSERT_TRUE(waitUntil([&] { return progress->bar()->value() > 0; }, 5000));
  EXPECT_TRUE(progress->isVisibleTo(draw));
  EXPECT_TRUE(progress->bar()->text().contains(QStringLiteral("line "))) << progress->bar()->text().toStdString();
  EXPECT_TRUE(progress->timeLeft()->text().endsWith(QStringLiteral(" left"))) << progress->timeLeft()->text().toStdString();
  ASSERT_TRUE(progress->stopButton()->isEnabled());
  progress->stopButton()->click();
  ASSERT_TRUE(waitUntil([&] { return !w.patternRun()->running(); }, 20000));
  EXPECT_EQ(w.patternRun()->state(), stream::RunState::Stopped);
  EXPECT_FALSE(progress->stopButton()->isEnabled());
  EXPECT_TRUE(progress->timeLeft()->text().isEmpty());
  EXPECT_TRUE(draw->sendButton()->isEnabled()) << "the pattern can be drawn again";
}

TEST(CalibrationWizard, NamesBadTableInput) {
  WizardRig rig;
  CalibrationWizard& w = rig.wizard;
  w.next();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  auto* measure = w.measurePage();
  QTableWidget* table = measure->table();
  measure->fillFromSimulatedSheet();
  const QString id = table->item(2, 0)->text();
  table->item(2, kX)->setText(QStringLiteral("12.3x"));
  w.next();
  EXPECT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  EXPECT_TRUE(measure->problem()->text().contains(QStringLiteral("Mark %1, x: '12.3x'").arg(id)))
      << measure->problem()->text().toStdString();

  table->item(2, kX)->setText(QStringLiteral("12,5"));  // a decimal comma is fine
  table->item(4, kY)->setText(QString());
  w.next();
  EXPECT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  EXPECT_TRUE(measure->problem()->text().contains(
      QStringLiteral("Mark %1: y is empty").arg(table->item(4, 0)->text())))
      << measure->problem()->text().toStdString();

  // Too few marks measured: said so, and how many are needed.
  for (int r = 0; r < table->rowCount(); ++r) table->item(r, kX)->setText(QString()), table->item(r, kY)->setText(QString());
  w.next();
  EXPECT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  EXPECT_TRUE(measure->problem()->text().contains(QStringLiteral("Only 0 marks")))
      << measure->problem()->text().toStdString();
}

TEST(CalibrationWizard, AMisMeasuredMarkIsNamedAsAnOutlier) {
  WizardRig rig;
  CalibrationWizard& w = rig.wizard;
  w.next();
  w.next();
  auto* measure = w.measurePage();
  measure->fillFromSimulatedSheet();
  QTableWidget* table = measure->table();
  // The first grid mark read 3 mm off.
  int row = 0;
  while (w.pattern->marks[row].kind != MarkKind::Grid) ++row;
  table->item(row, kX)->setText(QString::number(table->item(row, kX)->text().toDouble() + 3.0, 'f', 2));
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kFitPage);
  ASSERT_TRUE(w.fit && w.fit->ok()) << (w.fit ? w.fit->reason.text() : std::string());
  const std::string id = std::to_string(w.pattern->marks[row].id);
  ASSERT_EQ(w.fit->outlierIds.size(), 1u);
  EXPECT_EQ(w.fit->outlierIds.front(), id);
  EXPECT_TRUE(w.fitPage()->summary()->text().contains(QStringLiteral("mark %1").arg(QString::fromStdString(id))));
}

TEST(CalibrationWizard, FillsTheTableFromAScanOfTheSheet) {
  WizardRig rig;
  CalibrationWizard& w = rig.wizard;
  w.next();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kMeasurePage);
  // The sheet the true machine drew, scanned at 300 dpi, a little turned, blurred and noisy.
  test::SheetOptions o;
  o.dpi = 300.0;
  o.rotationDeg = 4.0;
  o.blurSigmaPx = 0.8;
  o.noiseSigma = 6.0;
  o.seed = test::seed();
  for (const PatternMark& m : w.pattern->marks) {
    const auto c = widgets::calibration::trueMarkCentre(m, w.nominal, w.truth);
    ASSERT_TRUE(c.has_value());
    o.displacementMm[m.id] = *c - m.nominalMm;
  }
  // renderSheet moves the strokes between one dot and the next with the later mark: hand it the
  // marks in drawing (tour) order.
  CalibrationPattern tour = *w.pattern;
  std::vector<std::size_t> order(tour.marks.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return tour.dotStroke[a] < tour.dotStroke[b]; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    tour.marks[i] = w.pattern->marks[order[i]];
    tour.dotStroke[i] = w.pattern->dotStroke[order[i]];
  }
  const test::Sheet sheet = test::renderSheet(tour, o);
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("scan.png"));
  ASSERT_TRUE(sheet.image.save(path));
  QString message;
  ASSERT_TRUE(w.measurePage()->importScan(path, 300.0, &message)) << message.toStdString();
  EXPECT_TRUE(message.contains(QStringLiteral("Found %1 of %1").arg(w.pattern->marks.size())))
      << message.toStdString();
  w.next();
  ASSERT_EQ(w.currentId(), CalibrationWizard::kFitPage);
  ASSERT_TRUE(w.fit && w.fit->ok()) << (w.fit ? w.fit->reason.text() : std::string());
  EXPECT_GT(w.fit->beforeRmsMm, 0.5);
  EXPECT_LT(w.fit->afterRmsMm, 0.1);

  // A wrong file is named.
  EXPECT_FALSE(w.measurePage()->importScan(dir.filePath(QStringLiteral("none.png")), 300.0, &message));
  EXPECT_TRUE(message.contains(QStringLiteral("none.png"))) << message.toStdString();
}

}  // namespace
}  // namespace fivebar
