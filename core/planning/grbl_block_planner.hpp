// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL 1.1's planner, modelled block by block for the time estimate (time_estimate.hpp): a
// motion block's length, unit vector and per-axis limits, its junction speed (plan_buffer_line),
// the streamed 15-block look-ahead and the sink that hands each input its timing. Internal to
// core/planning: time_estimate.cpp times jobs with it; header-only so that the per-block steps
// inline into the job's loops exactly as before the split (the figures stay the same to the bit).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/planning/job.hpp"
#include "core/planning/time_estimate.hpp"

namespace fivebar::grbl_model {

// Shorter blocks than this (units) are dropped by GRBL's planner (no steps to take).
inline constexpr double kEmptyBlock = 1e-9;
// Z acceleration assumed for a Z-axis pen ($122), mm/s^2: the profile does not hold one.
inline constexpr double kZAccelMmPerS2 = 100.0;
// An axis whose share of a unit direction is at most this does not limit the vector value.
inline constexpr double kAxisShareFloor = 1e-12;
// "No limit" for a vector value (GRBL's SOME_LARGE_VALUE role).
inline constexpr double kNoLimit = 1e300;

// a / b for b > 0, skipping the division when a is +-0 (the quotient is a itself): the Z share of
// every XY move.
inline double quotient(double a, double b) { return a == 0.0 ? a : a / b; }

// GRBL's limit_value_by_axis_maximum: the largest vector value along the unit vector `unit`
// whose every axis share fits `maxima`. The same operations as the Eigen version it replaced, so
// that the figures stay the same to the last bit (a few blocks are far shorter than a step and
// their trapezoid times are ill-conditioned: one ulp in a speed shows at the 1e-8 level). The X
// and Y quotients are computed unconditionally (a pair of divisions the compiler can vectorize)
// and used only where GRBL would compute them.
inline double limitByAxis(const Eigen::Vector3d& maxima, const double unit[3]) {
  const double ax = std::abs(unit[0]), ay = std::abs(unit[1]), az = std::abs(unit[2]);
  const double qx = maxima[0] / ax, qy = maxima[1] / ay;
  double limit = kNoLimit;
  if (ax > kAxisShareFloor) limit = std::min(limit, qx);
  if (ay > kAxisShareFloor) limit = std::min(limit, qy);
  if (az > kAxisShareFloor) limit = std::min(limit, maxima[2] / az);
  return limit;
}

// One motion block in the planner buffer. entrySq is scratch of the look-ahead (see Lookahead).
struct Block {
  size_t input = 0;  // index into the inputs
  double length = 0.0, nominal = 0.0, accel = 0.0;
  double maxEntrySq = 0.0;  // junction limit, (units/s)^2
  double twoAccelLength = 0.0;  // 2 a L: how much v^2 can change over the block
  double entrySq = 0.0;
};

// GRBL 1.1 plan_buffer_line: junction speed^2 from the junction deviation and the angle between
// the previous and this block's unit vectors, limited by both nominal speeds.
inline double maxEntrySq(const GrblTimeModel& m, const double prevUnit[3], double prevNominal,
                  const double unit[3], double nominal) {
  const double cosTheta = -(prevUnit[0] * unit[0] + prevUnit[1] * unit[1] + prevUnit[2] * unit[2]);
  const double minJunctionSq = m.minJunctionSpeedPerS * m.minJunctionSpeedPerS;
  double junctionSq;
  if (cosTheta > 0.999999) {
    junctionSq = minJunctionSq;
  } else if (cosTheta < -0.999999) {
    junctionSq = kNoLimit;
  } else {
    const double w[3] = {unit[0] - prevUnit[0], unit[1] - prevUnit[1], unit[2] - prevUnit[2]};
    const double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double junctionUnit[3] = {w[0] / norm, w[1] / norm, quotient(w[2], norm)};
    const double junctionAccel = limitByAxis(m.accelPerS2, junctionUnit);
    const double sinHalf = std::sqrt(0.5 * (1.0 - cosTheta));
    junctionSq = std::max(minJunctionSq,
                          junctionAccel * m.junctionDeviation * sinHalf / (1.0 - sinHalf));
  }
  const double nominalMin = std::min(prevNominal, nominal);
  return std::min(junctionSq, nominalMin * nominalMin);
}

inline double trapezoidTime(double length, double v0, double vn, double v1, double a) {
  const double accelDist = (vn * vn - v0 * v0) / (2.0 * a);
  const double decelDist = (vn * vn - v1 * v1) / (2.0 * a);
  if (accelDist + decelDist <= length)
    return (vn - v0) / a + (vn - v1) / a + (length - accelDist - decelDist) / vn;
  const double peak = std::sqrt(std::max(0.0, (2.0 * a * length + v0 * v0 + v1 * v1) / 2.0));
  return std::max(0.0, (peak - v0) / a) + std::max(0.0, (peak - v1) / a);
}

// Receives every input's timing exactly once, in input order from `first` (inputs that are no
// block, such as an empty move, get a zero timing). Appends it to `out` and writes the moves'
// durations, when those are given, and with `startTimes` their start times from clock 0.
class TimingSink {
 public:
  // out: nullptr, or the timings of the moves from `outFirst` on, indexed by move - outFirst
  // (this sink writes its part's slice).
  TimingSink(GrblBlockTiming* out, size_t outFirst, std::vector<JobMove>* moves, size_t first,
             bool startTimes)
      : out_(out), outFirst_(outFirst), moves_(moves), next_(first), startTimes_(startTimes) {}
  void emit(size_t input, const GrblBlockTiming& t) {
    close(input);
    put(t);
  }
  // Every input before `end` has its timing.
  void close(size_t end) {
    while (next_ < end) put(GrblBlockTiming{});
  }
  double clockS() const { return clockS_; }

