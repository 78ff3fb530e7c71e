// SPDX-License-Identifier: GPL-3.0-or-later
// Test oracle: a verbatim copy of the GRBL time model as it was before it was made fast
// (core/time_estimate.cpp, 2026-11-22), in namespace fivebar::oracle. The optimised model must
// give the same per-move durations, start times and totals to 1e-9 relative;
// time_estimate_test.cpp compares the two on seeded random inputs and jobs.
// Do not "fix" this file: it is the reference. One amendment (issue 16, measured on the GRBL
// 1.1h firmware): grblInputsOf gives the step-rounded deltas GRBL plans (lround of the target as
// printed, 4 decimals, relative to the job start, times $100/$101).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/planning/time_estimate.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::oracle {
namespace {

// Shorter blocks than this (units) are dropped by GRBL's planner (no steps to take).
constexpr double kEmptyBlock = 1e-9;
// Z acceleration assumed for a Z-axis pen ($122), mm/s^2: the profile does not hold one.
constexpr double kZAccelMmPerS2 = 100.0;

// GRBL's limit_value_by_axis_maximum: the largest vector value whose every axis share fits.
double limitByAxis(const Eigen::Vector3d& maxima, const Eigen::Vector3d& unit) {
  double limit = 1e300;
  for (int i = 0; i < 3; ++i)
    if (std::abs(unit[i]) > 1e-12) limit = std::min(limit, maxima[i] / std::abs(unit[i]));
  return limit;
}

struct MotionBlock {
  size_t input = 0;  // index into the inputs
  double length = 0.0, nominal = 0.0, accel = 0.0, maxEntrySq = 0.0;
};

// GRBL 1.1 plan_buffer_line: junction speed from the junction deviation and the angle between
// the previous and this block's unit vectors, limited by both nominal speeds.
double maxEntrySq(const GrblTimeModel& m, const Eigen::Vector3d& prevUnit, double prevNominal,
                  const Eigen::Vector3d& unit, double nominal) {
  const double cosTheta = -prevUnit.dot(unit);
  double junctionSq;
  if (cosTheta > 0.999999) {
    junctionSq = m.minJunctionSpeedPerS * m.minJunctionSpeedPerS;
  } else if (cosTheta < -0.999999) {
    junctionSq = 1e300;
  } else {
    const Eigen::Vector3d junctionUnit = (unit - prevUnit).normalized();
    const double junctionAccel = limitByAxis(m.accelPerS2, junctionUnit);
    const double sinHalf = std::sqrt(0.5 * (1.0 - cosTheta));
    junctionSq = std::max(m.minJunctionSpeedPerS * m.minJunctionSpeedPerS,
                          junctionAccel * m.junctionDeviation * sinHalf / (1.0 - sinHalf));
  }
  const double nominalMin = std::min(prevNominal, nominal);
  return std::min(junctionSq, nominalMin * nominalMin);
}

double trapezoidTime(double length, double v0, double vn, double v1, double a) {
  const double accelDist = (vn * vn - v0 * v0) / (2.0 * a);
  const double decelDist = (vn * vn - v1 * v1) / (2.0 * a);
  if (accelDist + decelDist <= length)
    return (vn - v0) / a + (vn - v1) / a + (length - accelDist - decelDist) / vn;
  const double peak = std::sqrt(std::max(0.0, (2.0 * a * length + v0 * v0 + v1 * v1) / 2.0));
  return std::max(0.0, (peak - v0) / a) + std::max(0.0, (peak - v1) / a);
}

// Executes one chain of motion blocks between synchronising commands with a look-ahead window.
void executeChain(const std::vector<MotionBlock>& chain, int window,
                  std::vector<GrblBlockTiming>& out) {
  const size_t m = chain.size();
  double entrySq = 0.0;
  for (size_t c = 0; c < m; ++c) {
    const size_t end = std::min(m, c + static_cast<size_t>(std::max(1, window)));
    // Backward pass over the window: the last block it holds must be able to stop.
    double nextEntrySq = 0.0;
    for (size_t j = end - 1; j > c; --j)
      nextEntrySq = std::min(chain[j].maxEntrySq,
                             nextEntrySq + 2.0 * chain[j].accel * chain[j].length);
    const MotionBlock& b = chain[c];
    const double exitSq = std::min(c + 1 < end ? nextEntrySq : 0.0,
                                   entrySq + 2.0 * b.accel * b.length);
    GrblBlockTiming& t = out[b.input];
    t.lengthUnits = b.length;
    t.entryPerS = std::sqrt(entrySq);
    t.exitPerS = std::sqrt(exitSq);
    t.nominalPerS = b.nominal;
    t.accelPerS2 = b.accel;
    t.durationS = trapezoidTime(b.length, t.entryPerS, b.nominal, t.exitPerS, b.accel);
    entrySq = exitSq;
  }
}

}  // namespace

