// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/time_estimate.hpp"
#include "core/planning/grbl_block_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/support/memory_hint.hpp"
#include "core/support/parallel.hpp"
#include "core/kinematics/units.hpp"


namespace fivebar {
namespace {

using namespace grbl_model;  // the block planner (grbl_block_planner.hpp)

// Whether GRBL's planner empties its buffer at this move (M3/M5 outside laser mode, G4, M0).
bool synchronises(const JobMove& m, ToolKind tool) {
  switch (m.kind) {
    case JobMoveKind::PenUp:
    case JobMoveKind::PenDown: return tool == ToolKind::PenServo;
    case JobMoveKind::Dwell:
    case JobMoveKind::Pause: return true;
    case JobMoveKind::Draw:
    case JobMoveKind::Travel: return false;
  }
  return false;
}

// A run of moves [begin, end) the planner can time on its own: it starts at the job start or at
// a synchronising move (the machine at rest, nothing of the planner state crosses it), from the
// joint position `at` and Z height `z` the moves before it left.
struct JobPart {
  size_t begin = 0, end = 0;
  JointAngles at;
  double z = 0.0;
};

// The part [begin, end), begin being 0 or a synchronising move: where the moves before it left
// the joints and Z.
JobPart partFrom(const PlannedJob& job, const MachineProfile& profile, size_t begin, size_t end) {
  JobPart part{begin, end, job.start, profile.tool.zUpMm};
  bool haveAt = false, haveZ = profile.tool.kind != ToolKind::ZAxis;
  for (size_t i = begin; i-- > 0 && !(haveAt && haveZ);) {
    const JobMove& m = job.moves[i];
    if (!haveAt && isMotion(m.kind)) {
      part.at = m.target;
      haveAt = true;
    } else if (!haveZ && (m.kind == JobMoveKind::PenUp || m.kind == JobMoveKind::PenDown)) {
      part.z = m.toolValue;
      haveZ = true;
    }
  }
  return part;
}

// Jobs smaller than this are timed in one part: a thread costs more than it saves.
constexpr size_t kMinMovesToSplit = 20000;

// One part, or two cut at the synchronising move nearest the middle (searched within the middle
// half). Depends on the job only, so the figures do not depend on the thread count.
std::vector<JobPart> jobParts(const PlannedJob& job, const MachineProfile& profile) {
  const size_t n = job.moves.size();
  std::vector<JobPart> parts(1);
  parts[0] = {0, n, job.start, profile.tool.zUpMm};
  if (n < kMinMovesToSplit) return parts;
  size_t cut = 0;
  for (size_t d = 0; d < n / 4 && cut == 0; ++d) {
    if (synchronises(job.moves[n / 2 + d], profile.tool.kind)) cut = n / 2 + d;
    else if (synchronises(job.moves[n / 2 - d], profile.tool.kind)) cut = n / 2 - d;
  }
  if (cut == 0) return parts;
  parts[0].end = cut;
  parts.push_back(partFrom(job, profile, cut, n));
  return parts;
}

// Decimals of the joint angles in the G-code (core/output/gcode.cpp).
constexpr double kGcodeAngleScale = 1e4;

// What GRBL plans is the step-rounded move: the target in steps is lround(target x $100), the
// target as the G-code prints it (4 decimals of a degree) and relative to the pose the job starts
// from (where the reference pose is set, G10 L20), and the block's length and direction (and so
// its junction speeds) come from the step counts. On short moves the rounding turns the joint
// direction by up to a degree, which lowers GRBL's junction speeds on curves: measured on the
// firmware, about 1 % of a 200 mm/s job.
class StepGrid {
 public:
  StepGrid(const MachineProfile& p, const JointAngles& start)
      : stepsPerDeg_{p.motors.stepsPerDeg1, p.motors.stepsPerDeg2},
        startDeg_{printed(degFromRad(start.theta1)), printed(degFromRad(start.theta2))} {}
  // Joint-space delta (deg) GRBL plans for the move from `a` to `b`.
  void delta(const JointAngles& a, const JointAngles& b, double out[2]) const {
    out[0] = (steps(0, b.theta1) - steps(0, a.theta1)) / stepsPerDeg_[0];
    out[1] = (steps(1, b.theta2) - steps(1, a.theta2)) / stepsPerDeg_[1];
  }

