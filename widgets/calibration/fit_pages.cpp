// SPDX-License-Identifier: GPL-3.0-or-later
// The last steps of the calibration wizard: the fit (core/calibration/fit.hpp) shown with its
// errors, arrows and uncertainties; applying it to the profile; the verification pattern.
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QVBoxLayout>
#include <map>

#include "core/calibration/calibrate.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/output/gcode.hpp"
#include "core/kinematics/units.hpp"
#include "widgets/calibration/run_progress_box.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "i18n/translated.hpp"
#include "session/machine_session.hpp"

namespace fivebar::widgets::calibration {

namespace {

QString mm(double v, int decimals = 2) { return QString::number(v, 'f', decimals); }

// The value of a named machine parameter in a profile (the fit's names), in its file unit.
std::optional<double> nominalValue(const MachineProfile& p, const std::string& name) {
  const Geometry& g = p.geometry;
  const std::map<std::string, double> values{
      {"a1", g.a1}, {"b1", g.b1}, {"a2", g.a2}, {"b2", g.b2}, {"w", g.w},
      {"zeroOffset1", degFromRad(p.calibration ? p.calibration->zeroOffsetRad1 : 0.0)},
      {"zeroOffset2", degFromRad(p.calibration ? p.calibration->zeroOffsetRad2 : 0.0)}};
  const auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
FitPage::FitPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("4. Fit the machine to the marks"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("The fit looks for the link lengths and motor zeros with which the machine would have put "
         "every mark where you measured it. Some marks are kept out of the fit and only used to "
         "check it afterwards (\"held out\"): their error is the honest one. The arrows show each "
         "mark's error, greatly enlarged: grey before, red after.")));
  summary_ = explanation(QString());
  left->addWidget(summary_);
  parameters_ = new QTableWidget(0, 3);
  parameters_->setHorizontalHeaderLabels({tr("Parameter"), tr("Profile"), tr("Fitted \u00b1 std. dev.")});
  parameters_->verticalHeader()->setVisible(false);
  parameters_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  parameters_->horizontalHeader()->setStretchLastSection(true);
  parameters_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  left->addWidget(parameters_, 1);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 3);
}

bool FitPage::isComplete() const { return w_.fit && w_.fit->ok(); }