inline GrblTimeModel grblTimeModelOf(const MachineProfile& profile) {
  GrblTimeModel m;
  const MotorSettings& s = profile.motors;
  m.maxRatePerS = {degFromRad(s.maxSpeedRadPerS1), degFromRad(s.maxSpeedRadPerS2),
                   profile.tool.zFeedMmPerMin / 60.0};
  m.accelPerS2 = {degFromRad(s.maxAccelRadPerS2_1), degFromRad(s.maxAccelRadPerS2_2),
                  kZAccelMmPerS2};
  m.junctionDeviation = s.junctionDeviationDeg;
  return m;
}

inline std::vector<GrblBlockTiming> estimateBlocks(const std::vector<GrblBlockInput>& inputs,
                                            const GrblTimeModel& model) {
  std::vector<GrblBlockTiming> out(inputs.size());
  std::vector<MotionBlock> chain;
  Eigen::Vector3d prevUnit = Eigen::Vector3d::Zero();
  double prevNominal = 0.0;
  for (size_t i = 0; i < inputs.size(); ++i) {
    const GrblBlockInput& in = inputs[i];
    if (in.sync) {
      executeChain(chain, model.lookaheadBlocks, out);
      chain.clear();
      out[i].durationS = in.dwellS;
      continue;
    }
    const double length = in.delta.norm();
    if (length < kEmptyBlock) continue;
    const Eigen::Vector3d unit = in.delta / length;
    const double rate = limitByAxis(model.maxRatePerS, unit);
    MotionBlock b;
    b.input = i;
    b.length = length;
    b.nominal = in.feedPerS > 0.0 ? std::min(in.feedPerS, rate) : rate;
    b.accel = limitByAxis(model.accelPerS2, unit);
    b.maxEntrySq = chain.empty() ? 0.0 : maxEntrySq(model, prevUnit, prevNominal, unit, b.nominal);
    chain.push_back(b);
    prevUnit = unit;
    prevNominal = b.nominal;
  }
  executeChain(chain, model.lookaheadBlocks, out);
  return out;
}

inline double distanceAt(const GrblBlockTiming& b, double t) {
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

inline std::vector<GrblBlockInput> grblInputsOf(const PlannedJob& job, const MachineProfile& profile) {
  std::vector<GrblBlockInput> inputs(job.moves.size());
  JointAngles at = job.start;
  double z = profile.tool.zUpMm;
  const auto printedDeg = [](double rad) { return std::round(degFromRad(rad) * 1e4) / 1e4; };
  const auto stepDeltaDeg = [&](double fromRad, double toRad, double startRad, double stepsPerDeg) {
    const long long a = std::llround((printedDeg(fromRad) - printedDeg(startRad)) * stepsPerDeg);
    const long long b = std::llround((printedDeg(toRad) - printedDeg(startRad)) * stepsPerDeg);
    return static_cast<double>(b - a) / stepsPerDeg;
  };
  for (size_t i = 0; i < job.moves.size(); ++i) {
    const JobMove& mv = job.moves[i];
    GrblBlockInput& in = inputs[i];
    switch (mv.kind) {
      case JobMoveKind::Draw:
      case JobMoveKind::Travel:
        in.delta = {stepDeltaDeg(at.theta1, mv.target.theta1, job.start.theta1,
                                 profile.motors.stepsPerDeg1),
                    stepDeltaDeg(at.theta2, mv.target.theta2, job.start.theta2,
                                 profile.motors.stepsPerDeg2),
                    0.0};
        in.feedPerS = degFromRad(mv.jointFeedRadPerS);
        at = mv.target;
        break;
      case JobMoveKind::PenUp:
      case JobMoveKind::PenDown:
        if (profile.tool.kind == ToolKind::PenServo) {
          in.sync = true;  // M3/M5 empty the planner buffer outside laser mode
          in.dwellS = mv.dwellS;
        } else if (profile.tool.kind == ToolKind::ZAxis) {
          in.delta = {0.0, 0.0, mv.toolValue - z};
          in.feedPerS = profile.tool.zFeedMmPerMin / 60.0;
          z = mv.toolValue;
        }  // laser: the S word rides on the next G1, no block of its own
        break;
      case JobMoveKind::Dwell:
      case JobMoveKind::Pause:
        in.sync = true;
        in.dwellS = mv.kind == JobMoveKind::Dwell ? mv.dwellS : 0.0;
        break;
    }
  }
  return inputs;
}

inline std::vector<GrblBlockTiming> estimateJobTime(PlannedJob& job, const MachineProfile& profile) {
  std::vector<GrblBlockTiming> timings =
      oracle::estimateBlocks(oracle::grblInputsOf(job, profile), oracle::grblTimeModelOf(profile));
  double t = 0.0;
  for (size_t i = 0; i < job.moves.size(); ++i) {
    job.moves[i].startTimeS = t;
    job.moves[i].durationS = timings[i].durationS;
    t += timings[i].durationS;
  }
  job.summary.estimatedTimeS = t;
  return timings;
}

}  // namespace fivebar::oracle