 private:
  static double printed(double deg) { return std::round(deg * kGcodeAngleScale) / kGcodeAngleScale; }
  double steps(int axis, double rad) const {
    return static_cast<double>(
        std::llround((printed(degFromRad(rad)) - startDeg_[axis]) * stepsPerDeg_[axis]));
  }
  double stepsPerDeg_[2];
  double startDeg_[2];
};

// Feeds a part of a job's moves, as the G-code sends them, to a Planner (or to the collector of
// grblInputsOf): motion(input, delta, feedPerS) for a block, sync(input, dwellS) for a
// synchronising command, nothing for a laser's tool moves (the S word rides on the next G1).
template <class Consumer>
void feedJob(const PlannedJob& job, const MachineProfile& profile, const JobPart& part,
             Consumer& planner) {
  JointAngles at = part.at;
  double z = part.z;
  const double zFeedPerS = profile.tool.zFeedMmPerMin / 60.0;
  const StepGrid grid(profile, job.start);
  for (size_t i = part.begin; i < part.end; ++i) {
    const JobMove& mv = job.moves[i];
    switch (mv.kind) {
      case JobMoveKind::Draw:
      case JobMoveKind::Travel: {
        double delta[3] = {0.0, 0.0, 0.0};
        grid.delta(at, mv.target, delta);
        planner.motion(i, delta, degFromRad(mv.jointFeedRadPerS));
        at = mv.target;
        break;
      }
      case JobMoveKind::PenUp:
      case JobMoveKind::PenDown:
        if (profile.tool.kind == ToolKind::PenServo) {
          planner.sync(i, mv.dwellS);  // M3/M5 empty the planner buffer outside laser mode
        } else if (profile.tool.kind == ToolKind::ZAxis) {
          const double delta[3] = {0.0, 0.0, mv.toolValue - z};
          planner.motion(i, delta, zFeedPerS);
          z = mv.toolValue;
        }  // laser: the S word rides on the next G1, no block of its own
        break;
      case JobMoveKind::Dwell: planner.sync(i, mv.dwellS); break;
      case JobMoveKind::Pause: planner.sync(i, 0.0); break;
    }
  }
}

// grblInputsOf's consumer for feedJob.
struct InputCollector {
  std::vector<GrblBlockInput>& inputs;
  void motion(size_t i, const double delta[3], double feedPerS) {
    inputs[i].delta = {delta[0], delta[1], delta[2]};
    inputs[i].feedPerS = feedPerS;
  }
  void sync(size_t i, double dwellS) {
    inputs[i].sync = true;
    inputs[i].dwellS = dwellS;
  }
};

// Times the job's moves (durations, start times, total) in one or two parts on up to two threads,
// and with `timings` also returns every move's timing (each part writes its own slice). The parts
// are independent and the start times are summed in move order afterwards, so the figures are
// those of one sequential pass.
void timeJob(PlannedJob& job, const MachineProfile& profile, std::vector<GrblBlockTiming>* timings) {
  const GrblTimeModel model = grblTimeModelOf(profile);
  const std::vector<JobPart> parts = jobParts(job, profile);
  std::vector<double> partClockS(parts.size(), 0.0);
  if (timings != nullptr) {
    reserveWithHugePages(*timings, job.moves.size());
    timings->resize(job.moves.size());
  }
  parallelFor(parts.size(), planningThreads(), [&](size_t k) {
    TimingSink sink(timings != nullptr ? timings->data() : nullptr, 0, &job.moves, parts[k].begin, k == 0);
    Planner planner(model, sink);
    feedJob(job, profile, parts[k], planner);
    planner.endChain();
    sink.close(parts[k].end);
    partClockS[k] = sink.clockS();
  });
  double clockS = partClockS[0];
  for (size_t k = 1; k < parts.size(); ++k) {
    for (size_t i = parts[k].begin; i < parts[k].end; ++i) {
      job.moves[i].startTimeS = clockS;
      clockS += job.moves[i].durationS;
    }
  }
  job.summary.estimatedTimeS = clockS;
}

}  // namespace

GrblTimeModel grblTimeModelOf(const MachineProfile& profile) {
  GrblTimeModel m;
  const MotorSettings& s = profile.motors;
  m.maxRatePerS = {degFromRad(s.maxSpeedRadPerS1), degFromRad(s.maxSpeedRadPerS2),
                   profile.tool.zFeedMmPerMin / 60.0};
  m.accelPerS2 = {degFromRad(s.maxAccelRadPerS2_1), degFromRad(s.maxAccelRadPerS2_2),
                  kZAccelMmPerS2};
  m.junctionDeviation = s.junctionDeviationDeg;
  return m;
}

std::vector<GrblBlockTiming> estimateBlocks(const std::vector<GrblBlockInput>& inputs,
                                            const GrblTimeModel& model) {
  std::vector<GrblBlockTiming> out;
  reserveWithHugePages(out, inputs.size());
  out.resize(inputs.size());
  TimingSink sink(out.data(), 0, nullptr, 0, false);
  Planner planner(model, sink);
  for (size_t i = 0; i < inputs.size(); ++i) {
    const GrblBlockInput& in = inputs[i];
    if (in.sync) {
      planner.sync(i, in.dwellS);
    } else {
      const double delta[3] = {in.delta.x(), in.delta.y(), in.delta.z()};
      planner.motion(i, delta, in.feedPerS);
    }
  }
  planner.endChain();
  sink.close(inputs.size());
  return out;
}

double distanceAt(const GrblBlockTiming& b, double t) {
  if (b.lengthUnits <= 0.0 || b.accelPerS2 <= 0.0) return 0.0;
  const double a = b.accelPerS2, v0 = b.entryPerS, v1 = b.exitPerS;
  double vp = b.nominalPerS;
  double accelDist = (vp * vp - v0 * v0) / (2.0 * a);
  double decelDist = (vp * vp - v1 * v1) / (2.0 * a);
  if (accelDist + decelDist > b.lengthUnits) {
    vp = std::sqrt(std::max(0.0, (2.0 * a * b.lengthUnits + v0 * v0 + v1 * v1) / 2.0));
    accelDist = std::max(0.0, (vp * vp - v0 * v0) / (2.0 * a));
    decelDist = std::max(0.0, (vp * vp - v1 * v1) / (2.0 * a));
  }
  const double cruise = std::max(0.0, b.lengthUnits - accelDist - decelDist);
  const double t1 = std::max(0.0, (vp - v0) / a);
  const double tc = vp > 0.0 ? cruise / vp : 0.0;
  double s;
  if (t <= t1) {
    s = v0 * t + 0.5 * a * t * t;
  } else if (t <= t1 + tc) {
    s = accelDist + vp * (t - t1);
  } else {
    const double tau = t - t1 - tc;
    s = accelDist + cruise + vp * tau - 0.5 * a * tau * tau;
  }
  return std::clamp(s, 0.0, b.lengthUnits);
}

std::vector<GrblBlockInput> grblInputsOf(const PlannedJob& job, const MachineProfile& profile) {
  std::vector<GrblBlockInput> inputs(job.moves.size());
  InputCollector collector{inputs};
  feedJob(job, profile, JobPart{0, job.moves.size(), job.start, profile.tool.zUpMm}, collector);
  return inputs;
}

std::vector<GrblBlockTiming> estimateJobTime(PlannedJob& job, const MachineProfile& profile) {
  std::vector<GrblBlockTiming> timings;
  timeJob(job, profile, &timings);
  return timings;
}

void fillJobTimes(PlannedJob& job, const MachineProfile& profile) { timeJob(job, profile, nullptr); }

TimedChain timeChainAround(const PlannedJob& job, const MachineProfile& profile, size_t moveIndex) {
  const size_t n = job.moves.size();
  TimedChain chain;
  if (moveIndex >= n) return chain;
  const ToolKind tool = profile.tool.kind;
  size_t begin = moveIndex;
  while (begin > 0 && !synchronises(job.moves[begin], tool)) --begin;
  size_t end = moveIndex + 1;
  while (end < n && !synchronises(job.moves[end], tool)) ++end;
  const JobPart part = partFrom(job, profile, begin, end);
  chain.begin = begin;
  chain.end = end;
  chain.timings.resize(end - begin);
  TimingSink sink(chain.timings.data(), begin, nullptr, begin, false);
  const GrblTimeModel model = grblTimeModelOf(profile);
  Planner planner(model, sink);
  feedJob(job, profile, part, planner);
  planner.endChain();
  sink.close(end);
  return chain;
}

}  // namespace fivebar