void FitPage::initializePage() {
  w_.fit.reset();
  w_.calibrated.reset();
  w_.backlash.reset();
  std::vector<fivebar::calibration::MarkMeasurement> marks;
  std::map<int, Vec2> byId;
  std::vector<Vec2> paper, nominal;
  std::vector<int> patternIndex;
  for (std::size_t i = 0; i < (w_.useDistances ? 0 : w_.measured.size()); ++i) {
    const TableMark& t = w_.measured[i];
    if (!t.paperMm) continue;
    byId[t.id] = *t.paperMm;
    const PatternMark& m = w_.pattern->marks[i];
    if (m.kind != MarkKind::Grid) continue;  // backlash rows measure play, not geometry
    marks.push_back({std::to_string(t.id), t.commanded, *t.paperMm, static_cast<int>(i) + 1});
    paper.push_back(*t.paperMm);
    nominal.push_back(m.nominalMm);
    patternIndex.push_back(static_cast<int>(i));
  }
  fivebar::calibration::CalibrationInput input;
  input.nominal = w_.nominal;
  input.dateIso = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
  if (w_.useDistances) {
    for (const PatternMark& m : w_.pattern->marks)
      if (m.kind == MarkKind::Grid) input.poses.push_back({std::to_string(m.id), m.q, 0});
    for (std::size_t k = 0; k < w_.distances.size(); ++k) {
      const DistanceRow& d = w_.distances[k];
      input.distances.push_back({std::to_string(d.idA), std::to_string(d.idB), d.distanceMm, static_cast<int>(k) + 1});
    }
  } else {
    input.marks = marks;
    if (w_.pattern) {
      input.patternMarks = w_.pattern->marks;
      input.measuredById = byId;
    }
  }
  const fivebar::calibration::CalibrationOutcome outcome = fivebar::calibration::calibrate(input);
  const fivebar::calibration::CalibrationFit& fit = outcome.fit;
  if (!outcome.ok()) {
    summary_->setText(tr("<span style='color:#b00000'><b>The fit failed:</b> %1</span><br>Go back, "
                         "check the table, or measure more marks.")
                          .arg(translated(outcome.error)));
    parameters_->setRowCount(0);
    preview_->setArrows({});
    emit completeChanged();
    return;
  }
  w_.fit = fit;
  const MachineProfile& calibrated = *outcome.profile;
  QString backlashText;
  if (w_.useDistances) {
    backlashText = tr("Backlash is not measured from distances (it needs the positions of the "
                      "backlash rows' marks); the profile's backlash is kept.");
  } else if (outcome.backlash) {
    const BacklashEstimate& b = *outcome.backlash;
    if (b.ok()) {
      backlashText = tr("Backlash from %1 + %2 rows: motor 1 %3\u00b0, motor 2 %4\u00b0.")
                         .arg(b.rowsMotor1).arg(b.rowsMotor2)
                         .arg(degFromRad(b.play.motor1Rad), 0, 'f', 2)
                         .arg(degFromRad(b.play.motor2Rad), 0, 'f', 2);
    } else {
      backlashText = tr("Backlash not measured: %1").arg(translated(b.error));
    }
    w_.backlash = b;
  }
  w_.calibrated = calibrated;

  QString outliers = fit.outlierIds.empty()
                         ? tr("No mark looks mis-measured.")
                         : (w_.useDistances ? tr("<span style='color:#b00000'>Left out as mis-measured: "
                                                 "distance %1 (marks A-B). Measure it again.</span>")
                                            : tr("<span style='color:#b00000'>Left out as mis-measured: mark %1. "
                                                 "Check it on the sheet.</span>"))
                               .arg(QString::fromStdString([&] {
                                 std::string s;
                                 for (const auto& id : fit.outlierIds) s += (s.empty() ? "" : ", ") + id;
                                 return s;
                               }()));
  const QString errors =
      (w_.useDistances
           ? tr("<b>Distance error before: %1 mm RMS</b> (largest %2 mm) &rarr; <b>after: %3 mm RMS</b> "
                "(largest %4 mm) over %5 distances.")
           : tr("<b>Error before: %1 mm RMS</b> (largest %2 mm) &rarr; <b>after: %3 mm RMS</b> (largest %4 mm) "
                "over %5 marks."))
          .arg(mm(fit.beforeRmsMm), mm(fit.beforeMaxMm), mm(fit.afterRmsMm, 3), mm(fit.afterMaxMm, 3))
          .arg(fit.used);
  summary_->setText(errors +
                    tr("<br>Held-out measurements (%1): %2 mm before &rarr; %3 mm after.<br>%4<br>%5<br>"
                       "<small>Condition number %6 (below 10000 is fine).</small>")
                        .arg(fit.heldOut)
                        .arg(mm(fit.heldOutBeforeRmsMm), mm(fit.heldOutRmsMm, 3), outliers, backlashText)
                        .arg(fit.conditionNumber, 0, 'f', 0));

  parameters_->setRowCount(0);
  for (const auto& e : fit.estimates) {
    if (!e.machine) continue;
    const int r = parameters_->rowCount();
    parameters_->insertRow(r);
    const QString unit = QString::fromStdString(e.unit) == QLatin1String("deg") ? tr("\u00b0")
                                                                                 : tr(" mm");
    const auto before = nominalValue(w_.nominal, e.name);
    parameters_->setItem(r, 0, new QTableWidgetItem(QString::fromStdString(e.name)));
    parameters_->setItem(r, 1, new QTableWidgetItem(before ? mm(*before, 3) + unit : QStringLiteral("\u2013")));
    parameters_->setItem(r, 2, new QTableWidgetItem(tr("%1 \u00b1 %2%3").arg(mm(e.value, 3), mm(e.stdDev, 3), unit)));
  }

  // Arrows on the pattern: before = the sheet placed rigidly onto the plan; after = the fit's
  // residuals turned into the machine frame by that placement.
  std::vector<std::vector<Vec2>> plan;
  for (const Stroke& s : w_.pattern->strokes) plan.push_back(s.points);
  preview_->setPlan(plan);
  std::vector<Vec2> centres;
  std::vector<int> ids;
  for (const PatternMark& m : w_.pattern->marks) centres.push_back(m.nominalMm), ids.push_back(m.id);
  preview_->setMarks(centres, ids);
  std::vector<PreviewArrow> arrows;
  if (const auto placed = fitRigid(paper, nominal)) {
    for (std::size_t k = 0; k < paper.size(); ++k)
      arrows.push_back({nominal[k], placed->map(paper[k]) - nominal[k], false});
    for (std::size_t k = 0; k < fit.residuals.size() && k < nominal.size(); ++k) {
      if (fit.residuals[k].role == fivebar::calibration::Role::Outlier) continue;
      arrows.push_back({nominal[k], placed->rotation * fit.residuals[k].residualVecMm, true});
    }
  }
  preview_->setArrows(arrows);
  emit completeChanged();
}

