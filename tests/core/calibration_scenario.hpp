// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated calibration of issue 13's goal, shared by tests/core/calibration_fit_test.cpp and
// tests/bench/calibration_bench.cpp: a maker-plotter whose links are off by up to 0.5 mm and whose
// motor zeros are off by about 1 deg, 25 marks over the working area (edges included) measured with
// 0.05 mm noise in a rotated, translated (optionally mirrored) paper frame.
#pragma once

#include <random>
#include <stdexcept>
#include <vector>

#include "core/calibration/fit.hpp"
#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar::test {

// The machine as built: what the paper sees.
inline calibration::MachineParameters trueMakerPlotter() {
  calibration::MachineParameters t;
  t.geometry = {100.4, 179.65, 99.6, 180.35, 90.3};
  t.zeroOffsetRad1 = radFromDeg(1.0);
  t.zeroOffsetRad2 = radFromDeg(-0.8);
  return t;
}

// The working area: the largest safe A5-shaped rectangle of the nominal maker-plotter.
inline Rect workingArea(const MachineProfile& nominal) {
  const WorkspaceSettings s = workspaceSettings(nominal);
  const WorkspaceMap map = computeMap(nominal.geometry, s, nominal.defaultMode, gridCovering(nominal.geometry, 200));
  return *largestSafeRectangle(map, nominal.geometry, s, 210.0 / 148.0);
}
// Where the drawing is judged: the working area less 2 mm on each side, since its corners touch
// the nominal reach boundary, which the real machine's longer or shorter links move by up to 1 mm.
inline Rect judgedArea(const Rect& area) {
  return {area.xMin + 2.0, area.yMin + 2.0, area.xMax - 2.0, area.yMax - 2.0};
}

// nx x ny points over `r`, its edges included.
inline std::vector<Vec2> gridOver(const Rect& r, int nx, int ny) {
  std::vector<Vec2> points;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      points.emplace_back(r.xMin + r.width() * i / (nx - 1), r.yMin + r.height() * j / (ny - 1));
  return points;
}

// Commanded angles the host sends for a machine-frame point under `profile` (nullopt: out of reach).
inline std::optional<JointAngles> commandedFor(const MachineProfile& profile, const Vec2& point) {
  const IkResult ik = inverse(profile.geometry, point, profile.defaultMode);
  if (!ik.ok()) return std::nullopt;
  return commandedFromKinematic(profile.calibration, ik.angles);
}

// Where the true machine draws the points the host planned with `profile`.
inline std::vector<Vec2> drawnBy(const calibration::MachineParameters& truth, const MachineProfile& profile,
                                 const std::vector<Vec2>& planned) {
  std::vector<Vec2> drawn;
  for (const Vec2& p : planned) {
    const auto q = commandedFor(profile, p);
    const auto pen = q ? calibration::penPosition(truth, profile.assembly, *q) : std::nullopt;
    if (!pen) throw std::runtime_error("a planned point is out of the machine's reach");
    drawn.push_back(*pen);
  }
  return drawn;
}

// The 25 marks: a 5 x 5 grid over the working area, commanded by the nominal profile, drawn by the
// true machine, measured in a paper frame with `noiseMm` per coordinate.
inline std::vector<calibration::MarkMeasurement> measuredMarks(const MachineProfile& nominal, std::uint64_t seed,
                                                               bool mirrored, double noiseMm = 0.05) {
  const calibration::MachineParameters truth = trueMakerPlotter();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noiseMm);
  calibration::PaperPose paper;
  paper.mirrored = mirrored;
  paper.rotationRad = 0.35;
  paper.translationMm = Vec2(-40.0, 210.0);
  std::vector<calibration::MarkMeasurement> marks;
  int id = 1;
  for (const Vec2& p : gridOver(workingArea(nominal), 5, 5)) {
    const JointAngles q = *commandedFor(nominal, p);
    const Vec2 pen = *calibration::penPosition(truth, nominal.assembly, q);
    const Vec2 measured = paper.paperFromMachine(pen) + Vec2(noise(rng), noise(rng));
    marks.push_back({std::to_string(id++), q, measured, 0});
  }
  return marks;
}

// The drawing's shape error over the working area (11 x 9 points, after the best rigid placement).
inline calibration::ShapeError areaShapeError(const MachineProfile& profile, const Rect& area) {
  const std::vector<Vec2> planned = gridOver(judgedArea(area), 11, 9);
  return calibration::shapeError(drawnBy(trueMakerPlotter(), profile, planned), planned);
}

}  // namespace fivebar::test