 private:
  void put(const GrblBlockTiming& t) {
    if (moves_ != nullptr) {
      JobMove& m = (*moves_)[next_];
      if (startTimes_) m.startTimeS = clockS_;
      m.durationS = t.durationS;
      clockS_ += t.durationS;
    }
    if (out_ != nullptr) out_[next_ - outFirst_] = t;
    ++next_;
  }
  GrblBlockTiming* out_;
  size_t outFirst_;
  std::vector<JobMove>* moves_;
  size_t next_;
  bool startTimes_;
  double clockS_ = 0.0;
};

// The look-ahead of one chain of motion blocks between synchronising commands, streamed: block c
// is executed once the `window` blocks c .. c+W-1 are known (or the chain ends), with the exit
// speed its window allows: the last block held must be able to stop.
//
// The window's backward pass r_j = min(maxEntrySq_j, r_{j+1} + 2 a_j L_j) (r = 0 past its end)
// is monotone in the window end, in floating point too (rounding and min are monotone). So once
// the pass is clamped at some j (r_j = maxEntrySq_j), r_j and every r below it stay the same
// for all later windows: they are stored, and a new pass is only needed past that "frontier".
// Same values as running the full pass for every block; about one step per block instead of W.
class Lookahead {
 public:
  explicit Lookahead(int window) : window_(static_cast<size_t>(std::max(1, window))) {}

  bool empty() const { return head_ == tail_; }
  void push(const Block& b, TimingSink& sink) {
    if (tail_ - head_ == ring_.size()) grow();
    ring_[tail_ & mask_] = b;
    ++tail_;
    if (tail_ - head_ >= window_) execute(sink);
  }
  // The chain ends (a synchronising command or the end of the job): the machine stops.
  void flush(TimingSink& sink) {
    while (!empty()) execute(sink);
    entrySq_ = 0.0;
    entryPerS_ = 0.0;
    frontier_ = 0;
  }

 private:
  Block& at(size_t seq) { return ring_[seq & mask_]; }

  void grow() {
    std::vector<Block> bigger(std::max<size_t>(64, 2 * ring_.size()));
    const size_t biggerMask = bigger.size() - 1;
    for (size_t s = head_; s < tail_; ++s) bigger[s & biggerMask] = at(s);
    ring_.swap(bigger);
    mask_ = biggerMask;
  }

  // Exit speed^2 allowed at the end of block c by the window (c, end): r_{c+1}.
  double windowEntrySq(size_t c, size_t end) {
    if (frontier_ > c) return at(c + 1).entrySq;
    double r = 0.0;
    for (size_t j = end - 1; j > c; --j) {
      Block& b = at(j);
      const double extended = r + b.twoAccelLength;
      if (extended < b.maxEntrySq) {  // r = std::min(maxEntrySq, extended), as GRBL's planner
        r = extended;
      } else {  // clamped: final for every later window
        r = b.maxEntrySq;
        frontier_ = std::max(frontier_, j);
      }
      b.entrySq = r;
    }
    return r;
  }

