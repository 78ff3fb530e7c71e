// SPDX-License-Identifier: GPL-3.0-or-later
// The measure step of the calibration wizard: a table of the marks to type x, y into (any paper
// frame), the mark being typed highlighted on the picture, or filled from the simulated sheet.
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QTabWidget>
#include <QVBoxLayout>
#include <map>

#include "core/calibration/marks_csv.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/calibration/scan/scan.hpp"
#include "i18n/translated.hpp"
#include "core/kinematics/units.hpp"
#include "widgets/calibration/distances_box.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace fivebar::widgets::calibration {

namespace {
enum Column { kId, kKind, kTheta1, kTheta2, kX, kY, kColumns };

QTableWidgetItem* fixedItem(const QString& text) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(item->flags() & ~Qt::ItemIsEditable);
  item->setForeground(QColor(90, 90, 90));
  return item;
}

}  // namespace

MeasurePage::MeasurePage(CalibrationWizard& wizard) : w_(wizard) {
  setTitle(tr("3. Measure the marks"));
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  left->addWidget(explanation(
      tr("Measure the centre of each numbered dot with a ruler and type its x and y in millimetres. "
         "Any corner of the sheet can be the origin, and y may point up or down: the fit finds how "
         "the sheet lay. The mark you are typing is circled on the picture. Leave a row empty if "
         "a mark cannot be read; a mis-measured mark is found and named by the fit. With a "
         "scanner, import a scan instead: the marks are found and numbered for you. With a ruler "
         "alone, measure distances between marks in the second tab.")));
  // Two forms: coordinates (typed, loaded or from a scan) and distances (a ruler alone).
  tabs_ = new QTabWidget;
  auto* coordinates = new QWidget;
  auto* coordinatesLayout = new QVBoxLayout(coordinates);
  distances_ = new DistancesBox;
  tabs_->addTab(coordinates, tr("Coordinates (x, y)"));
  tabs_->addTab(distances_, tr("Distances between marks"));
  left->addWidget(tabs_, 1);
  table_ = new QTableWidget(0, kColumns);
  table_->setHorizontalHeaderLabels({tr("Mark"), tr("Kind"), QStringLiteral("\u03b8\u2081 (\u00b0)"),
                                     QStringLiteral("\u03b8\u2082 (\u00b0)"),
                                     tr("x (mm)"), tr("y (mm)")});
  table_->verticalHeader()->setVisible(false);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  coordinatesLayout->addWidget(table_, 1);
  problem_ = explanation(QString());
  problem_->setStyleSheet(QStringLiteral("color:#b00000"));
  coordinatesLayout->addWidget(problem_);

  auto* sim = new QHBoxLayout;
  fromSheet_ = new QPushButton(tr("Simulation: measure the simulated sheet"));
  fromSheet_->setToolTip(tr("Fills the table with where the simulated imperfect machine put each "
                            "mark, plus ruler noise. For trying the wizard without hardware."));
  noise_ = new QDoubleSpinBox;
  noise_->setRange(0.0, 1.0);
  noise_->setDecimals(2);
  noise_->setSingleStep(0.01);
  noise_->setValue(0.05);
  noise_->setPrefix(tr("noise \u00b1"));
  noise_->setSuffix(tr(" mm"));
  sim->addWidget(fromSheet_);
  sim->addWidget(noise_);
  coordinatesLayout->addLayout(sim);
  auto* scan = new QHBoxLayout;
  auto* scanButton = new QPushButton(tr("Import a scan..."));
  scanButton->setToolTip(tr("A scan or photo taken straight from above (PNG or JPEG): the marks are "
                            "found and numbered by themselves."));
  dpi_ = new QDoubleSpinBox;
  dpi_->setRange(50.0, 4800.0);
  dpi_->setDecimals(0);
  dpi_->setValue(600.0);
  dpi_->setSuffix(tr(" dpi"));
  dpi_->setToolTip(tr("The scanner's resolution: the scan's size in mm comes from it."));
  scan->addWidget(scanButton);
  scan->addWidget(dpi_);
  scan->addStretch(1);
  coordinatesLayout->addLayout(scan);
  auto* files = new QHBoxLayout;
  auto* load = new QPushButton(tr("Load MEASURED.csv..."));
  auto* save = new QPushButton(tr("Save MEASURED.csv..."));
  files->addWidget(load);
  files->addWidget(save);
  files->addStretch(1);
  coordinatesLayout->addLayout(files);
  preview_ = new CalibrationPreview;
  layout->addLayout(left, 3);
  layout->addWidget(preview_, 3);

  connect(table_, &QTableWidget::currentCellChanged, this, [this](int row) { onCurrentCell(row); });
  connect(table_, &QTableWidget::cellChanged, this, [this](int row) {
    if (filling_) return;
    onCurrentCell(row);
    showMeasured();
  });
  connect(fromSheet_, &QPushButton::clicked, this, &MeasurePage::fillFromSimulatedSheet);
  connect(distances_, &DistancesBox::currentMark, this, [this](int id) {
    int index = -1;
    if (w_.pattern)
      for (std::size_t i = 0; i < w_.pattern->marks.size(); ++i)
        if (w_.pattern->marks[i].id == id) index = static_cast<int>(i);
    preview_->setHighlighted(index);
  });
  connect(tabs_, &QTabWidget::currentChanged, this, [this] { preview_->setMeasured({}); showMeasured(); });
  connect(scanButton, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a scan of the sheet"), QString(),
                                                      tr("Images (*.png *.jpg *.jpeg *.tif *.tiff *.bmp)"));
    if (path.isEmpty()) return;
    QString message;
    importScan(path, dpi_->value(), &message);
  });
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load MEASURED.csv"), QString(), tr("CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !loadCsv(path, &error)) problem_->setText(error);
  });
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save MEASURED.csv"),
                                                      QStringLiteral("MEASURED.csv"), tr("CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !saveCsv(path, &error)) problem_->setText(error);
  });
}

