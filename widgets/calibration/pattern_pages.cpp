// The first two steps of the calibration wizard: choose the pattern, draw it.
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
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
         "apart, to judge straightness and length before and after; nothing to measure.")));
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

  auto* box = new QGroupBox(tr("No hardware? Simulate an imperfect machine"));
  auto* boxLayout = new QVBoxLayout(box);
  simulate_ = new QCheckBox(tr("Simulate an imperfect machine (the sheet below is what it draws)"));
  simulate_->setChecked(true);
  boxLayout->addWidget(simulate_);
  boxLayout->addWidget(explanation(
      tr("The simulated machine differs by these amounts from the profile as it was when this wizard opened, as a real one would. "
         "The picture shows what its pen really draws (orange) beside the plan. The built-in simulated "
         "machine of the Machine panel takes these amounts the next time it connects.")));
  truthBox_ = new QWidget;
  auto* grid = new QGridLayout(truthBox_);
  grid->setContentsMargins(0, 0, 0, 0);
  struct F { QString label; double value; double range; QString suffix; };
  const std::vector<F> fields{
      {tr("a1 longer by"), 0.4, 5.0, tr(" mm")},   {tr("b1 longer by"), -0.3, 5.0, tr(" mm")},
      {tr("a2 longer by"), 0.5, 5.0, tr(" mm")},   {tr("b2 longer by"), 0.2, 5.0, tr(" mm")},
      {tr("motors farther apart by"), -0.4, 5.0, tr(" mm")},
      {tr("motor 1 zero off by"), 1.0, 5.0, tr(" \u00b0")},
      {tr("motor 2 zero off by"), -0.8, 5.0, tr(" \u00b0")},
      {tr("motor 1 backlash"), 0.3, 2.0, tr(" \u00b0")},
      {tr("motor 2 backlash"), 0.2, 2.0, tr(" \u00b0")}};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    auto* spin = new QDoubleSpinBox;
    spin->setDecimals(2);
    spin->setSingleStep(0.1);
    spin->setRange(i >= 7 ? 0.0 : -fields[i].range, fields[i].range);
    spin->setValue(fields[i].value);
    spin->setSuffix(fields[i].suffix);
    const int row = static_cast<int>(i % 5), col = static_cast<int>(i / 5) * 2;
    grid->addWidget(new QLabel(fields[i].label), row, col);
    grid->addWidget(spin, row, col + 1);
    fields_.push_back(spin);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this] { refresh(); });
  }
  boxLayout->addWidget(truthBox_);
  left->addWidget(box);
  left->addStretch(1);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 2);
  layout->addWidget(preview_, 3);

  connect(simulate_, &QCheckBox::toggled, this, [this] { refresh(); });
  connect(send_, &QPushButton::clicked, this, [this] {
    if (!w_.session()) return;
    if (!sender_) {
      sender_ = new PatternSender(*w_.session(), this);
      connect(sender_, &PatternSender::finished, this, [this](bool ok, const QString& message) {
        status_->setText(ok ? tr("The pattern is drawn. Take the sheet off and measure it.") : message);
        send_->setEnabled(true);
      });
    }
    QString error;
    const QString path = QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                             .filePath(QStringLiteral("calibration/pattern.gcode"));
    if (sender_->send(w_.gcode, w_.nominal, path, &error)) {
      status_->setText(tr("Drawing the pattern (%1 lines of G-code)...").arg(std::count(w_.gcode.begin(), w_.gcode.end(), '\n')));
      send_->setEnabled(false);
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
  refresh();
}

int DrawPage::nextId() const {
  return w_.patternKind == PatternKind::AccuracyOnly ? -1 : CalibrationWizard::kMeasurePage;
}

void DrawPage::readTruth() {
  TrueMachine t;
  t.builtFrom = w_.builtFrom;
  t.da1Mm = fields_[0]->value();
  t.db1Mm = fields_[1]->value();
  t.da2Mm = fields_[2]->value();
  t.db2Mm = fields_[3]->value();
  t.dwMm = fields_[4]->value();
  t.zeroOffsetRad1 = radFromDeg(fields_[5]->value());
  t.zeroOffsetRad2 = radFromDeg(fields_[6]->value());
  t.play.motor1Rad = radFromDeg(fields_[7]->value());
  t.play.motor2Rad = radFromDeg(fields_[8]->value());
  w_.truth = t;
}

void DrawPage::refresh() {
  w_.simulated = simulate_->isChecked();
  truthBox_->setEnabled(w_.simulated);
  readTruth();
  // The built-in simulated machine becomes this imperfect machine (from its next connect).
  if (w_.session())
    w_.session()->setSimulatedTrueMachine(
        w_.simulated ? std::optional<MachineProfile>(trueMachineProfile(w_.nominal, w_.truth)) : std::nullopt);
  std::vector<std::vector<Vec2>> trace;
  if (w_.simulated && !w_.job.moves.empty()) trace = trueTrace(w_.job, w_.nominal, w_.truth);
  preview_->setTrueTrace(trace);
  if (w_.pattern) w_.showOnCanvas(planStrokes(*w_.pattern), trace);
}

}  // namespace fivebar::widgets::calibration
