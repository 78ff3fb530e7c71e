// SPDX-License-Identifier: GPL-3.0-or-later
// Fitting the calibration model to measured marks (issue 13, docs/calibration.md): nonlinear least
// squares with Eigen's LevenbergMarquardt module, robust to mis-measured marks (flagged, named,
// left out, refitted), with parameter standard deviations, the problem's conditioning and an
// honest error on held-out marks. Millimetres and radians inside; estimates in file units.
#pragma once

#include "core/support/message.hpp"

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/calibration/model.hpp"
#include "core/machine/profile.hpp"

namespace fivebar::calibration {

// A mark drawn at commanded angles and measured in some paper frame (any origin, rotation,
// mirrored or not). `line` is where it came from (for messages), 0 when not from a file.
struct MarkMeasurement {
  std::string id;
  JointAngles commanded;
  Vec2 paperMm = Vec2::Zero();
  int line = 0;
};

// A mark drawn at commanded angles, without a measured position (the distance form).
struct MarkPose {
  std::string id;
  JointAngles commanded;
  int line = 0;
};

// A ruler's distance between two marks.
struct DistanceMeasurement {
  std::string idA;
  std::string idB;
  double distanceMm = 0.0;
  int line = 0;
};

struct FitOptions {
  bool fitPenOffset = false;        // also fit the pen's offset from P (docs/calibration.md)
  int holdOutEvery = 5;             // every Nth measurement (in file order) is held out; 0: none
  int minMeasurementsToHoldOut = 15;  // fewer measurements than this: nothing is held out
  double outlierSigmas = 4.0;       // robust rule: residual > outlierSigmas * robust sigma ...
  double minOutlierResidualMm = 0.5;  // ... and larger than this (a ruler reading's own error)
  double maxOutlierShare = 0.2;     // at most this share of measurements may be rejected
  double maxConditionNumber = 1e4;  // of the column-normalised Jacobian (25 spread marks: ~60); above: refused
  int maxFunctionEvaluations = 4000;
};

enum class FitStatus { Ok, TooFewMeasurements, DidNotConverge, IllConditioned, BadInput };

struct ParameterEstimate {
  std::string name;  // "a1", ..., "zeroOffset1", "penOffsetAlong", "paperRotation", ...
  std::string unit;  // "mm" or "deg"
  double value = 0.0;
  double stdDev = 0.0;
  bool machine = true;  // false for the paper pose (fitted alongside, then discarded)
};

enum class Role { Fitted, HeldOut, Outlier };

struct MeasurementResidual {
  std::string id;            // mark id, or "A-B" for a distance
  Role role = Role::Fitted;
  double residualMm = 0.0;   // |predicted - measured| (points) or |predicted - measured distance|
  Vec2 residualVecMm = Vec2::Zero();  // points: measured - predicted, paper frame
};

struct CalibrationFit {
  FitStatus status = FitStatus::BadInput;
  Message reason;  // why the fit was refused (empty when Ok); translatable (context CalibrationFit)
  MachineParameters parameters;
  std::optional<PaperPose> paper;  // points form only
  std::vector<ParameterEstimate> estimates;
  double conditionNumber = 0.0;     // column-normalised Jacobian at the solution
  double residualSigmaMm = 0.0;     // sqrt(SSR / (residuals - parameters))
  double beforeRmsMm = 0.0, beforeMaxMm = 0.0;    // nominal model, all non-outlier measurements
  double afterRmsMm = 0.0, afterMaxMm = 0.0;      // fitted model, fitted measurements
  double heldOutBeforeRmsMm = 0.0;                // nominal model on the held-out measurements
  double heldOutRmsMm = 0.0, heldOutMaxMm = 0.0;  // fitted model on the held-out measurements
  int used = 0;
  int heldOut = 0;
  std::vector<std::string> outlierIds;
  std::vector<MeasurementResidual> residuals;  // one per measurement, in input order
  int functionEvaluations = 0;
  bool ok() const { return status == FitStatus::Ok; }
};

// The parameters a profile stands for (its geometry and calibration, if any).
MachineParameters parametersOf(const MachineProfile& p);

CalibrationFit fitMarks(const MachineProfile& nominal, std::span<const MarkMeasurement> marks,
                        const FitOptions& options = {});
CalibrationFit fitDistances(const MachineProfile& nominal, std::span<const MarkPose> marks,
                            std::span<const DistanceMeasurement> distances, const FitOptions& options = {});

// "maker-plotter (calibrated 2026-12-04)": the nominal name with one calibration mark (a profile
// calibrated again keeps one mark, with the new date; `dateIso` "" gives "(calibrated)").
std::string calibratedProfileName(const std::string& nominalName, const std::string& dateIso);
// `nominal` with the fitted geometry and a calibration section (zero offsets, pen offset, fit
// statistics, `dateIso`). Backlash already in `nominal`'s calibration is kept. Its name is its
// own, not the preset's: calibratedProfileName(nominal.name, dateIso).
MachineProfile calibratedProfile(const MachineProfile& nominal, const CalibrationFit& fit,
                                 const std::string& dateIso);

}  // namespace fivebar::calibration