void MeasurePage::initializePage() {
  fromSheet_->setEnabled(w_.simulated);
  noise_->setEnabled(w_.simulated);
  distances_->setPattern(w_.pattern ? &*w_.pattern : nullptr);
  if (w_.simulated && w_.pattern)
    distances_->setSimulatedSource([this](double noiseMm, unsigned seed) {
      return measureSimulatedDistances(*w_.pattern, w_.nominal, w_.truth, noiseMm, seed);
    });
  else
    distances_->setSimulatedSource({});
  if (!w_.pattern) return;
  // Keep what was typed when the pattern is the same (Back and Next again).
  if (table_->rowCount() == static_cast<int>(w_.pattern->marks.size())) return;
  filling_ = true;
  table_->setRowCount(static_cast<int>(w_.pattern->marks.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    const PatternMark& m = w_.pattern->marks[r];
    table_->setItem(r, kId, fixedItem(QString::number(m.id)));
    table_->setItem(r, kKind, fixedItem(m.kind == MarkKind::Grid ? tr("fit")
                                                                 : tr("backlash %1").arg(m.group)));
    table_->setItem(r, kTheta1, fixedItem(QString::number(degFromRad(m.q.theta1), 'f', 2)));
    table_->setItem(r, kTheta2, fixedItem(QString::number(degFromRad(m.q.theta2), 'f', 2)));
    table_->setItem(r, kX, new QTableWidgetItem);
    table_->setItem(r, kY, new QTableWidgetItem);
  }
  filling_ = false;
  std::vector<Vec2> centres;
  std::vector<int> ids;
  for (const PatternMark& m : w_.pattern->marks) centres.push_back(m.nominalMm), ids.push_back(m.id);
  std::vector<std::vector<Vec2>> plan;
  for (const Stroke& s : w_.pattern->strokes) plan.push_back(s.points);
  preview_->setPlan(plan);
  preview_->setMarks(centres, ids);
  preview_->setMeasured({});
  problem_->clear();
  table_->setCurrentCell(0, kX);
}

void MeasurePage::onCurrentCell(int row) { preview_->setHighlighted(row); }

void MeasurePage::fillFromSimulatedSheet() {
  if (!w_.pattern) return;
  const std::vector<TableMark> sheet =
      measureSimulatedSheet(*w_.pattern, w_.nominal, w_.truth, noise_->value(), sheetSeed_++);
  filling_ = true;
  for (int r = 0; r < table_->rowCount() && r < static_cast<int>(sheet.size()); ++r) {
    const auto& p = sheet[r].paperMm;
    table_->item(r, kX)->setText(p ? QString::number(p->x(), 'f', 2) : QString());
    table_->item(r, kY)->setText(p ? QString::number(p->y(), 'f', 2) : QString());
  }
  filling_ = false;
  problem_->setText(tr("Filled from the simulated sheet (simulation, not a measurement)."));
  problem_->setStyleSheet(QStringLiteral("color:#a05000"));
  showMeasured();
}

bool MeasurePage::readTable(std::vector<TableMark>* out, QString* error) const {
  out->clear();
  if (!w_.pattern) return false;
  for (int r = 0; r < table_->rowCount(); ++r) {
    const PatternMark& m = w_.pattern->marks[r];
    TableMark t;
    t.id = m.id;
    t.commanded = m.q;
    const QString xs = table_->item(r, kX)->text().trimmed(), ys = table_->item(r, kY)->text().trimmed();
    if (xs.isEmpty() && ys.isEmpty()) {
      out->push_back(t);
      continue;
    }
    if (xs.isEmpty() || ys.isEmpty()) {
      *error = tr("Mark %1: %2 is empty. Type both x and y, or leave both empty.")
                   .arg(m.id).arg(xs.isEmpty() ? QStringLiteral("x") : QStringLiteral("y"));
      return false;
    }
    const auto x = typedNumber(xs), y = typedNumber(ys);
    if (!x || !y) {
      *error = tr("Mark %1, %2: '%3' is not a number.")
                   .arg(m.id).arg(!x ? QStringLiteral("x") : QStringLiteral("y"), !x ? xs : ys);
      return false;
    }
    t.paperMm = Vec2(*x, *y);
    out->push_back(t);
  }
  return true;
}

void MeasurePage::showMeasured() {
  if (tabs_->currentWidget() == distances_) return;  // distances place nothing on the sheet
  std::vector<TableMark> marks;
  QString error;
  if (!readTable(&marks, &error)) {
    problem_->setStyleSheet(QStringLiteral("color:#b00000"));
    problem_->setText(error);
    preview_->setMeasured({});
    return;
  }
  // The typed marks placed onto the pattern (best rigid placement, mirrored or not).
  std::vector<Vec2> paper, nominal;
  for (std::size_t i = 0; i < marks.size(); ++i) {
    if (!marks[i].paperMm || w_.pattern->marks[i].kind != MarkKind::Grid) continue;
    paper.push_back(*marks[i].paperMm);
    nominal.push_back(w_.pattern->marks[i].nominalMm);
  }
  std::vector<Vec2> placed;
  if (paper.size() >= 3) {
    if (const auto fit = fitRigid(paper, nominal)) {
      for (const TableMark& t : marks)
        if (t.paperMm) placed.push_back(fit->map(*t.paperMm));
    }
  }
  preview_->setMeasured(placed);
}

bool MeasurePage::validatePage() {
  w_.useDistances = tabs_->currentWidget() == distances_;
  if (w_.useDistances) {
    std::vector<DistanceRow> rows;
    QString error;
    if (!distances_->read(&rows, &error)) {
      distances_->showProblem(error, true);
      return false;
    }
    if (static_cast<int>(rows.size()) < kMinDistances) {
      distances_->showProblem(tr("Only %1 distances are measured; measure at least %2, about four "
                                 "for each mark (the fit finds 5 lengths and 2 motor zeros).")
                                  .arg(rows.size()).arg(kMinDistances), true);
      return false;
    }
    w_.distances = rows;
    return true;
  }
  std::vector<TableMark> marks;
  QString error;
  if (!readTable(&marks, &error)) {
    problem_->setStyleSheet(QStringLiteral("color:#b00000"));
    problem_->setText(error);
    return false;
  }
  int grid = 0;
  for (std::size_t i = 0; i < marks.size(); ++i)
    if (marks[i].paperMm && w_.pattern->marks[i].kind == MarkKind::Grid) ++grid;
  if (grid < kMinPatternMarks) {
    problem_->setStyleSheet(QStringLiteral("color:#b00000"));
    problem_->setText(tr("Only %1 marks for the fit are measured; measure at least %2 (the fit finds "
                         "5 lengths, 2 motor zeros and how the sheet lay).")
                          .arg(grid).arg(kMinPatternMarks));
    return false;
  }
  w_.measured = marks;
  return true;
}

bool MeasurePage::loadCsv(const QString& path, QString* error) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    *error = tr("Cannot read %1: %2").arg(path, file.errorString());
    return false;
  }
  const MeasuredLoad load = parseMeasuredCsv(file.readAll().toStdString(), path.toStdString());
  if (!load.ok()) {
    *error = translated(load.error);
    return false;
  }
  std::map<int, Vec2> byId;
  for (const MeasuredMark& m : load.marks) byId[m.id] = m.measuredMm;
  filling_ = true;
  for (int r = 0; r < table_->rowCount(); ++r) {
    const auto it = byId.find(w_.pattern->marks[r].id);
    table_->item(r, kX)->setText(it == byId.end() ? QString() : QString::number(it->second.x(), 'f', 3));
    table_->item(r, kY)->setText(it == byId.end() ? QString() : QString::number(it->second.y(), 'f', 3));
  }
  filling_ = false;
  showMeasured();
  return true;
}

