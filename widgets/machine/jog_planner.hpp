// The machine panels' view of the drivers' checked jog planning (drivers/jog.hpp): every move the
// jog panel, the keyboard and the canvas go-to send is planned there (straight XY lines in short
// checked $J= sub-moves, clipped at the last safe point; per-motor jogs clipped at limits and
// margins; go-to by a safe travel), and this adapter adds what the UI needs on top: a status
// the panels can word, and the pen's path (machine frame) for the canvas preview. Pure, no Qt.
#pragma once

#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"

namespace fivebar::widgets {

// Largest distance (mm) between the pen's joint-linear path and the straight XY jog line.
inline constexpr double kJogChordToleranceMm = 0.05;

enum class JogStatus {
  Full,     // the whole requested move is planned
  Clipped,  // planned up to the last safe point; reason says what stopped it
  Refused,  // not even a first sub-move is safe (or the position is unknown); nothing to send
};

struct JogPlan {
  JogStatus status = JogStatus::Refused;
  std::vector<std::string> lines;    // lines to send, in order ($J=, or pen-up and G0 for go-to)
  std::vector<JointAngles> targets;  // joint target of each motion line (continuous, rad)
  std::string reason;                // why clipped or refused (English, from the drivers)
  std::vector<Vec2> pathMm;          // the pen's path (machine frame), first point = start
  bool ok() const { return status != JogStatus::Refused && !lines.empty(); }
};

// Straight XY jog by deltaMm from the pose at `current`, at speedMmPerS along the line.
JogPlan planCartesianJog(const MachineProfile& profile, const JointAngles& current, Vec2 deltaMm,
                         double speedMmPerS);

// Jog of one motor (motorIndex 1 or 2) by deltaRad at speedRadPerS.
JogPlan planMotorJog(const MachineProfile& profile, const JointAngles& current, int motorIndex,
                     double deltaRad, double speedRadPerS);

// Go-to: pen up, then a safe travel (every leg checked) to the pose that puts the pen at
// targetMm in the current working mode.
JogPlan planGoTo(const MachineProfile& profile, const JointAngles& current, Vec2 targetMm);

}  // namespace fivebar::widgets
