// Checked jog and go-to planning for the machine panels: every move the jog panel, the keyboard
// and the canvas go-to send is planned here as joint-space "$J=" targets, and every sub-move is
// checked with core/safety.hpp checkJointMove before it may be sent. Pure functions, no Qt.
//
// A Cartesian jog follows the straight XY line in sub-moves short enough that the joint-linear
// path GRBL interpolates stays within kJogChordToleranceMm of that line; it stops at the last
// safe point before the workspace edge, a joint limit or the singularity margin (conventions.md:
// a jog is never sent as one joint-space move to the edge). Units: mm, rad, s; F in deg/min.
#pragma once

#include <string>
#include <vector>

#include "core/kinematics.hpp"
#include "core/profile.hpp"

namespace fivebar::widgets {

// Largest distance (mm) between the pen's joint-linear path and the straight XY jog line.
inline constexpr double kJogChordToleranceMm = 0.05;
// Longest Cartesian sub-move (mm); shorter where the chord tolerance demands it.
inline constexpr double kJogMaxSubMoveMm = 2.0;
// Shortest sub-move tried before the line is declared impossible to follow (mm).
inline constexpr double kJogMinSubMoveMm = 0.005;
// Longest per-motor sub-move (rad), so a clipped motor jog stops close to the limit.
inline constexpr double kMotorJogPieceRad = 0.5 * kPi / 180.0;

// One "$J=G90" target: absolute continuous motor angles and the joint-space feed.
struct JogTarget {
  JointAngles q;
  double feedDegPerMin = 0.0;
};

enum class JogStatus {
  Full,     // the whole requested move is planned
  Clipped,  // planned up to the last safe point; reason says what stopped it
  Refused,  // not even a first sub-move is safe; nothing to send
};

struct JogPlan {
  JogStatus status = JogStatus::Refused;
  std::vector<JogTarget> moves;  // in order; empty when refused
  std::string reason;            // why clipped or refused (English; shown in the panel)
  std::vector<Vec2> pathMm;      // the pen's path (machine frame), first point = start
  bool ok() const { return status != JogStatus::Refused; }
  JointAngles end(const JointAngles& start) const { return moves.empty() ? start : moves.back().q; }
};

// Straight XY jog by deltaMm from the pose at `current` (continuous angles), in the working mode
// of that pose and the profile's assembly mode, at speedMmPerS along the line.
JogPlan planCartesianJog(const MachineProfile& profile, const JointAngles& current, Vec2 deltaMm,
                         double speedMmPerS);

// Jog of one motor (motorIndex 1 or 2) by deltaRad at speedRadPerS.
JogPlan planMotorJog(const MachineProfile& profile, const JointAngles& current, int motorIndex,
                     double deltaRad, double speedRadPerS);

// Go-to: a safe travel (core planSafeTravel, every leg checked) from `current` to the pose that
// puts the pen at targetMm in the current working mode, at roughly speedMmPerS.
JogPlan planGoTo(const MachineProfile& profile, const JointAngles& current, Vec2 targetMm,
                 double speedMmPerS);

// "$J=G90 X12.345 Y-6.789 F1234.5": X = theta1, Y = theta2 in degrees (conventions.md).
std::string jogLine(const JogTarget& target);

}  // namespace fivebar::widgets
