// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/simulated_sheet.hpp"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <random>

#include "core/calibration/rigid_fit.hpp"
#include "core/kinematics/kinematics.hpp"
#include "core/output/gcode.hpp"
#include "drivers/sim/sim_machine.hpp"
#include "i18n/translated.hpp"

namespace fivebar::session {

QString accuracyPatternDoesNotFit() {
  return QCoreApplication::translate("CalibrationWizard",
                                     "Hoang's accuracy pattern (10 lines of 40 mm) does not fit "
                                     "in this machine's safe area.");
}

std::vector<std::vector<Vec2>> simulatedTrace(const std::string& gcode, const MachineProfile& profile,
                                              const TrueMachine& truth) {
  sim::SimConfig config;
  config.profile = profile;
  config.instant = true;
  config.setUp = true;
  config.referenced = true;
  config.trueMachine = trueMachineProfile(profile, truth);
  sim::SimMachine machine(config);
  // Line by line, each answered before the next (a line the board refuses is skipped: the
  // wizard's G-code passed the planner's checks).
  std::size_t from = 0;
  while (from < gcode.size()) {
    std::size_t end = gcode.find('\n', from);
    if (end == std::string::npos) end = gcode.size();
    machine.receive(std::string_view(gcode).substr(from, end - from));
    machine.receive("\n");
    from = end + 1;
    std::string answer;
    for (int i = 0; i < 200 && answer.find('\n') == std::string::npos; ++i) {
      machine.advance(0.01);
      answer += machine.takeOutput();
    }
  }
  std::vector<std::vector<Vec2>> out;
  for (const auto& line : machine.drawnTrace()) {
    std::vector<Vec2> kept;
    for (std::size_t i = 0; i < line.size(); ++i)
      if (kept.empty() || i + 1 == line.size() || (line[i] - kept.back()).norm() >= kTracePreviewStepMm)
        kept.push_back(line[i]);
    out.push_back(std::move(kept));
  }
  return out;
}

std::optional<Vec2> trueMarkCentre(const PatternMark& mark, const MachineProfile& profile,
                                   const TrueMachine& truth) {
  // The approach ends with each motor moving in the mark's approach direction: start one approach
  // excursion before it and let the play be taken up on the way in.
  const double d = PatternOptions{}.approachRad;
  const JointAngles from{mark.q.theta1 + (mark.approach1 == Approach::Plus ? -d : d),
                         mark.q.theta2 + (mark.approach2 == Approach::Plus ? -d : d)};
  PlayState state(truth.play, from);
  state.moveTo(mark.q);
  const JointAngles arm{state.arm().theta1 + truth.zeroOffsetRad1,
                        state.arm().theta2 + truth.zeroOffsetRad2};
  const FkResult fk = forward(truth.geometry(), arm, profile.assembly);
  if (!fk.ok()) return std::nullopt;
  return fk.p;
}

std::vector<TableMark> measureSimulatedSheet(const CalibrationPattern& pattern,
                                             const MachineProfile& profile,
                                             const TrueMachine& truth, double noiseMm,
                                             unsigned seed) {
  std::vector<TableMark> out;
  std::vector<Vec2> centres;
  for (const PatternMark& m : pattern.marks) {
    TableMark t;
    t.id = m.id;
    t.commanded = m.q;
    t.paperMm = trueMarkCentre(m, profile, truth);
    if (t.paperMm) centres.push_back(*t.paperMm);
    out.push_back(t);
  }
  // A ruler from the sheet's lower-left corner, 15 mm below and left of the outermost marks.
  Vec2 corner = Vec2::Zero();
  if (!centres.empty()) {
    corner = centres.front();
    for (const Vec2& c : centres) corner = corner.cwiseMin(c);
    corner -= Vec2(15.0, 15.0);
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, std::max(0.0, noiseMm));
  for (TableMark& t : out) {
    if (!t.paperMm) continue;
    Vec2 p = *t.paperMm - corner;
    if (noiseMm > 0.0) p += Vec2(noise(rng), noise(rng));
    // A ruler reads to 0.01 mm at best.
    t.paperMm = Vec2(std::round(p.x() * 100.0) / 100.0, std::round(p.y() * 100.0) / 100.0);
  }
  return out;
}

std::vector<DistanceRow> measureSimulatedDistances(const CalibrationPattern& pattern,
                                                   const MachineProfile& profile,
                                                   const TrueMachine& truth, double noiseMm,
                                                   unsigned seed) {
  std::vector<std::pair<int, Vec2>> centres;
  for (const PatternMark& m : pattern.marks)
    if (m.kind == MarkKind::Grid)
      if (const auto c = trueMarkCentre(m, profile, truth)) centres.emplace_back(m.id, *c);
  const std::size_t n = centres.size();
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, std::max(0.0, noiseMm));
  std::vector<DistanceRow> out;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t step : {1u, 5u, 11u, 17u}) {
      if (step >= n) continue;
      const std::size_t j = (i + step) % n;
      const std::pair<std::size_t, std::size_t> key{std::min(i, j), std::max(i, j)};
      if (std::find(pairs.begin(), pairs.end(), key) != pairs.end()) continue;
      pairs.push_back(key);
      double d = (centres[i].second - centres[j].second).norm();
      if (noiseMm > 0.0) d += noise(rng);
      out.push_back({centres[i].first, centres[j].first, std::round(d * 100.0) / 100.0});
    }
  return out;
}

