// SPDX-License-Identifier: GPL-3.0-or-later
// What GRBL 1.1 executes, modelled to estimate a job's time: joint-space blocks (X = theta1 deg,
// Y = theta2 deg, Z mm) with trapezoidal speed profiles, per-axis rate and acceleration limits,
// junction speeds from the junction deviation ($11), a 15-block look-ahead window (the planner
// only knows the blocks in its buffer: the last one must be able to stop), synchronising
// commands (servo M3/M5, G4 dwell, M0) that empty the buffer, and dwells.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/planning/job.hpp"
#include "core/machine/profile.hpp"

namespace fivebar {

struct GrblTimeModel {
  Eigen::Vector3d maxRatePerS{180.0, 180.0, 10.0};  // $110..$112 in deg/s (X, Y), mm/s (Z)
  Eigen::Vector3d accelPerS2{1000.0, 1000.0, 100.0};  // $120..$122, deg/s^2 (X, Y), mm/s^2 (Z)
  double junctionDeviation = 0.01;  // $11, in the joint-space units (deg)
  int lookaheadBlocks = 15;         // planner buffer (16 slots, one kept free)
  double minJunctionSpeedPerS = 0.0;  // MINIMUM_JUNCTION_SPEED
};
// The profile's $ settings; Z rate from the tool's zFeedMmPerMin, Z acceleration 100 mm/s^2.
GrblTimeModel grblTimeModelOf(const MachineProfile& profile);

// One planner input: a motion block (delta != 0) or a synchronising command (sync = true: the
// motion before it stops completely, then dwellS passes).
struct GrblBlockInput {
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();  // X, Y in deg; Z in mm
  double feedPerS = 0.0;   // programmed F / 60: vector rate, units/s
  bool sync = false;
  double dwellS = 0.0;
};

// Execution of one input: trapezoid speeds along the block (units/s), its length and duration.
struct GrblBlockTiming {
  double lengthUnits = 0.0;
  double entryPerS = 0.0;
  double nominalPerS = 0.0;  // cruise speed after the per-axis rate clamp
  double exitPerS = 0.0;
  double accelPerS2 = 0.0;   // after the per-axis acceleration clamp
  double durationS = 0.0;    // motion time, plus dwellS for a sync input
};

std::vector<GrblBlockTiming> estimateBlocks(const std::vector<GrblBlockInput>& inputs,
                                            const GrblTimeModel& model);

// Distance covered after `t` seconds into a block with this timing (0 <= t <= motion duration).
double distanceAt(const GrblBlockTiming& b, double t);

// The planner inputs a job's moves become (one per move, in order), as the G-code sends them.
std::vector<GrblBlockInput> grblInputsOf(const PlannedJob& job, const MachineProfile& profile);

// Fills every move's durationS and startTimeS and job.summary.estimatedTimeS; returns the
// per-move timings (for the trajectory). Uses up to planningThreads() threads on large jobs;
// the figures do not depend on the thread count.
std::vector<GrblBlockTiming> estimateJobTime(PlannedJob& job, const MachineProfile& profile);

// The same figures as estimateJobTime without building the per-move timings (about 50 bytes a
// move, tens of MB on a large job): for the planner, which only needs the moves' times.
void fillJobTimes(PlannedJob& job, const MachineProfile& profile);

// The moves around one move that GRBL's planner times on their own: from the last synchronising
// command at or before it (servo M3/M5, G4, M0; or the job's start) up to the next one (or the
// job's end). The machine is at rest where such a chain starts, so its timings are exactly those
// the whole job's estimate gives its moves (estimateJobTime), for a fraction of the work and
// memory: the trajectory times a large job chain by chain, as it is sampled.
struct TimedChain {
  size_t begin = 0, end = 0;               // moves [begin, end)
  std::vector<GrblBlockTiming> timings;    // timings[i - begin] of move i
};
TimedChain timeChainAround(const PlannedJob& job, const MachineProfile& profile, size_t moveIndex);

}  // namespace fivebar
