// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/calibration_wizard.hpp"

#include <QAction>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <cmath>
#include <QLocale>
#include <QSaveFile>

#include "core/output/gcode.hpp"
#include "widgets/calibration/sheet_layer.hpp"
#include "widgets/calibration/simulated_machine.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "i18n/translated.hpp"
#include "widgets/canvas/canvas_view.hpp"
#include "session/fixed_job_inputs.hpp"
#include "session/machine_session.hpp"
#include "session/run_controller.hpp"
#include <QStandardPaths>

namespace fivebar::widgets::calibration {

QLabel* explanation(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  label->setTextFormat(Qt::RichText);
  return label;
}

std::optional<double> typedNumber(QString text) {
  text = text.trimmed().replace(QLatin1Char(','), QLatin1Char('.'));
  bool ok = false;
  const double v = QLocale::c().toDouble(text, &ok);
  if (!ok || !std::isfinite(v)) return std::nullopt;
  return v;
}

CalibrationWizard::CalibrationWizard(StudioDocument& doc, session::MachineSession* session,
                                     SimulatedTruth* simulatedTruth, QWidget* parent)
    : QWizard(parent), doc_(doc), session_(session), simTruth_(session ? simulatedTruth : nullptr) {
  setObjectName(QStringLiteral("calibrationWizard"));
  setWindowTitle(tr("Calibrate the machine"));
  setWizardStyle(QWizard::ClassicStyle);
  setOption(QWizard::NoBackButtonOnStartPage);
  nominal = doc.profile();
  builtFrom = nominal.geometry;
  if (simTruth_) builtFrom = simTruth_->builtFrom();
  patternPage_ = new PatternPage(*this);
  drawPage_ = new DrawPage(*this);
  measurePage_ = new MeasurePage(*this);
  fitPage_ = new FitPage(*this);
  applyPage_ = new ApplyPage(*this);
  verifyPage_ = new VerifyPage(*this);
  accuracyPage_ = new AccuracyPage(*this);
  setPage(kPatternPage, patternPage_);
  setPage(kDrawPage, drawPage_);
  setPage(kMeasurePage, measurePage_);
  setPage(kFitPage, fitPage_);
  setPage(kApplyPage, applyPage_);
  setPage(kVerifyPage, verifyPage_);
  setPage(kAccuracyPage, accuracyPage_);
  resize(980, 720);
  // No hidden imperfect machine after the wizard: the studio's saved setting comes back, unless
  // the maker ticked "keep" (then the wizard's machine becomes the saved setting).
  connect(this, &QDialog::finished, this, [this] {
    if (!simTruth_) return;
    if (drawPage_->keepChoice()->isChecked() && simulated) simTruth_->setTruth(truth, true);
    else simTruth_->setTruth(simTruth_->saved(), false);
  });
}

CalibrationWizard::~CalibrationWizard() = default;

QAction* CalibrationWizard::createAction(StudioDocument& doc, session::MachineSession* session,
                                         SimulatedTruth* truth, CanvasView* canvas, QWidget* parent,
                                         QPointer<CalibrationWizard>& wizard) {
  auto* action = new QAction(tr("&Calibrate..."), parent);
  action->setObjectName(QStringLiteral("calibrateAction"));
  action->setStatusTip(tr("Measure a drawn pattern and correct the profile's link lengths and motor zeros"));
  QObject::connect(action, &QAction::triggered, parent, [&doc, session, truth, canvas, parent, &wizard] {
    if (!wizard) {
      wizard = new CalibrationWizard(doc, session, truth, parent);
      wizard->attachCanvas(canvas);
    }
    wizard->show();
    wizard->raise();
  });
  return action;
}

void CalibrationWizard::attachCanvas(CanvasView* canvas) {
  if (!canvas || sheetLayer_) return;
  // The layer lives as long as the wizard, which lives as long as the window (created after the
  // canvas, so deleted after it).
  sheetLayer_ = new SheetLayer(this);
  canvas->addLayer(sheetLayer_);
  connect(sheetLayer_, &SheetLayer::changed, canvas, [canvas] { canvas->update(); });
  connect(this, &QDialog::finished, sheetLayer_, &SheetLayer::clear);
}

void CalibrationWizard::showOnCanvas(std::vector<std::vector<Vec2>> plan,
                                     std::vector<std::vector<Vec2>> trace) {
  if (sheetLayer_) sheetLayer_->setSheet(std::move(plan), std::move(trace));
}

bool CalibrationWizard::planPattern(const MachineProfile& profile, QString* error) {
  if (!pattern) {
    if (error) *error = tr("Choose a pattern first.");
    return false;
  }
  PlanResult plan = planCalibrationPattern(*pattern, profile);
  if (!plan.ok()) {
    if (error) *error = tr("The pattern cannot be planned: %1").arg(translated(plan.message));
    return false;
  }
  job = std::move(plan.job);
  try {
    gcode = writeGcode(job, profile);
  } catch (const std::exception& e) {
    if (error) *error = tr("The pattern's G-code cannot be written: %1").arg(QString::fromUtf8(e.what()));
    return false;
  }
  return true;
}

bool CalibrationWizard::runPattern(const PlannedJob& job, const MachineProfile& profile, const QString& name,
                                   std::function<void(bool, const QString&)> done, QString* error) {
  if (!session_) {
    *error = tr("Connect a machine (or the simulated machine) in the Machine panel first, and let "
                "any running job finish.");
    return false;
  }
  if (!patternRun_) {
    patternInputs_ = new session::FixedJobInputs(this);
    patternRun_ = new session::RunController(*patternInputs_, *session_, this);
    patternRun_->setJobDirectory(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                                     .filePath(QStringLiteral("calibration")));
  }
  if (patternRun_->running()) {
    *error = tr("The pattern is already being drawn.");
    return false;
  }
  patternInputs_->set(profile, name + QStringLiteral(".svg"), job);
  QString why;
  if (!patternRun_->start(&why)) {
    *error = why;
    return false;
  }
  connect(patternRun_, &session::RunController::finished, this, std::move(done), Qt::SingleShotConnection);
  return true;
}

}  // namespace fivebar::widgets::calibration
