// SPDX-License-Identifier: GPL-3.0-or-later
// The first two steps of the calibration wizard: choose the pattern, draw it.
#include <QLocale>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSaveFile>
#include <QSpinBox>
#include <QStandardPaths>
#include <QVBoxLayout>

#include "core/calibration/marks_csv.hpp"
#include "core/kinematics/units.hpp"
#include "widgets/calibration/run_progress_box.hpp"
#include "widgets/calibration/wizard_pages.hpp"
#include "session/machine_session.hpp"

namespace fivebar::widgets::calibration {

namespace {

std::vector<std::vector<Vec2>> planStrokes(const CalibrationPattern& pattern) {
  std::vector<std::vector<Vec2>> out;
  for (const Stroke& s : pattern.strokes) out.push_back(s.points);
  return out;
}

void showPattern(CalibrationPreview& preview, const CalibrationPattern& pattern) {
  preview.setPlan(planStrokes(pattern));
  std::vector<Vec2> centres;
  std::vector<int> ids;
  for (const PatternMark& m : pattern.marks) {
    centres.push_back(m.nominalMm);
    ids.push_back(m.id);
  }
  preview.setMarks(centres, ids);
}

bool writeText(const QString& path, const std::string& text, QString* error) {
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) ||
      file.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()) ||
      !file.commit()) {
    if (error) *error = QObject::tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
PatternPage::PatternPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("1. Choose the pattern"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("No machine is built exactly as drawn: a link cut half a millimetre long or a motor zero "
         "set by eye bends every drawing. The studio draws a <b>pattern</b> of numbered marks, you "
         "measure where they really landed, and a fit finds the machine's true link lengths and "
         "motor zeros.<br><br><b>Calibration marks</b>: numbered dots in rings spread over the "
         "whole working area, plus rows that show the slack (backlash) of each motor. Use these to "
         "calibrate.<br><b>Accuracy pattern</b> (Hoang): ten parallel lines, 40 mm long and 10 mm "
         "apart, to judge straightness and length before and after: you measure each line's length "
         "and straightness with a ruler in the wizard's last step.")));
  marks_ = new QRadioButton(tr("Calibration marks"));
  accuracy_ = new QRadioButton(tr("Accuracy pattern only (10 lines)"));
  marks_->setChecked(true);
  count_ = new QSpinBox;
  count_->setRange(kMinPatternMarks, 60);
  count_->setValue(25);
  count_->setSuffix(tr(" marks"));
  count_->setToolTip(tr("More marks: a more certain fit, more to measure. 25 is a good start."));
  auto* form = new QFormLayout;
  form->addRow(marks_);
  form->addRow(tr("Marks for the fit:"), count_);
  form->addRow(accuracy_);
  left->addLayout(form);
  summary_ = explanation(QString());
  left->addWidget(summary_);
  left->addStretch(1);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 3);
  connect(marks_, &QRadioButton::toggled, this, [this] { rebuild(); });
  connect(count_, &QSpinBox::valueChanged, this, [this] { rebuild(); });
}

void PatternPage::initializePage() {
  w_.nominal = w_.document().profile();
  rebuild();
}

bool PatternPage::isComplete() const { return w_.pattern.has_value(); }

void PatternPage::rebuild() {
  count_->setEnabled(marks_->isChecked());
  w_.patternKind = marks_->isChecked() ? PatternKind::Marks : PatternKind::AccuracyOnly;
  QString error;
  w_.pattern = makePattern(w_.nominal, w_.patternKind, count_->value(), &error);
  w_.fit.reset();
  w_.calibrated.reset();
  if (!w_.pattern) {
    summary_->setText(tr("<span style='color:#b00000'>%1</span>").arg(error));
    preview_->setPlan({});
    preview_->setMarks({}, {});
  } else {
    int grid = 0, rows = 0;
    for (const PatternMark& m : w_.pattern->marks) (m.kind == MarkKind::Grid ? grid : rows)++;
    summary_->setText(
        w_.patternKind == PatternKind::Marks
            ? tr("For <b>%1</b>: %2 marks for the fit and %3 marks in backlash rows%4.")
                  .arg(QString::fromStdString(w_.nominal.name))
                  .arg(grid)
                  .arg(rows)
                  .arg(w_.pattern->accuracy ? tr(", with the accuracy lines in the middle") : QString())
            : tr("For <b>%1</b>: ten lines of 40 mm in the middle of the working area.")
                  .arg(QString::fromStdString(w_.nominal.name)));
    showPattern(*preview_, *w_.pattern);
    w_.showOnCanvas(planStrokes(*w_.pattern), {});
  }
  emit completeChanged();
}

