// SPDX-License-Identifier: GPL-3.0-or-later
// The G-code reader used by `fivebar stream`, `send` and resume (parseJob, strokesOf,
// lastPenDownPoint, planResume) and the file check every job passes before its first byte
// (checkFile), on the maker-plotter preset. Asserts: line numbers increase; a line over GRBL's
// 80 characters is an issue; a job the check passes has finite targets inside the joint limits.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "core/machine/profile.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/stream/resume.hpp"
#include "fuzz_check.hpp"

namespace {
const fivebar::MachineProfile& profile() {
  static const fivebar::MachineProfile p = *fivebar::preset("maker-plotter");
  return p;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar;
  const std::string_view text = fuzz::asText(data, size);
  const stream::JobRules rules = stream::rulesFor(profile());
  const stream::GcodeJob job = stream::parseJob(text, rules);
  int lastLine = 0;
  bool longLine = false;
  for (const stream::JobLine& line : job.lines) {
    FUZZ_CHECK(line.fileLine > lastLine, "file line numbers do not increase");
    lastLine = line.fileLine;
    FUZZ_CHECK(!line.text.empty(), "an empty job line");
    longLine = longLine || line.text.size() > 80;
  }
  FUZZ_CHECK(!longLine || !job.issues.empty(), "a line over 80 characters without an issue");
  const auto strokes = stream::strokesOf(job, rules);
  if (!job.lines.empty()) {
    const auto point = stream::lastPenDownPoint(job, job.lines.size() - 1);
    FUZZ_CHECK(!point || *point < job.lines.size(), "a pen-down point past the last line");
    if (job.issues.empty() && !job.relativeMoves) {
      const stream::ResumePlan plan = stream::planResume(job, point, profile(), profile().homeAngles);
      FUZZ_CHECK(plan.ok() || !plan.message.empty(), "a refused resume without a reason");
      FUZZ_CHECK(!plan.ok() || plan.continueFrom <= job.lines.size(), "resume past the end");
    }
  }
  (void)motion::readJobHeader(text);
  const motion::FileCheck check = motion::checkFile(profile(), text, std::nullopt);
  FUZZ_CHECK(check.ok || !check.reason.empty(), "a refused file without a reason");
  if (check.ok && job.issues.empty()) {
    constexpr double kDeg = 180.0 / std::numbers::pi;
    const JointLimits& limits = profile().limits;
    constexpr double kSlackDeg = 1e-6;
    for (const stream::JobLine& line : job.lines) {
      if (!line.motion) continue;
      const double t1 = line.endDeg[0], t2 = line.endDeg[1];
      FUZZ_CHECK(std::isfinite(t1) && std::isfinite(t2), "a checked target that is not finite");
      FUZZ_CHECK(t1 >= limits.theta1Min * kDeg - kSlackDeg && t1 <= limits.theta1Max * kDeg + kSlackDeg &&
                     t2 >= limits.theta2Min * kDeg - kSlackDeg && t2 <= limits.theta2Max * kDeg + kSlackDeg,
                 "a checked target outside the joint limits at line " + std::to_string(line.fileLine));
    }
  }
  return 0;
}