// ---------------------------------------------------------------------------------------------
ApplyPage::ApplyPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("5. Apply the calibration to the profile"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(explanation(
      tr("Applying writes the fitted link lengths into the profile and keeps the motor zeros and "
         "the backlash in its calibration section. From then on every plan, jog and check uses "
         "them. <b>Edit &gt; Undo</b> takes it back; the profile is saved with the project, and "
         "you can also save it as a profile file for other projects.")));
  changes_ = explanation(QString());
  layout->addWidget(changes_);
  auto* buttons = new QHBoxLayout;
  apply_ = new QPushButton(tr("Apply to the profile"));
  auto* save = new QPushButton(tr("Save profile as..."));
  buttons->addWidget(apply_);
  buttons->addWidget(save);
  buttons->addStretch(1);
  layout->addLayout(buttons);
  status_ = explanation(QString());
  layout->addWidget(status_);
  layout->addStretch(1);
  connect(apply_, &QPushButton::clicked, this, &ApplyPage::apply);
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the calibrated profile"),
                                                      QStringLiteral("calibrated-profile.json"),
                                                      tr("Machine profile (*.json)"));
    if (path.isEmpty()) return;
    const MachineProfile& p = w_.applied ? w_.document().profile() : *w_.calibrated;
    const std::string why = saveProfile(p, path.toStdString());
    status_->setText(why.empty() ? tr("Saved %1.").arg(path) : QString::fromStdString(why));
  });
}

void ApplyPage::initializePage() {
  w_.applied = false;
  apply_->setEnabled(w_.calibrated.has_value());
  status_->clear();
  if (!w_.calibrated) return;
  const Geometry& a = w_.nominal.geometry;
  const Geometry& b = w_.calibrated->geometry;
  const MachineCalibration& c = *w_.calibrated->calibration;
  auto row = [](const QString& name, double from, double to, const QString& unit) {
    return QStringLiteral("<tr><td>%1</td><td align='right'>%2%4</td><td>&rarr;</td><td align='right'><b>%3%4</b></td></tr>")
        .arg(name, QString::number(from, 'f', 3), QString::number(to, 'f', 3), unit);
  };
  const double z1 = degFromRad(w_.nominal.calibration ? w_.nominal.calibration->zeroOffsetRad1 : 0.0);
  const double z2 = degFromRad(w_.nominal.calibration ? w_.nominal.calibration->zeroOffsetRad2 : 0.0);
  const double p1 = degFromRad(w_.nominal.calibration ? w_.nominal.calibration->backlashRad1 : 0.0);
  const double p2 = degFromRad(w_.nominal.calibration ? w_.nominal.calibration->backlashRad2 : 0.0);
  const QString mmU = tr(" mm"), degU = tr("\u00b0");
  changes_->setText(QStringLiteral("<table cellspacing='4'>") + row(QStringLiteral("a1"), a.a1, b.a1, mmU) +
                    row(QStringLiteral("b1"), a.b1, b.b1, mmU) + row(QStringLiteral("a2"), a.a2, b.a2, mmU) +
                    row(QStringLiteral("b2"), a.b2, b.b2, mmU) + row(QStringLiteral("w"), a.w, b.w, mmU) +
                    row(tr("motor 1 zero"), z1, degFromRad(c.zeroOffsetRad1), degU) +
                    row(tr("motor 2 zero"), z2, degFromRad(c.zeroOffsetRad2), degU) +
                    row(tr("motor 1 backlash"), p1, degFromRad(c.backlashRad1), degU) +
                    row(tr("motor 2 backlash"), p2, degFromRad(c.backlashRad2), degU) +
                    QStringLiteral("</table>"));
}

