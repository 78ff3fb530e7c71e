// SPDX-License-Identifier: GPL-3.0-or-later
#include "pen_trace.hpp"

#include <algorithm>
#include <cmath>

#include "core/kinematics/units.hpp"

namespace fivebar::sim {

namespace {
JointAngles radOf(const std::array<double, 2>& deg) { return {radFromDeg(deg[0]), radFromDeg(deg[1])}; }
}  // namespace

PenTrace::PenTrace(const MachineProfile& m) { setMachine(m); }

void PenTrace::setMachine(const MachineProfile& m) {
  assembly_ = m.assembly;
  params_ = {};
  params_.geometry = m.geometry;
  play_ = {};
  if (m.calibration) {
    params_.zeroOffsetRad1 = m.calibration->zeroOffsetRad1;
    params_.zeroOffsetRad2 = m.calibration->zeroOffsetRad2;
    params_.penOffset = m.calibration->penOffset;
    play_ = {std::max(0.0, m.calibration->backlashRad1), std::max(0.0, m.calibration->backlashRad2)};
  }
  maxPieceDeg_ = 1.0 / std::max({m.motors.stepsPerDeg1, m.motors.stepsPerDeg2, 1.0});
  place(motor_);
}

void PenTrace::place(const std::array<double, 2>& commandedDeg) {
  motor_ = commandedDeg;
  arms_ = PlayState(play_, radOf(commandedDeg), {0.5 * play_.motor1Rad, 0.5 * play_.motor2Rad});
  out_ = {degFromRad(arms_.arm().theta1), degFromRad(arms_.arm().theta2)};
  open_ = false;
}

void PenTrace::moveTo(const std::array<double, 2>& commandedDeg, bool penDown) {
  const std::array<double, 2> from = motor_;
  const double span = std::max(std::abs(commandedDeg[0] - from[0]), std::abs(commandedDeg[1] - from[1]));
  // Along one joint-linear move each motor is monotonic: without the pen only the end counts.
  const int pieces = penDown ? std::max(1, int(std::ceil(span / maxPieceDeg_))) : 1;
  if (penDown && !open_) penAt(out_, true);  // the pen touches down where it stands
  for (int k = 1; k <= pieces; ++k) {
    const double u = double(k) / pieces;
    for (size_t i = 0; i < 2; ++i) motor_[i] = from[i] + (commandedDeg[i] - from[i]) * u;
    // The play: the output moves only when the motor pushes it at either side of the band.
    arms_.moveTo(radOf(motor_));
    out_ = {degFromRad(arms_.arm().theta1), degFromRad(arms_.arm().theta2)};
    if (penDown) penAt(out_, k == pieces);
  }
  motor_ = commandedDeg;
  if (!penDown) open_ = false;
}

void PenTrace::penAt(const std::array<double, 2>& outputDeg, bool keep) {
  const auto p = calibration::penPosition(params_, assembly_, {radFromDeg(outputDeg[0]), radFromDeg(outputDeg[1])});
  if (!p) {  // the true loop cannot close here: a gap in the drawing
    open_ = false;
    return;
  }
  if (!open_) {
    drawn_.push_back({*p});
    open_ = true;
    return;
  }
  const double d = (drawn_.back().back() - *p).norm();
  if (d >= 0.01 || (keep && d > 1e-9)) drawn_.back().push_back(*p);
}

}  // namespace fivebar::sim
