// SPDX-License-Identifier: GPL-3.0-or-later
// The measure step's second form (docs/calibration.md "Distances"): a ruler alone, no paper frame.
// A table of pairs of mark numbers and their measured distance in mm, as `fivebar calibrate fit`
// reads it from `id_a,id_b,distance_mm`; loaded from such a file, or filled from the simulated
// sheet. Only the fit marks count (the backlash rows' marks lag by the play).
#pragma once

#include <QWidget>
#include <functional>
#include <optional>
#include <vector>

#include "widgets/calibration/calibration_state.hpp"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace fivebar::widgets::calibration {

class DistancesBox : public QWidget {
  Q_OBJECT
 public:
  explicit DistancesBox(QWidget* parent = nullptr);
  // The pattern whose fit marks may be named (null: none yet).
  void setPattern(const CalibrationPattern* pattern);
  // Where "measure the simulated sheet" gets its rows from (noise mm, seed); unset: disabled.
  using SimulatedSource = std::function<std::vector<DistanceRow>(double noiseMm, unsigned seed)>;
  void setSimulatedSource(SimulatedSource source);

  QTableWidget* table() const { return table_; }
  QPushButton* simulatedButton() const { return fromSheet_; }
  QLabel* problem() const { return problem_; }
  void setRows(const std::vector<DistanceRow>& rows);
  void fillFromSimulatedSheet();
  // The rows read back (empty rows skipped); false with *error naming the row and the field.
  bool read(std::vector<DistanceRow>* out, QString* error) const;
  // A distances file (id_a,id_b,distance_mm); false with *error naming the file and line.
  bool loadCsv(const QString& path, QString* error);
  void showProblem(const QString& text, bool bad);

 signals:
  void currentMark(int id);  // the first mark of the row being typed (-1: none)

 private:
  const CalibrationPattern* pattern_ = nullptr;
  SimulatedSource source_;
  QTableWidget* table_ = nullptr;
  QPushButton* fromSheet_ = nullptr;
  QDoubleSpinBox* noise_ = nullptr;
  QLabel* problem_ = nullptr;
  unsigned seed_ = 29;
};

}  // namespace fivebar::widgets::calibration
