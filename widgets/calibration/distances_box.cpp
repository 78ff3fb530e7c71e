// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/distances_box.hpp"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "core/calibration/measurements.hpp"
#include "i18n/translated.hpp"
#include "widgets/calibration/wizard_pages.hpp"

namespace fivebar::widgets::calibration {

namespace {
enum Column { kA, kB, kDistance, kColumns };
}  // namespace

DistancesBox::DistancesBox(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(explanation(
      tr("Only a ruler? Measure the distance between the centres of two marks and type both mark "
         "numbers and the distance. No corner or direction is needed. Measure long and short "
         "pairs across the whole sheet, each mark in several pairs: about four per mark "
         "(100 for 25 marks) calibrate as well as coordinates. Use the marks for the fit, not "
         "the backlash rows."), this));
  table_ = new QTableWidget(0, kColumns, this);
  table_->setObjectName(QStringLiteral("distancesTable"));
  table_->setHorizontalHeaderLabels({tr("Mark A"), tr("Mark B"), tr("Distance (mm)")});
  table_->verticalHeader()->setVisible(true);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  layout->addWidget(table_, 1);
  problem_ = explanation(QString(), this);
  layout->addWidget(problem_);
  auto* rows = new QHBoxLayout;
  auto* add = new QPushButton(tr("Add a row"), this);
  auto* remove = new QPushButton(tr("Remove the row"), this);
  auto* load = new QPushButton(tr("Load distances CSV..."), this);
  load->setToolTip(tr("A file with the columns id_a,id_b,distance_mm (as fivebar calibrate fit reads it)"));
  rows->addWidget(add);
  rows->addWidget(remove);
  rows->addWidget(load);
  rows->addStretch(1);
  layout->addLayout(rows);
  auto* sim = new QHBoxLayout;
  fromSheet_ = new QPushButton(tr("Simulation: measure distances on the simulated sheet"), this);
  fromSheet_->setToolTip(tr("Fills the table with distances between where the simulated imperfect "
                            "machine put the marks, plus ruler noise."));
  noise_ = new QDoubleSpinBox(this);
  noise_->setRange(0.0, 1.0);
  noise_->setDecimals(2);
  noise_->setSingleStep(0.01);
  noise_->setValue(0.05);
  noise_->setPrefix(tr("noise \u00b1"));
  noise_->setSuffix(tr(" mm"));
  sim->addWidget(fromSheet_);
  sim->addWidget(noise_);
  sim->addStretch(1);
  layout->addLayout(sim);
  fromSheet_->setEnabled(false);
  noise_->setEnabled(false);

  connect(add, &QPushButton::clicked, this, [this] {
    const int r = table_->rowCount();
    table_->insertRow(r);
    for (int c = 0; c < kColumns; ++c) table_->setItem(r, c, new QTableWidgetItem);
    table_->setCurrentCell(r, kA);
  });
  connect(remove, &QPushButton::clicked, this, [this] {
    if (table_->currentRow() >= 0) table_->removeRow(table_->currentRow());
  });
  connect(load, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Load distances"), QString(), tr("CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !loadCsv(path, &error)) showProblem(error, true);
  });
  connect(fromSheet_, &QPushButton::clicked, this, &DistancesBox::fillFromSimulatedSheet);
  connect(table_, &QTableWidget::currentCellChanged, this, [this](int row) {
    const QTableWidgetItem* item = row >= 0 ? table_->item(row, kA) : nullptr;
    const auto id = item ? typedNumber(item->text()) : std::nullopt;
    emit currentMark(id ? static_cast<int>(*id) : -1);
  });
}

void DistancesBox::setPattern(const CalibrationPattern* pattern) { pattern_ = pattern; }

void DistancesBox::setSimulatedSource(SimulatedSource source) {
  source_ = std::move(source);
  fromSheet_->setEnabled(static_cast<bool>(source_));
  noise_->setEnabled(static_cast<bool>(source_));
}

void DistancesBox::showProblem(const QString& text, bool bad) {
  problem_->setStyleSheet(bad ? QStringLiteral("color:#b00000") : QStringLiteral("color:#a05000"));
  problem_->setText(text);
}

