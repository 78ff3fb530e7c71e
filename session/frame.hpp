// SPDX-License-Identifier: GPL-3.0-or-later
// The Frame button as the session plans it: the job's outline (jog::planFrame: convex hull of
// its pen-down points) traced pen up (a laser at low power) along checked joint-space moves from
// where a new jog starts, read from the very G-code Start would stream, then cut by the board's
// part of the one motion check (JogPort::boardChecked). MachineSession::frameJob sends it.
#pragma once

#include "core/machine/profile.hpp"
#include "core/planning/job.hpp"
#include "session/machine_ports.hpp"

namespace fivebar::session {

// Frame speed: the profile's drawing speed, so that the outline is traced as the job is drawn.
jog::JogPlan planJobFrame(const JogPort& jog, const MachineProfile& profile, const JointAngles& start,
                          const PlannedJob& job, jog::FrameShape shape = jog::FrameShape::ConvexHull);

}  // namespace fivebar::session