void ApplyPage::apply() {
  if (!w_.calibrated || w_.applied) return;
  w_.document().setProfile(*w_.calibrated);
  w_.applied = true;
  apply_->setEnabled(false);
  status_->setText(tr("Applied. Edit > Undo restores the profile as it was."));
}

// ---------------------------------------------------------------------------------------------
VerifyPage::VerifyPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("6. Draw the verification pattern"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("Draw the pattern once more, now planned with the calibrated profile, on a fresh sheet. "
         "Its marks should land where they were meant, and the accuracy lines should be straight "
         "and 40 mm long: <b>Next</b> measures the lines with a ruler for a before/after figure.")));
  send_ = new QPushButton(tr("Draw on the connected machine"));
  auto* exportButton = new QPushButton(tr("Export G-code..."));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(send_);
  buttons->addWidget(exportButton);
  buttons->addStretch(1);
  left->addLayout(buttons);
  status_ = explanation(QString());
  left->addWidget(status_);
  auto* progress = new RunProgressBox;
  left->addWidget(progress);
  figures_ = explanation(QString());
  left->addWidget(figures_);
  left->addStretch(1);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 3);
  connect(send_, &QPushButton::clicked, this, [this, progress] {
    if (!w_.session()) return;
    QString error;
    const auto done = [this](bool ok, const QString& message) {
      status_->setText(ok ? tr("The verification pattern is drawn.") : message);
    };
    const bool started = w_.runPattern(job_, w_.document().profile(), QStringLiteral("verification"), done, &error);
    status_->setText(started ? tr("Drawing the verification pattern...") : error);
    if (started) progress->watch(w_.patternRun());
  });
  connect(exportButton, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the verification G-code"),
                                                      QStringLiteral("calibration-verification.gcode"),
                                                      tr("G-code (*.gcode *.nc)"));
    if (path.isEmpty()) return;
    QFile file(path);
    status_->setText(file.open(QIODevice::WriteOnly) && file.write(gcode_.data(), qint64(gcode_.size())) >= 0
                         ? tr("Wrote %1.").arg(path) : tr("Cannot write %1.").arg(path));
  });
}

void VerifyPage::initializePage() {
  const MachineProfile& profile = w_.document().profile();
  QString error;
  pattern_ = makePattern(profile, PatternKind::Marks, 25, &error);
  job_ = {};
  gcode_.clear();
  if (pattern_) {
    // The calibration applied by the planner (zero offsets, pen offset, backlash compensation):
    // this sheet shows what the calibration achieves.
    PlanResult plan = planVerificationPattern(*pattern_, profile);
    if (plan.ok()) {
      job_ = std::move(plan.job);
      try {
        gcode_ = writeGcode(job_, profile);
      } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
      }
    } else {
      error = translated(plan.message);
    }
  }
  status_->setText(error);
  send_->setEnabled(w_.session() && w_.session()->isConnected() && !gcode_.empty());
  std::vector<std::vector<Vec2>> plan;
  if (pattern_)
    for (const Stroke& s : pattern_->strokes) plan.push_back(s.points);
  std::vector<std::vector<Vec2>> trace;
  if (w_.simulated && !gcode_.empty()) trace = simulatedTrace(gcode_, profile, w_.truth);
  preview_->setPlan(plan);
  preview_->setTrueTrace(trace);
  w_.showOnCanvas(plan, trace);
  if (w_.simulated && pattern_) {
    before_ = markShapeError(*pattern_, w_.nominal, w_.truth);
    now_ = markShapeError(*pattern_, profile, w_.truth);
    figures_->setText(
        tr("<b>Simulation:</b> the imperfect machine puts the marks %1 mm RMS (largest %2 mm) from "
           "where they are meant with the old profile, and <b>%3 mm RMS (largest %4 mm)</b> with "
           "the profile now in use%5.")
            .arg(mm(before_.rmsMm), mm(before_.maxMm), mm(now_.rmsMm, 3), mm(now_.maxMm, 3))
            .arg(w_.applied ? QString() : tr(" (the calibration is not applied)")));
  } else {
    figures_->clear();
  }
}

}  // namespace fivebar::widgets::calibration
