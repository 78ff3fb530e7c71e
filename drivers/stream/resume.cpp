// SPDX-License-Identifier: GPL-3.0-or-later
#include "resume.hpp"

#include <algorithm>
#include <cstdio>

#include "core/planning/safety.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::stream {
namespace {

std::string anglesText(const Point2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f) deg", p[0], p[1]);
  return buf;
}

}  // namespace

std::optional<std::size_t> indexOfFileLine(const GcodeJob& job, int fileLine) {
  const auto it = std::lower_bound(job.lines.begin(), job.lines.end(), fileLine,
                                   [](const JobLine& l, int n) { return l.fileLine < n; });
  if (it == job.lines.end() || it->fileLine != fileLine) return std::nullopt;
  return std::size_t(it - job.lines.begin());
}

ResumePlan planResume(const GcodeJob& job, std::optional<std::size_t> penDownPoint,
                      const MachineProfile& profile, const JointAngles& current) {
  ResumePlan plan;
  if (job.relativeMoves) {
    plan.status = ResumeStatus::RelativeMoves;
    plan.message = "the job uses relative moves (G91): resume needs absolute targets";
    return plan;
  }
  if (penDownPoint && *penDownPoint >= job.lines.size()) {
    plan.status = ResumeStatus::UnknownLine;
    plan.message = "the saved resume point lies beyond the end of the job";
    return plan;
  }
  const Point2 targetDeg = penDownPoint ? job.lines[*penDownPoint].endDeg
                                        : Point2{degFromRad(profile.homeAngles.theta1),
                                                 degFromRad(profile.homeAngles.theta2)};
  const JointAngles target{radFromDeg(targetDeg[0]), radFromDeg(targetDeg[1])};
  const auto travel = planSafeTravel(profile, current, target);
  if (!travel) {
    plan.status = ResumeStatus::NoSafeTravel;
    plan.message = "no safe pen-up travel from " +
                   anglesText({degFromRad(current.theta1), degFromRad(current.theta2)}) + " to " +
                   anglesText(targetDeg) +
                   (penDownPoint ? " (line " + std::to_string(job.lines[*penDownPoint].fileLine) + ")"
                                 : std::string(" (the job's start)"));
    return plan;
  }
  plan.preamble.push_back("G90");
  for (const std::string& s : penUpCommands(profile.tool)) plan.preamble.push_back(s);
  for (const JointAngles& q : *travel)
    plan.preamble.push_back(moveTo({degFromRad(q.theta1), degFromRad(q.theta2)}, true));
  if (penDownPoint) {
    const JobLine& at = job.lines[*penDownPoint];
    if (at.penDownAfter)
      for (const std::string& s : penDownCommands(profile.tool)) plan.preamble.push_back(s);
    // Restore the job's modal motion and feed: the travel above left G0 in effect.
    char buf[40];
    if (at.rapidModal) std::snprintf(buf, sizeof buf, "G0");
    else if (at.feedPerMin > 0.0) std::snprintf(buf, sizeof buf, "G1F%.1f", at.feedPerMin);
    else std::snprintf(buf, sizeof buf, "G1");
    plan.preamble.push_back(buf);
    plan.continueFrom = *penDownPoint + 1;
  }
  return plan;
}

}  // namespace fivebar::stream
