// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_timeline.hpp"

#include <algorithm>
#include <cmath>

#include "core/planning/time_estimate.hpp"
#include "drivers/protocol/gcode_words.hpp"

namespace fivebar::stream {

double JobTimeline::remainingS(std::optional<std::size_t> lastCompleted) const {
  if (!lastCompleted) return totalS();
  if (*lastCompleted >= lineEndS.size()) return 0.0;
  return std::max(0.0, totalS() - lineEndS[*lastCompleted]);
}

JobTimeline timelineOf(const GcodeJob& job, const MachineProfile& profile) {
  const JobRules rules = rulesFor(profile);
  const double zTravelMm = std::abs(profile.tool.zUpMm - profile.tool.zDownMm);
  std::vector<GrblBlockInput> inputs;
  std::vector<std::optional<std::size_t>> inputOfLine(job.lines.size());
  std::array<double, 2> at = rules.startDeg;
  bool penDown = false;
  for (std::size_t i = 0; i < job.lines.size(); ++i) {
    const JobLine& line = job.lines[i];
    GrblBlockInput in;
    if (line.motion) {
      in.delta = {line.endDeg[0] - at[0], line.endDeg[1] - at[1], 0.0};
      if (profile.tool.kind == ToolKind::ZAxis && line.penDownAfter != penDown) in.delta.z() = zTravelMm;
      in.feedPerS = line.rapidModal ? 1e12 : line.feedPerMin / 60.0;  // G0: the axes' max rates
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
    inputOfLine[i] = inputs.size();
    inputs.push_back(in);
  }
  const std::vector<GrblBlockTiming> timing = estimateBlocks(inputs, grblTimeModelOf(profile));
  std::vector<double> inputEndS(timing.size());
  double clock = 0.0;
  for (std::size_t k = 0; k < timing.size(); ++k) inputEndS[k] = clock += timing[k].durationS;
  JobTimeline out;
  out.lineEndS.resize(job.lines.size());
  double last = 0.0;
  for (std::size_t i = 0; i < job.lines.size(); ++i) {
    if (inputOfLine[i]) last = inputEndS[*inputOfLine[i]];
    out.lineEndS[i] = last;
  }
  return out;
}

}  // namespace fivebar::stream
