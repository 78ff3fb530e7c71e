// SPDX-License-Identifier: GPL-3.0-or-later
// PenTrace: what the pen of a real, imperfect five-bar draws (issue 13), for the simulated
// machine. It follows the motors' commanded angles (degrees, the G-code X/Y frame) and records
// the pen's true path in the machine (base) frame, millimetres, while the pen is down:
//   motor angle -> backlash (per motor, core's play model, fivebar::PlayState of
//   core/calibration/backlash.hpp, the model the planner's compensation assumes: the drive's
//   output a stays within [m, m + b] of the motor m, pushed along at either side; at the start
//   it stands in the middle of that band) -> true angle = output + zero offset -> forward
//   kinematics of the true geometry (and its pen offset, if any).
// The true machine is a profile whose geometry is the true geometry and whose `calibration`
// section gives the true zero offsets, backlash and pen offset; without a calibration section
// it is perfect. Pure logic.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/calibration/backlash.hpp"
#include "core/calibration/model.hpp"
#include "core/machine/profile.hpp"

namespace fivebar::sim {

class PenTrace {
 public:
  explicit PenTrace(const MachineProfile& trueMachine);

  // Another true machine from now on (the studio's simulated-machine settings changed while the
  // machine is open): what was drawn stays, the current polyline ends, the motors stay where
  // they are and the play starts in the middle of its band again.
  void setMachine(const MachineProfile& trueMachine);

  // The motors stand at `commandedDeg` without having moved there (power-up, a redefined
  // position): each output stands in the middle of its play band there; nothing is drawn.
  void place(const std::array<double, 2>& commandedDeg);
  // A joint-linear move of the motors from the last point to `commandedDeg`; drawn when penDown.
  void moveTo(const std::array<double, 2>& commandedDeg, bool penDown);
  // The pen touches the paper where it stands: a dot (a one-point polyline) until it moves.
  void touchDown() {
    if (!open_) penAt(out_, true);
  }
  // The pen leaves the paper: the current polyline ends.
  void liftPen() { open_ = false; }

  // What the pen drew: polylines in the machine frame, mm (points at least 0.01 mm apart, and
  // every move's end).
  const std::vector<std::vector<Vec2>>& polylines() const { return drawn_; }
  // The drive outputs (degrees) after the backlash, e.g. for tests.
  std::array<double, 2> outputDeg() const { return out_; }

 private:
  void penAt(const std::array<double, 2>& outputDeg, bool keep);  // keep: a move's end

  calibration::MachineParameters params_;
  AssemblyMode assembly_;
  MotorPlay play_;                          // rad
  PlayState arms_{MotorPlay{}, JointAngles{}};  // the drive outputs, rad
  double maxPieceDeg_;                      // the longest piece a move is cut into (one step)
  std::array<double, 2> motor_{0.0, 0.0};   // commanded angles, deg
  std::array<double, 2> out_{0.0, 0.0};     // drive outputs, deg
  bool open_ = false;                       // a polyline is being drawn
  std::vector<std::vector<Vec2>> drawn_;
};

}  // namespace fivebar::sim
