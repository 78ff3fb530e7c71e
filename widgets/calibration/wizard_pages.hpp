// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration wizard's pages (calibration_wizard.hpp). Each explains itself in plain words
// at the top; the picture of the sheet is a CalibrationPreview.
#pragma once

#include <QWizardPage>
#include <optional>

#include "widgets/calibration/calibration_preview.hpp"
#include "widgets/calibration/calibration_wizard.hpp"
#include "widgets/calibration/simulated_machine.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QTableWidget;
class QTabWidget;

namespace fivebar::widgets::calibration {

class DistancesBox;
class RunProgressBox;

// A label with word wrap for the explanations.
QLabel* explanation(const QString& text, QWidget* parent = nullptr);

// A number as typed in the measuring tables: "12.5", "12,5", " 12.5 ". nullopt when it is not one.
std::optional<double> typedNumber(QString text);

class PatternPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit PatternPage(CalibrationWizard& wizard);
  void initializePage() override;
  bool isComplete() const override;
  QRadioButton* marksChoice() const { return marks_; }
  QRadioButton* accuracyChoice() const { return accuracy_; }
  QSpinBox* markCount() const { return count_; }
  CalibrationPreview* preview() const { return preview_; }

 private:
  void rebuild();
  CalibrationWizard& w_;
  QRadioButton* marks_ = nullptr;
  QRadioButton* accuracy_ = nullptr;
  QSpinBox* count_ = nullptr;
  QLabel* summary_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
};

class DrawPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit DrawPage(CalibrationWizard& wizard);
  void initializePage() override;
  int nextId() const override;
  QCheckBox* simulateChoice() const { return simulate_; }
  // Keep the wizard's imperfect machine as the studio's simulated machine after the wizard closes.
  QCheckBox* keepChoice() const { return keep_; }
  TrueMachineForm* truthForm() const { return form_; }
  // The true machine's fields: da1, db1, da2, db2, dw (mm), zero offsets (deg), backlash (deg).
  QDoubleSpinBox* trueField(int index) const;
  QPushButton* sendButton() const { return send_; }
  QLabel* status() const { return status_; }
  // The pattern's run while it is drawn: progress, time left, Stop (as the Run panel shows a job).
  RunProgressBox* progress() const { return progress_; }
  CalibrationPreview* preview() const { return preview_; }
  bool exportGcode(const QString& path, QString* error) const;

 private:
  void refresh();
  CalibrationWizard& w_;
  QCheckBox* simulate_ = nullptr;
  QCheckBox* keep_ = nullptr;
  TrueMachineForm* form_ = nullptr;
  bool formFilled_ = false;
  QPushButton* send_ = nullptr;
  QLabel* status_ = nullptr;
  RunProgressBox* progress_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
};

class MeasurePage : public QWizardPage {
  Q_OBJECT
 public:
  explicit MeasurePage(CalibrationWizard& wizard);
  void initializePage() override;
  bool validatePage() override;
  QTableWidget* table() const { return table_; }
  QPushButton* simulatedSheetButton() const { return fromSheet_; }
  QDoubleSpinBox* noise() const { return noise_; }
  QLabel* problem() const { return problem_; }
  CalibrationPreview* preview() const { return preview_; }
  // Fills the table from the simulated sheet (the wizard's true machine, with noise).
  void fillFromSimulatedSheet();
  // The table read back; false with *error naming the mark and the column of the first bad cell.
  bool readTable(std::vector<TableMark>* out, QString* error) const;
  bool loadCsv(const QString& path, QString* error);
  // Finds the marks in a scanned sheet (PNG/JPEG at `dpi`) and fills the table; false with
  // *message naming the file and the problem, else *message says what was found.
  bool importScan(const QString& path, double dpi, QString* message);
  QDoubleSpinBox* dpi() const { return dpi_; }
  bool saveCsv(const QString& path, QString* error) const;
  // The two forms: coordinates (tab 0) and distances (tab 1, DistancesBox).
  QTabWidget* tabs() const { return tabs_; }
  DistancesBox* distances() const { return distances_; }
  static constexpr int kMinDistances = 12;