// ---------------------------------------------------------------------------------------------
DrawPage::DrawPage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("2. Draw the pattern"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("Tape a sheet down so it cannot move, and draw the pattern with the pen you normally use. "
         "Draw it on the connected machine, or export its G-code and send it your way. "
         "Keep MARKS.csv: it says which motor angles drew each mark.")));
  send_ = new QPushButton(tr("Draw on the connected machine"));
  auto* exportButton = new QPushButton(tr("Export G-code..."));
  auto* marksButton = new QPushButton(tr("Export MARKS.csv..."));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(send_);
  buttons->addWidget(exportButton);
  buttons->addWidget(marksButton);
  left->addLayout(buttons);
  status_ = explanation(QString());
  left->addWidget(status_);
  progress_ = new RunProgressBox;
  left->addWidget(progress_);

  auto* box = new QGroupBox(tr("No hardware? Simulate an imperfect machine"));
  auto* boxLayout = new QVBoxLayout(box);
  simulate_ = new QCheckBox(tr("Simulate an imperfect machine (the sheet below is what it draws)"));
  simulate_->setChecked(true);
  boxLayout->addWidget(simulate_);
  boxLayout->addWidget(explanation(
      tr("The simulated machine differs from the profile by these amounts, as a real one would. The "
         "picture shows what its pen really draws (orange) beside the plan. The built-in simulated "
         "machine (Machine panel) becomes this machine at once, also when it is connected. When the "
         "wizard closes it goes back to the studio's setting (Machine &gt; Simulated machine...), "
         "unless you keep it.")));
  form_ = new TrueMachineForm;
  boxLayout->addWidget(form_);
  keep_ = new QCheckBox(tr("Keep this machine as the studio's simulated machine after the wizard"));
  keep_->setToolTip(tr("Saved in Machine > Simulated machine...; the status bar shows it while it is imperfect"));
  boxLayout->addWidget(keep_);
  connect(form_, &TrueMachineForm::edited, this, [this] { refresh(); });
  left->addWidget(box);
  left->addStretch(1);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 3);

  connect(simulate_, &QCheckBox::toggled, this, [this] { refresh(); });
  connect(send_, &QPushButton::clicked, this, [this] {
    if (!w_.session()) return;
    QString error;
    const auto done = [this](bool ok, const QString& message) {
      status_->setText(ok ? tr("The pattern is drawn. Take the sheet off and measure it.") : message);
      send_->setEnabled(true);
    };
    if (w_.runPattern(w_.job, w_.nominal, QStringLiteral("pattern"), done, &error)) {
      status_->setText(tr("Drawing the pattern (%1 lines of G-code)...").arg(QLocale().toString(qlonglong(std::count(w_.gcode.begin(), w_.gcode.end(), '\n')))));
      send_->setEnabled(false);
      progress_->watch(w_.patternRun());
    } else {
      status_->setText(error);
    }
  });
  connect(exportButton, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the pattern's G-code"),
                                                      QStringLiteral("calibration-pattern.gcode"),
                                                      tr("G-code (*.gcode *.nc)"));
    if (path.isEmpty()) return;
    QString error;
    status_->setText(exportGcode(path, &error) ? tr("Wrote %1.").arg(path) : error);
  });
  connect(marksButton, &QPushButton::clicked, this, [this] {
    if (!w_.pattern) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export MARKS.csv"),
                                                      QStringLiteral("MARKS.csv"), tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    status_->setText(writeText(path, marksCsv(*w_.pattern), &error) ? tr("Wrote %1.").arg(path) : error);
  });
}

bool DrawPage::exportGcode(const QString& path, QString* error) const {
  return writeText(path, w_.gcode, error);
}

void DrawPage::initializePage() {
  QString error;
  if (!w_.planPattern(w_.nominal, &error)) status_->setText(error);
  else status_->clear();
  const bool connected = w_.session() && w_.session()->isConnected();
  send_->setEnabled(connected);
  send_->setToolTip(connected ? tr("Streams the pattern with the same checks as the Run panel")
                              : tr("Connect a machine or the simulated machine in the Machine panel first"));
  if (w_.pattern) showPattern(*preview_, *w_.pattern);
  if (!formFilled_) {
    // The studio's imperfect machine when there is one, else an example of a maker's machine.
    SimulatedTruth* studio = w_.simulatedTruth();
    form_->setAmounts(studio && studio->active() ? studio->truth() : TrueMachineForm::example());
    formFilled_ = true;
  }
  refresh();
}

QDoubleSpinBox* DrawPage::trueField(int index) const { return form_->field(index); }

int DrawPage::nextId() const {
  return w_.patternKind == PatternKind::AccuracyOnly ? CalibrationWizard::kAccuracyPage
                                                   : CalibrationWizard::kMeasurePage;
}

void DrawPage::refresh() {
  w_.simulated = simulate_->isChecked();
  form_->setEnabled(w_.simulated);
  keep_->setEnabled(w_.simulated && w_.simulatedTruth() != nullptr);
  w_.truth = form_->amounts();
  w_.truth.builtFrom = w_.builtFrom;
  // The built-in simulated machine is this imperfect machine from now on (until the wizard closes).
  if (SimulatedTruth* studio = w_.simulatedTruth()) studio->setTruth(w_.simulated ? w_.truth : TrueMachine{}, false);
  std::vector<std::vector<Vec2>> trace;
  if (w_.simulated && !w_.gcode.empty()) trace = simulatedTrace(w_.gcode, w_.nominal, w_.truth);
  preview_->setTrueTrace(trace);
  if (w_.pattern) w_.showOnCanvas(planStrokes(*w_.pattern), trace);
}

}  // namespace fivebar::widgets::calibration
