// SPDX-License-Identifier: GPL-3.0-or-later
// The canvas's click-to-go-to as the session plans it: the jog planner's checked joint-space
// path from where a new jog starts to the clicked point, cut by the board's part of the one
// motion check, and the pen's path along it for the canvas to draw.
#pragma once

#include <vector>

#include "core/kinematics/geometry.hpp"
#include "core/machine/profile.hpp"
#include "session/machine_ports.hpp"

namespace fivebar::session {

jog::JogPlan planGoTo(const JogPort& jog, const MachineProfile& profile, const JointAngles& start,
                      const Vec2& targetMm);
// The pen's path (machine frame, mm) along the plan, from `start`.
std::vector<Vec2> goToPenPathMm(const MachineProfile& profile, const JointAngles& start,
                                const jog::JogPlan& plan);

}  // namespace fivebar::session
