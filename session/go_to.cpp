// SPDX-License-Identifier: GPL-3.0-or-later
// The go-to planned. Contract: go_to.hpp.
#include "session/go_to.hpp"

namespace fivebar::session {

jog::JogPlan planGoTo(const JogPort& jog, const MachineProfile& profile, const JointAngles& start,
                      const Vec2& targetMm) {
  return jog.boardChecked(jog::planGoTo(profile, start, targetMm), false);
}

std::vector<Vec2> goToPenPathMm(const MachineProfile& profile, const JointAngles& start,
                                const jog::JogPlan& plan) {
  return jog::penPathMm(profile, start, plan);
}

}  // namespace fivebar::session