void DistancesBox::setRows(const std::vector<DistanceRow>& rows) {
  table_->setRowCount(static_cast<int>(rows.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    const DistanceRow& d = rows[static_cast<std::size_t>(r)];
    table_->setItem(r, kA, new QTableWidgetItem(QString::number(d.idA)));
    table_->setItem(r, kB, new QTableWidgetItem(QString::number(d.idB)));
    table_->setItem(r, kDistance, new QTableWidgetItem(QString::number(d.distanceMm, 'f', 2)));
  }
}

void DistancesBox::fillFromSimulatedSheet() {
  if (!source_) return;
  setRows(source_(noise_->value(), seed_++));
  showProblem(tr("Filled from the simulated sheet (simulation, not a measurement)."), false);
}

bool DistancesBox::read(std::vector<DistanceRow>* out, QString* error) const {
  out->clear();
  auto text = [this](int r, int c) {
    const QTableWidgetItem* item = table_->item(r, c);
    return item ? item->text().trimmed() : QString();
  };
  const QString names[kColumns] = {tr("mark A"), tr("mark B"), tr("distance")};
  for (int r = 0; r < table_->rowCount(); ++r) {
    const QString fields[kColumns] = {text(r, kA), text(r, kB), text(r, kDistance)};
    if (fields[0].isEmpty() && fields[1].isEmpty() && fields[2].isEmpty()) continue;
    std::optional<double> v[kColumns];
    for (int c = 0; c < kColumns; ++c) {
      if (fields[c].isEmpty()) {
        *error = tr("Row %1: %2 is empty.").arg(r + 1).arg(names[c]);
        return false;
      }
      v[c] = typedNumber(fields[c]);
      if (!v[c] || (c < kDistance && *v[c] != std::round(*v[c]))) {
        *error = tr("Row %1, %2: '%3' is not a number.").arg(r + 1).arg(names[c], fields[c]);
        return false;
      }
    }
    DistanceRow d{static_cast<int>(*v[kA]), static_cast<int>(*v[kB]), *v[kDistance]};
    for (int id : {d.idA, d.idB}) {
      const PatternMark* mark = nullptr;
      if (pattern_)
        for (const PatternMark& m : pattern_->marks)
          if (m.id == id) mark = &m;
      if (!mark) {
        *error = tr("Row %1: there is no mark %2 in the pattern.").arg(r + 1).arg(id);
        return false;
      }
      if (mark->kind != MarkKind::Grid) {
        *error = tr("Row %1: mark %2 is in a backlash row; measure distances between marks for the fit.")
                     .arg(r + 1).arg(id);
        return false;
      }
    }
    if (d.idA == d.idB) {
      *error = tr("Row %1: a distance from mark %2 to itself.").arg(r + 1).arg(d.idA);
      return false;
    }
    if (!(d.distanceMm > 0.0)) {
      *error = tr("Row %1: the distance must be more than 0 mm.").arg(r + 1);
      return false;
    }
    out->push_back(d);
  }
  return true;
}

bool DistancesBox::loadCsv(const QString& path, QString* error) {
  std::string text;
  Message why;
  if (!fivebar::calibration::readTextFile(path.toStdString(), text, why)) {
    *error = translated(why);
    return false;
  }
  const auto read = fivebar::calibration::readMeasurements(text, path.toStdString());
  if (!read.ok()) {
    *error = translated(read.error);
    return false;
  }
  if (read.form != fivebar::calibration::MeasurementForm::Distances) {
    *error = tr("%1 holds mark coordinates, not distances: load it in the Coordinates tab.").arg(path);
    return false;
  }
  std::vector<DistanceRow> rows;
  for (const auto& d : read.distances) {
    bool okA = false, okB = false;
    const int a = QString::fromStdString(d.idA).toInt(&okA), b = QString::fromStdString(d.idB).toInt(&okB);
    if (!okA || !okB) {
      *error = tr("%1:%2: the pattern's marks are numbered; '%3' is not a mark number.")
                   .arg(path).arg(d.line).arg(QString::fromStdString(okA ? d.idB : d.idA));
      return false;
    }
    rows.push_back({a, b, d.distanceMm});
  }
  setRows(rows);
  showProblem(tr("Loaded %1 distances from %2.").arg(rows.size()).arg(path), false);
  return true;
}

}  // namespace fivebar::widgets::calibration