std::optional<AccuracyFigures> simulatedAccuracy(const MachineProfile& profile, const TrueMachine& truth,
                                                 std::vector<std::vector<Vec2>>* trace, QString* error) {
  const auto pattern = accuracyOnlyPattern(profile);
  if (!pattern) {
    if (error) *error = accuracyPatternDoesNotFit();
    return std::nullopt;
  }
  // Planned with the profile as it is: a calibrated profile's zero offsets, pen offset and
  // backlash compensation all apply (planCalibrationPattern would draw the raw machine, without
  // the compensation the fitted zeros assume).
  PlanResult plan = planVerificationPattern(*pattern, profile);
  if (!plan.ok()) {
    if (error) *error = translated(plan.message);
    return std::nullopt;
  }
  std::string gcode;
  try {
    gcode = writeGcode(plan.job, profile);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return std::nullopt;
  }
  auto drawn = simulatedTrace(gcode, profile, truth);
  if (drawn.size() != static_cast<std::size_t>(kAccuracyLineCount)) {
    if (error)
      *error = QCoreApplication::translate("CalibrationWizard", "The simulated machine drew %1 lines instead of %2.")
                   .arg(drawn.size()).arg(kAccuracyLineCount);
    return std::nullopt;
  }
  auto figures = accuracyFigures(drawn);
  if (trace) *trace = std::move(drawn);
  if (!figures && error) *error = QCoreApplication::translate("CalibrationWizard", "A simulated line is too short to measure.");
  return figures;
}

ShapeFigures markShapeError(const CalibrationPattern& pattern, const MachineProfile& profile,
                            const TrueMachine& truth) {
  // Each grid mark's meant place, commanded as the profile (with its calibration) would command
  // it, drawn by the true machine.
  std::vector<Vec2> meant, drawn;
  const Geometry trueGeometry = truth.geometry();
  for (const PatternMark& m : pattern.marks) {
    if (m.kind != MarkKind::Grid) continue;
    const IkResult ik = inverse(profile.geometry, m.nominalMm, pattern.mode);
    if (!ik.ok()) continue;
    const JointAngles commanded = commandedFromKinematic(profile.calibration, ik.angles);
    const FkResult fk = forward(trueGeometry,
                                {commanded.theta1 + truth.zeroOffsetRad1, commanded.theta2 + truth.zeroOffsetRad2},
                                profile.assembly);
    if (!fk.ok()) continue;
    meant.push_back(m.nominalMm);
    drawn.push_back(fk.p);
  }
  ShapeFigures f;
  const auto fit = fitRigid(drawn, meant, false);
  if (!fit) return f;
  double sum = 0.0;
  for (std::size_t i = 0; i < meant.size(); ++i) {
    const double e = (fit->map(drawn[i]) - meant[i]).norm();
    sum += e * e;
    f.maxMm = std::max(f.maxMm, e);
  }
  f.marks = static_cast<int>(meant.size());
  f.rmsMm = f.marks > 0 ? std::sqrt(sum / f.marks) : 0.0;
  return f;
}

}  // namespace fivebar::session