bool MeasurePage::importScan(const QString& path, double dpi, QString* message) {
  if (!w_.pattern) return false;
  std::vector<MarkRecord> records;
  for (const PatternMark& m : w_.pattern->marks) records.push_back({m, w_.pattern->ringRadiusMm});
  const ScanOutcome scan = scanFile(path.toStdString(), dpi, records);
  if (!scan.ok()) {
    *message = translated(scan.error);
    problem_->setStyleSheet(QStringLiteral("color:#b00000"));
    problem_->setText(*message);
    return false;
  }
  std::map<int, Vec2> byId;
  for (const MeasuredMark& m : scan.measured) byId[m.id] = m.measuredMm;
  filling_ = true;
  for (int r = 0; r < table_->rowCount(); ++r) {
    const auto it = byId.find(w_.pattern->marks[r].id);
    table_->item(r, kX)->setText(it == byId.end() ? QString() : QString::number(it->second.x(), 'f', 3));
    table_->item(r, kY)->setText(it == byId.end() ? QString() : QString::number(it->second.y(), 'f', 3));
  }
  filling_ = false;
  QStringList missing;
  for (int id : scan.missingIds) missing << QString::number(id);
  *message = tr("Found %1 of %2 marks in the scan (sheet turned %3°%4).%5")
                 .arg(static_cast<int>(scan.measured.size()))
                 .arg(static_cast<int>(w_.pattern->marks.size()))
                 .arg(scan.rotationDeg, 0, 'f', 1)
                 .arg(scan.mirrored ? tr(", mirrored") : QString())
                 .arg(missing.isEmpty() ? QString() : tr(" Not found: %1; type them in by hand.").arg(missing.join(QStringLiteral(", "))));
  problem_->setStyleSheet(QString());
  problem_->setText(*message);
  showMeasured();
  return true;
}

bool MeasurePage::saveCsv(const QString& path, QString* error) const {
  std::vector<TableMark> marks;
  if (!readTable(&marks, error)) return false;
  std::vector<MeasuredMark> rows;
  for (const TableMark& t : marks) {
    if (!t.paperMm) continue;
    rows.push_back({t.id, degFromRad(t.commanded.theta1), degFromRad(t.commanded.theta2), *t.paperMm});
  }
  const std::string text = measuredCsv(rows);
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), static_cast<qint64>(text.size())) < 0 ||
      !file.commit()) {
    *error = tr("Cannot write %1: %2").arg(path, file.errorString());
    return false;
  }
  return true;
}

}  // namespace fivebar::widgets::calibration
