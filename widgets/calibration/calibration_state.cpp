#include "widgets/calibration/calibration_state.hpp"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <random>

#include "core/calibration/backlash.hpp"
#include "core/calibration/rigid_fit.hpp"
#include "core/kinematics/kinematics.hpp"

namespace fivebar::widgets::calibration {

Geometry TrueMachine::geometry() const {
  Geometry g = builtFrom;
  g.a1 += da1Mm;
  g.b1 += db1Mm;
  g.a2 += da2Mm;
  g.b2 += db2Mm;
  g.w += dwMm;
  return g;
}

MachineProfile trueMachineProfile(const MachineProfile& nominal, const TrueMachine& truth) {
  MachineProfile m = nominal;
  m.geometry = truth.geometry();
  MachineCalibration c;
  c.zeroOffsetRad1 = truth.zeroOffsetRad1;
  c.zeroOffsetRad2 = truth.zeroOffsetRad2;
  c.backlashRad1 = truth.play.motor1Rad;
  c.backlashRad2 = truth.play.motor2Rad;
  m.calibration = c;
  return m;
}

bool TrueMachine::perfect() const {
  return da1Mm == 0.0 && db1Mm == 0.0 && da2Mm == 0.0 && db2Mm == 0.0 && dwMm == 0.0 &&
         zeroOffsetRad1 == 0.0 && zeroOffsetRad2 == 0.0 && play.none();
}

std::optional<CalibrationPattern> makePattern(const MachineProfile& profile, PatternKind kind,
                                              int gridMarks, QString* error) {
  if (kind == PatternKind::AccuracyOnly) {
    const auto lines = placeAccuracyPattern(profile);
    if (!lines) {
      if (error)
        *error = QCoreApplication::translate("CalibrationWizard",
                                             "Hoang's accuracy pattern (10 lines of 40 mm) does not fit "
                                             "in this machine's safe area.");
      return std::nullopt;
    }
    CalibrationPattern pattern;
    pattern.accuracy = lines;
    pattern.mode = profile.defaultMode;
    for (const AccuracyLine& line : lines->lines) {
      Stroke s;
      s.points = {line.startMm, line.endMm};
      pattern.strokes.push_back(s);
    }
    return pattern;
  }
  PatternOptions options;
  options.gridMarks = gridMarks;
  PatternResult r = makeCalibrationPattern(profile, options);
  if (!r.pattern) {
    if (error) *error = QString::fromStdString(r.error);
    return std::nullopt;
  }
  return r.pattern;
}

std::vector<std::vector<Vec2>> trueTrace(const PlannedJob& job, const MachineProfile& profile,
                                         const TrueMachine& truth) {
  // The true motor angle is the commanded one plus the zero offset: shift every target.
  PlannedJob shifted = job;
  const JointAngles d{truth.zeroOffsetRad1, truth.zeroOffsetRad2};
  shifted.start = {job.start.theta1 + d.theta1, job.start.theta2 + d.theta2};
  for (JobMove& m : shifted.moves) m.target = {m.target.theta1 + d.theta1, m.target.theta2 + d.theta2};
  return drawnWithPlay(shifted, truth.geometry(), profile.assembly, truth.play);
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

}  // namespace fivebar::widgets::calibration
