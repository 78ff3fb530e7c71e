// SPDX-License-Identifier: GPL-3.0-or-later
// Resuming a job from its last completed pen-down point: pen up, a safe travel (core/safety.hpp
// planSafeTravel, every leg checked) from where the machine is to that point's joint angles,
// pen down when the point lies inside a stroke, the job's modal feed, then the rest of the job.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/machine/profile.hpp"
#include "gcode_job.hpp"

namespace fivebar::stream {

enum class ResumeStatus { Ok, RelativeMoves, NoSafeTravel, UnknownLine };

struct ResumePlan {
  ResumeStatus status = ResumeStatus::Ok;
  std::string message;                // why not, naming the line and the angles
  std::vector<std::string> preamble;  // sent before the job lines
  std::size_t continueFrom = 0;       // index into GcodeJob::lines
  bool ok() const { return status == ResumeStatus::Ok; }
};

// penDownPoint: index of the last completed pen-down point (nullopt: start over from the
// beginning, still with a safe pen-up travel to the job's start). current: the machine's motor
// angles (continuous, rad), from a status report.
ResumePlan planResume(const GcodeJob& job, std::optional<std::size_t> penDownPoint,
                      const MachineProfile& profile, const JointAngles& current);

// The index of the line with this 1-based file line number; nullopt when absent.
std::optional<std::size_t> indexOfFileLine(const GcodeJob& job, int fileLine);

}  // namespace fivebar::stream
