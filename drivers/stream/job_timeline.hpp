// SPDX-License-Identifier: GPL-3.0-or-later
// The time line of a G-code job: for each job line, the machine time (s) at which it has been
// executed, from GRBL's own planning model (core/planning/time_estimate: trapezoids, junction
// speeds, look-ahead, synchronising pen commands and dwells) fed with the job's lines as the
// board reads them. The run ETA is the job's end time minus the time of the last line the
// machine reports executed: it follows the plan, not a line-count extrapolation, and it does not
// move while the machine holds. Under a feed or rapid override the job is planned again with the
// overridden rates (overridden()). JobRunner takes its ETA from here, so `fivebar stream` and the
// studio's Run panel show the same one. Pure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/machine/profile.hpp"
#include "core/planning/time_estimate.hpp"
#include "drivers/protocol/overrides.hpp"
#include "gcode_job.hpp"

namespace fivebar::stream {

struct JobTimeline {
  std::vector<double> lineEndS;  // per job line: machine time when it is done (non-decreasing)
  double totalS() const { return lineEndS.empty() ? 0.0 : lineEndS.back(); }
  // Time left once line `lastCompleted` is executed (the whole job when nullopt).
  double remainingS(std::optional<std::size_t> lastCompleted) const;

  // The same job's time line as GRBL 1.1h runs it under these overrides (planner.c
  // plan_compute_profile_nominal_speed): every G1 at its F x the feed override, capped at the
  // block's rapid rate (the highest speed $110/$111/$112 allow along it), every G0 at the rapid
  // rate x the rapid override; accelerations, junctions and look-ahead re-planned with them, so
  // the ramps are right too. The ETA under an override is remainingS() of this: the time the
  // rest of the job takes when it runs at those overrides. An approximation only where the
  // override changed: the block under way then, and the few blocks GRBL had already planned at
  // the old speeds, are counted at the new ones. O(lines): recompute on a change, not per poll.
  JobTimeline overridden(const grbl::MotionOverrides& overrides) const;

  // What overridden() plans from: the model's input of each job line that takes time (G0 inputs
  // with feedPerS 0: at the rapid rate), and the GRBL model of the profile.
  std::vector<GrblBlockInput> inputs;
  std::vector<std::int64_t> inputOfLine;  // per job line: index into inputs, -1 for none
  std::vector<bool> rapidInput;           // per input: a G0 move
  GrblTimeModel model;
};

JobTimeline timelineOf(const GcodeJob& job, const MachineProfile& profile);

}  // namespace fivebar::stream
