// SPDX-License-Identifier: GPL-3.0-or-later
// The frame planned. Contract: frame.hpp.
#include "session/frame.hpp"

#include "core/output/gcode.hpp"
#include "drivers/stream/gcode_job.hpp"

namespace fivebar::session {

jog::JogPlan planJobFrame(const JogPort& jog, const MachineProfile& profile, const JointAngles& start,
                          const PlannedJob& job, jog::FrameShape shape) {
  const stream::JobRules rules = stream::rulesFor(profile);
  const stream::GcodeJob gcode = stream::parseJob(writeGcode(job, profile), rules);
  return jog.boardChecked(jog::planFrame(profile, start, gcode, rules, shape, profile.drawSpeedMmPerS), false);
}

}  // namespace fivebar::session