 private:
  void onCurrentCell(int row);
  void showMeasured();
  CalibrationWizard& w_;
  QTabWidget* tabs_ = nullptr;
  DistancesBox* distances_ = nullptr;
  QTableWidget* table_ = nullptr;
  QPushButton* fromSheet_ = nullptr;
  QDoubleSpinBox* noise_ = nullptr;
  QDoubleSpinBox* dpi_ = nullptr;
  QLabel* problem_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
  bool filling_ = false;
  unsigned sheetSeed_ = 13;  // each fill a new, reproducible noise draw
};

class FitPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit FitPage(CalibrationWizard& wizard);
  void initializePage() override;
  bool isComplete() const override;
  QLabel* summary() const { return summary_; }
  QTableWidget* parameters() const { return parameters_; }
  CalibrationPreview* preview() const { return preview_; }

 private:
  CalibrationWizard& w_;
  QLabel* summary_ = nullptr;
  QTableWidget* parameters_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
};

class ApplyPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit ApplyPage(CalibrationWizard& wizard);
  void initializePage() override;
  QPushButton* applyButton() const { return apply_; }
  QLabel* status() const { return status_; }
  void apply();

 private:
  CalibrationWizard& w_;
  QLabel* changes_ = nullptr;
  QPushButton* apply_ = nullptr;
  QLabel* status_ = nullptr;
};

class VerifyPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit VerifyPage(CalibrationWizard& wizard);
  void initializePage() override;
  QLabel* figures() const { return figures_; }
  CalibrationPreview* preview() const { return preview_; }
  // Shape error of the simulated true machine with the document's profile (for tests).
  ShapeFigures before() const { return before_; }
  ShapeFigures now() const { return now_; }

 private:
  CalibrationWizard& w_;
  QLabel* figures_ = nullptr;
  QPushButton* send_ = nullptr;
  QLabel* status_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
  std::optional<CalibrationPattern> pattern_;
  PlannedJob job_;
  std::string gcode_;
  ShapeFigures before_, now_;
};

// Hoang's accuracy lines measured with a ruler (or on the simulated sheet): each line's length and
// straightness, drawn before calibration and after it (the verification sheet), and the figures.
class AccuracyPage : public QWizardPage {
  Q_OBJECT
 public:
  explicit AccuracyPage(CalibrationWizard& wizard);
  void initializePage() override;
  int nextId() const override { return -1; }
  enum Column { kLengthBefore, kStraightBefore, kLengthAfter, kStraightAfter, kColumns };
  QTableWidget* table() const { return table_; }
  QLabel* figures() const { return figures_; }
  QPushButton* simulatedButton() const { return fromSheet_; }
  CalibrationPreview* preview() const { return preview_; }
  // Fills the table from the simulated sheets (before: the profile the wizard started from;
  // after: the profile in use, when the calibration is applied).
  void fillFromSimulatedSheet();
  // Fills the before (or after) columns from a scan of that sheet (core's scanAccuracyLines) and
  // shows the lines found in the preview; false with *message saying why (also shown).
  bool importScan(const QString& path, double dpi, bool after, QString* message);
  QDoubleSpinBox* scanDpi() const { return dpi_; }
  QComboBox* scanSheet() const { return sheet_; }
  // The columns read back; false with *error naming the line and the column of a bad cell.
  bool readColumns(bool after, std::vector<LineMeasure>* out, QString* error) const;
  // Recomputes the figures from the table (called on every edit).
  void updateFigures();
  std::optional<AccuracySummary> before() const { return before_; }
  std::optional<AccuracySummary> after() const { return after_; }

 private:
  CalibrationWizard& w_;
  QTableWidget* table_ = nullptr;
  QLabel* figures_ = nullptr;
  QPushButton* fromSheet_ = nullptr;
  QDoubleSpinBox* dpi_ = nullptr;
  QComboBox* sheet_ = nullptr;
  QLabel* scanStatus_ = nullptr;
  CalibrationPreview* preview_ = nullptr;
  std::optional<AccuracySummary> before_, after_;
  bool filling_ = false;
};

}  // namespace fivebar::widgets::calibration
