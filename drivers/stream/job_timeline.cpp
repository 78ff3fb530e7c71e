// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "drivers/protocol/gcode_words.hpp"

namespace fivebar::stream {
namespace {

// planner.c limit_value_by_axis_maximum: the highest rate along delta that no axis's $11x exceeds.
double rapidRatePerS(const Eigen::Vector3d& delta, const GrblTimeModel& model) {
  const double length = delta.norm();
  double rate = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (std::abs(delta[i]) > 0.0) rate = std::min(rate, model.maxRatePerS[i] * length / std::abs(delta[i]));
  return rate;
}

// The line end times from the model's inputs, at these overrides.
std::vector<double> lineEndsOf(const JobTimeline& t, const grbl::MotionOverrides& ov) {
  std::vector<GrblBlockInput> inputs = t.inputs;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    GrblBlockInput& in = inputs[k];
    if (in.sync) continue;
    // estimateBlocks clamps every rate at the axes' max rates, as GRBL caps the overridden one.
    in.feedPerS = t.rapidInput[k] ? rapidRatePerS(in.delta, t.model) * 0.01 * ov.rapidPct
                                  : in.feedPerS * 0.01 * ov.feedPct;
  }
  const std::vector<GrblBlockTiming> timing = estimateBlocks(inputs, t.model);
  std::vector<double> inputEndS(timing.size());
  double clock = 0.0;
  for (std::size_t k = 0; k < timing.size(); ++k) inputEndS[k] = clock += timing[k].durationS;
  std::vector<double> out(t.inputOfLine.size());
  double last = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (t.inputOfLine[i] >= 0) last = inputEndS[std::size_t(t.inputOfLine[i])];
    out[i] = last;
  }
  return out;
}

}  // namespace

double JobTimeline::remainingS(std::optional<std::size_t> lastCompleted) const {
  if (!lastCompleted) return totalS();
  if (*lastCompleted >= lineEndS.size()) return 0.0;
  return std::max(0.0, totalS() - lineEndS[*lastCompleted]);
}

JobTimeline JobTimeline::overridden(const grbl::MotionOverrides& overrides) const {
  JobTimeline out = *this;
  out.lineEndS = lineEndsOf(*this, overrides);
  return out;
}

JobTimeline timelineOf(const GcodeJob& job, const MachineProfile& profile) {
  const JobRules rules = rulesFor(profile);
  const double zTravelMm = std::abs(profile.tool.zUpMm - profile.tool.zDownMm);
  JobTimeline out;
  out.model = grblTimeModelOf(profile);
  out.inputOfLine.assign(job.lines.size(), -1);
  std::array<double, 2> at = rules.startDeg;
  bool penDown = false;
  for (std::size_t i = 0; i < job.lines.size(); ++i) {
    const JobLine& line = job.lines[i];
    GrblBlockInput in;
    if (line.motion) {
      in.delta = {line.endDeg[0] - at[0], line.endDeg[1] - at[1], 0.0};
      if (profile.tool.kind == ToolKind::ZAxis && line.penDownAfter != penDown) in.delta.z() = zTravelMm;
      in.feedPerS = line.rapidModal ? 0.0 : line.feedPerMin / 60.0;  // G0: set by lineEndsOf
      if (in.delta.norm() <= 0.0) continue;
    } else {
      const gcode::Words w = gcode::parseWords(line.text);
      if (!w.ok()) continue;
      const bool spindle = w.hasCode('M', 3) || w.hasCode('M', 4) || w.hasCode('M', 5);
      const bool dwell = w.hasCode('G', 4);
      if (!spindle && !dwell) continue;
      in.sync = true;
      if (dwell) in.dwellS = std::max(0.0, w.get('P').value_or(0.0));
    }
    at = line.endDeg;
    penDown = line.penDownAfter;
    out.inputOfLine[i] = std::int64_t(out.inputs.size());
    out.rapidInput.push_back(line.motion && line.rapidModal);
    out.inputs.push_back(in);
  }
  out.lineEndS = lineEndsOf(out, grbl::MotionOverrides{});
  return out;
}

}  // namespace fivebar::stream
