// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/machine/true_machine.hpp"

namespace fivebar {

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

}  // namespace fivebar
