// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated sheet, beside the simulated board: what a "true machine" (true_machine.hpp: geometry,
// zero offsets and backlash that differ from the profile) really draws when it runs the calibration
// pattern, and the sheet measured as a maker would (marks from a corner, distances with a ruler,
// seeded noise). The calibration wizard offers it so the whole loop runs without hardware.
// Machine frame, mm and rad.
#pragma once

#include <QString>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/accuracy_pattern.hpp"
#include "core/calibration/pattern.hpp"
#include "core/machine/true_machine.hpp"

namespace fivebar::session {

// "Hoang's accuracy pattern ... does not fit in this machine's safe area." (translated)
QString accuracyPatternDoesNotFit();

// One measured mark as typed into the table (paper frame, any origin, mirrored or not).
struct TableMark {
  int id = 0;
  JointAngles commanded;
  std::optional<Vec2> paperMm;  // empty cell: not measured
};

// What the true machine draws when it runs `gcode` (written for `profile`): the G-code run on
// the simulator itself (drivers/sim/sim_machine: instant, set up and referenced, SimConfig::trueMachine
// = trueMachineProfile(profile, truth)), so the play, zero offsets and geometry act exactly as on
// the studio's simulated machine (drivers/sim/pen_trace on core's PlayState). One polyline per pen-down
// run, machine frame, points at least kTracePreviewStepMm apart (and every run's ends).
inline constexpr double kTracePreviewStepMm = 0.05;
std::vector<std::vector<Vec2>> simulatedTrace(const std::string& gcode, const MachineProfile& profile,
                                              const TrueMachine& truth);

// Where the true machine puts each mark's dot (after its approach, so backlash shows), machine
// frame, by core's play model (PlayState, as the simulator's pen trace); nullopt for a pose the
// true machine cannot reach.
std::optional<Vec2> trueMarkCentre(const PatternMark& mark, const MachineProfile& profile,
                                   const TrueMachine& truth);

// The simulated sheet measured with a ruler from its lower-left corner: the true mark centres
// shifted so the sheet corner is the origin, plus Gaussian noise (seeded: the same seed gives the
// same table).
std::vector<TableMark> measureSimulatedSheet(const CalibrationPattern& pattern,
                                             const MachineProfile& profile,
                                             const TrueMachine& truth, double noiseMm,
                                             unsigned seed);

// A ruler's distance between two marks, as typed into the distances table.
struct DistanceRow {
  int idA = 0, idB = 0;
  double distanceMm = 0.0;
};

// The simulated sheet measured with a ruler alone: about four distances per fit mark (to marks
// 1, 5, 11 and 17 places further in the pattern, pairs counted once), from the true mark centres,
// plus Gaussian noise (seeded), read to 0.01 mm.
std::vector<DistanceRow> measureSimulatedDistances(const CalibrationPattern& pattern,
                                                   const MachineProfile& profile,
                                                   const TrueMachine& truth, double noiseMm,
                                                   unsigned seed);

// Hoang's accuracy lines as the true machine draws them when planned with `profile`: the pattern
// placed for `profile`, its G-code run on the simulator (simulatedTrace), each drawn line's
// figures by core's accuracyFigures. *trace gets the drawing (may be null). nullopt with *error
// when the pattern does not fit or does not come out as kAccuracyLineCount lines.
std::optional<AccuracyFigures> simulatedAccuracy(const MachineProfile& profile, const TrueMachine& truth,
                                                 std::vector<std::vector<Vec2>>* trace, QString* error);

// The shape error (RMS and max, mm) of the true machine drawing the pattern's grid marks, after
// the best rigid placement onto what was meant: the number calibration should make small.
struct ShapeFigures {
  double rmsMm = 0.0;
  double maxMm = 0.0;
  int marks = 0;
};
ShapeFigures markShapeError(const CalibrationPattern& pattern, const MachineProfile& profile,
                            const TrueMachine& truth);

}  // namespace fivebar::session
