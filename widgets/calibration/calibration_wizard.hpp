// SPDX-License-Identifier: GPL-3.0-or-later
// Machine > Calibrate...: the calibration wizard (issue 13, docs/calibration-wizard.md). Steps:
// choose the pattern -> draw it (connected or simulated machine, or export its G-code) -> measure
// (type x, y per mark, or fill the table from the simulated sheet) -> fit (before/after errors,
// residual arrows, parameters with their uncertainties, outliers named) -> apply to the profile
// (undoable, saved with the project; or saved as a profile file) -> draw the verification pattern.
// The fit is core's (core/calibration/fit.hpp); this only shows it and carries the data.
#pragma once

#include <functional>

#include <QPointer>
#include <QWizard>
#include <memory>
#include <optional>
#include <vector>

#include "core/calibration/backlash.hpp"
#include "core/calibration/fit.hpp"
#include "widgets/calibration/calibration_state.hpp"
#include "widgets/document/studio_document.hpp"

class QAction;

namespace fivebar {
}

namespace fivebar::session {
class FixedJobInputs;
class MachineSession;
class RunController;
}

namespace fivebar::widgets {
class CanvasView;
}

namespace fivebar::widgets::calibration {

class PatternPage;
class SheetLayer;
class SimulatedTruth;
class DrawPage;
class MeasurePage;
class FitPage;
class ApplyPage;
class VerifyPage;
class AccuracyPage;

class CalibrationWizard : public QWizard {
  Q_OBJECT
 public:
  enum PageId { kPatternPage, kDrawPage, kMeasurePage, kFitPage, kApplyPage, kVerifyPage, kAccuracyPage };

  // `session` may be null (no machine side): drawing then means exporting the G-code.
  // `simulatedTruth` is the studio's simulated-machine setting (null without a session).
  CalibrationWizard(StudioDocument& doc, session::MachineSession* session, SimulatedTruth* simulatedTruth,
                    QWidget* parent = nullptr);
  ~CalibrationWizard() override;
  // Machine > Calibrate...; the sheet is shown on `canvas` (may be null) while the wizard is open.
  // The wizard is created on first use as the parent's child and kept in `wizard` (owned by the
  // composition root, which must outlive the action's use).
  static QAction* createAction(StudioDocument& doc, session::MachineSession* session, SimulatedTruth* truth,
                               CanvasView* canvas, QWidget* parent, QPointer<CalibrationWizard>& wizard);
  // Shows the sheet (plan and the simulated machine's true trace) on the studio's canvas.
  void attachCanvas(CanvasView* canvas);
  void showOnCanvas(std::vector<std::vector<Vec2>> plan, std::vector<std::vector<Vec2>> trace);
  SheetLayer* sheetLayer() const { return sheetLayer_; }

  StudioDocument& document() { return doc_; }
  session::MachineSession* session() { return session_; }
  // The studio's simulated-machine setting (simulated_machine.hpp); null without a session. The
  // draw step changes it for the time the wizard is open; closing the wizard puts the saved
  // setting back unless the maker chose to keep the wizard's machine.
  SimulatedTruth* simulatedTruth() const { return simTruth_; }

  // --- what the steps share ---
  MachineProfile nominal;                     // the profile the pattern was made for
  std::optional<CalibrationPattern> pattern;  // the chosen pattern
  PatternKind patternKind = PatternKind::Marks;
  PlannedJob job;                             // the pattern as planned
  std::string gcode;                          // and as G-code
  bool simulated = true;                      // the simulated sheet stands in for the machine
  Geometry builtFrom;                         // what the simulated machine's amounts are measured from
  TrueMachine truth;                          // what the simulated machine really is
  std::vector<TableMark> measured;            // the measure step's table, checked
  std::vector<DistanceRow> distances;         // or its distances, checked
  bool useDistances = false;                  // the fit uses the distances, not the table
  std::optional<fivebar::calibration::CalibrationFit> fit;
  std::optional<BacklashEstimate> backlash;
  std::optional<MachineProfile> calibrated;   // the nominal profile with the fit applied
  bool applied = false;

  // Plans `pattern` with `profile` into job and gcode; false with *error.
  bool planPattern(const MachineProfile& profile, QString* error);

  // Draws `job` (planned for `profile`) on the connected machine through a RunController, as the
  // Run panel runs a job: the same pose and settings checks, progress, hold, stop and resume; its
  // files are <app data>/calibration/<name>.gcode. `done` is called once when the run ends.
  // False with *error when it cannot start (no machine, a job running, the pose unknown, ...).
  bool runPattern(const PlannedJob& job, const MachineProfile& profile, const QString& name,
                  std::function<void(bool ok, const QString& message)> done, QString* error);
  // The controller of the patterns' runs; null before the first runPattern.
  session::RunController* patternRun() const { return patternRun_; }

  PatternPage* patternPage() const { return patternPage_; }
  DrawPage* drawPage() const { return drawPage_; }
  MeasurePage* measurePage() const { return measurePage_; }
  FitPage* fitPage() const { return fitPage_; }
  ApplyPage* applyPage() const { return applyPage_; }
  VerifyPage* verifyPage() const { return verifyPage_; }
  AccuracyPage* accuracyPage() const { return accuracyPage_; }

 private:
  StudioDocument& doc_;
  session::MachineSession* session_;
  SimulatedTruth* simTruth_ = nullptr;
  PatternPage* patternPage_ = nullptr;
  DrawPage* drawPage_ = nullptr;
  MeasurePage* measurePage_ = nullptr;
  FitPage* fitPage_ = nullptr;
  ApplyPage* applyPage_ = nullptr;
  VerifyPage* verifyPage_ = nullptr;
  AccuracyPage* accuracyPage_ = nullptr;
  SheetLayer* sheetLayer_ = nullptr;
  session::FixedJobInputs* patternInputs_ = nullptr;
  session::RunController* patternRun_ = nullptr;
};

}  // namespace fivebar::widgets::calibration
