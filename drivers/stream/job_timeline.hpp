// SPDX-License-Identifier: GPL-3.0-or-later
// The time line of a G-code job: for each job line, the machine time (s) at which it has been
// executed, from GRBL's own planning model (core/planning/time_estimate: trapezoids, junction
// speeds, look-ahead, synchronising pen commands and dwells) fed with the job's lines as the
// board reads them. The studio's run ETA is the job's end time minus the time of the last line
// the machine reports executed: it follows the plan, not a line-count extrapolation, and it does
// not move while the machine holds. Pure.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/machine/profile.hpp"
#include "gcode_job.hpp"

namespace fivebar::stream {

struct JobTimeline {
  std::vector<double> lineEndS;  // per job line: machine time when it is done (non-decreasing)
  double totalS() const { return lineEndS.empty() ? 0.0 : lineEndS.back(); }
  // Time left once line `lastCompleted` is executed (the whole job when nullopt).
  double remainingS(std::optional<std::size_t> lastCompleted) const;
};

JobTimeline timelineOf(const GcodeJob& job, const MachineProfile& profile);

}  // namespace fivebar::stream