  void execute(TimingSink& sink) {
    const size_t c = head_;
    const size_t end = std::min(tail_, c + window_);
    const Block& b = at(c);
    const double exitSq =
        std::min(c + 1 < end ? windowEntrySq(c, end) : 0.0, entrySq_ + b.twoAccelLength);
    GrblBlockTiming t;
    t.lengthUnits = b.length;
    t.entryPerS = entryPerS_;
    t.exitPerS = std::sqrt(exitSq);
    t.nominalPerS = b.nominal;
    t.accelPerS2 = b.accel;
    t.durationS = trapezoidTime(b.length, t.entryPerS, b.nominal, t.exitPerS, b.accel);
    entrySq_ = exitSq;
    entryPerS_ = t.exitPerS;
    ++head_;
    sink.emit(b.input, t);
  }

  size_t window_;
  std::vector<Block> ring_;  // power-of-two ring indexed by sequence number
  size_t mask_ = 0;
  size_t head_ = 0, tail_ = 0;  // sequence numbers: first held block, one past the last
  size_t frontier_ = 0;         // entrySq of blocks head_+1 .. frontier_ is final
  double entrySq_ = 0.0;        // speed^2 at the start of block head_
  double entryPerS_ = 0.0;      // its square root
};

// GRBL's planner fed one input at a time: motion blocks and synchronising commands. Motion
// blocks are taken in batches: their lengths, unit vectors, limits and junction speeds do not
// depend on each other (only on the previous unit vector), so computing them in a loop of their
// own lets the processor overlap the long division and square-root chains of many blocks. Same
// operations per block as one at a time.
class Planner {
 public:
  Planner(const GrblTimeModel& m, TimingSink& sink)
      : m_(m), lookahead_(m.lookaheadBlocks), sink_(sink) {}

  void motion(size_t input, const double delta[3], double feedPerS) {
    Pending& p = pending_[pendingCount_++];
    p.input = input;
    std::copy(delta, delta + 3, p.delta);
    p.feedPerS = feedPerS;
    if (pendingCount_ == kBatch) takeBatch();
  }

  void sync(size_t input, double dwellS) {
    endChain();
    GrblBlockTiming t;
    t.durationS = dwellS;
    sink_.emit(input, t);
  }

  void endChain() {
    takeBatch();
    lookahead_.flush(sink_);
    chainOpen_ = false;
  }

 private:
  static constexpr size_t kBatch = 32;
  struct Pending {
    size_t input;
    double delta[3];
    double feedPerS;
  };

  void takeBatch() {
    Block blocks[kBatch];
    double units[kBatch][3];
    size_t count = 0;
    for (size_t i = 0; i < pendingCount_; ++i) {  // independent per block
      const Pending& p = pending_[i];
      const double length =
          std::sqrt(p.delta[0] * p.delta[0] + p.delta[1] * p.delta[1] + p.delta[2] * p.delta[2]);
      if (length < kEmptyBlock) continue;  // no timing of its own: the sink gives it zero
      double* unit = units[count];
      unit[0] = p.delta[0] / length;
      unit[1] = p.delta[1] / length;
      unit[2] = quotient(p.delta[2], length);
      const double rate = limitByAxis(m_.maxRatePerS, unit);
      Block& b = blocks[count++];
      b.input = p.input;
      b.length = length;
      b.nominal = p.feedPerS > 0.0 ? std::min(p.feedPerS, rate) : rate;
      b.accel = limitByAxis(m_.accelPerS2, unit);
      b.twoAccelLength = 2.0 * b.accel * b.length;
    }
    for (size_t i = 0; i < count; ++i) {  // junctions: each needs only the previous unit vector
      blocks[i].maxEntrySq =  // the first block after a synchronising command starts from rest
          chainOpen_ ? maxEntrySq(m_, prevUnit_, prevNominal_, units[i], blocks[i].nominal) : 0.0;
      chainOpen_ = true;
      std::copy(units[i], units[i] + 3, prevUnit_);
      prevNominal_ = blocks[i].nominal;
    }
    for (size_t i = 0; i < count; ++i) lookahead_.push(blocks[i], sink_);
    pendingCount_ = 0;
  }

  const GrblTimeModel& m_;
  Lookahead lookahead_;
  TimingSink& sink_;
  Pending pending_[kBatch];
  size_t pendingCount_ = 0;
  bool chainOpen_ = false;  // a motion block entered since the last synchronising command
  double prevUnit_[3] = {0.0, 0.0, 0.0};
  double prevNominal_ = 0.0;
};

}  // namespace fivebar::grbl_model
