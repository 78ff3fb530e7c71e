// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fivebar::sim {
namespace {

double dot(const Axes3& a, const Axes3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Junction speed limit between two unit directions (GRBL 1.1 planner.c): the speed at which
// a circle of the junction deviation, tangent to both segments, is driven at `accel`.
double junctionSpeed(const Axes3& prevUnit, const Axes3& unit, double accel, double deviation) {
  const double cosTheta = -dot(prevUnit, unit);
  if (cosTheta > 0.999999) return 0.0;  // full reversal
  if (cosTheta < -0.999999) return std::numeric_limits<double>::infinity();  // straight on
  const double sinHalf = std::sqrt(0.5 * (1.0 - cosTheta));
  return std::sqrt(accel * deviation * sinHalf / (1.0 - sinHalf));
}

}  // namespace

Axes3 Planner::quantize(const Axes3& target) const {
  Axes3 q{};
  for (size_t i = 0; i < 3; ++i)
    q[i] = std::round(target[i] * limits_.stepsPerUnit[i]) / limits_.stepsPerUnit[i];
  return q;
}

bool Planner::add(const Axes3& rawTarget, double feedPerS, bool rapid, bool penDown, bool jog,
                  bool systemMotion) {
  Block b;
  b.start = plannedEnd();
  b.target = quantize(rawTarget);
  double len2 = 0.0;
  for (size_t i = 0; i < 3; ++i) len2 += (b.target[i] - b.start[i]) * (b.target[i] - b.start[i]);
  b.length = std::sqrt(len2);
  if (b.length < 0.5 / limits_.stepsPerUnit[0]) return false;
  double rapidRate = std::numeric_limits<double>::infinity();
  double accel = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < 3; ++i) {
    b.unit[i] = (b.target[i] - b.start[i]) / b.length;
    const double u = std::abs(b.unit[i]);
    if (u < 1e-12) continue;
    rapidRate = std::min(rapidRate, limits_.maxRatePerS[i] / u);
    accel = std::min(accel, limits_.accelPerS2[i] / u);
  }
  b.rapidRate = rapidRate;
  b.programmedRate = rapid ? rapidRate : feedPerS;
  b.rapid = rapid;
  b.noFeedOverride = jog || systemMotion;
  b.nominalSpeed = nominalSpeedOf(b);
  b.accel = accel;
  b.penDown = penDown;
  b.jog = jog;
  if (blocks_.empty()) {
    b.maxEntrySpeed = 0.0;  // starting from rest (the current speed is 0 with no blocks)
    b.maxJunctionSpeed = 0.0;
    remaining_ = b.length;
  } else {
    const Block& prev = blocks_.back();
    b.maxJunctionSpeed = junctionSpeed(prev.unit, b.unit, accel, limits_.junctionDeviation);
    b.maxEntrySpeed = std::min({b.maxJunctionSpeed, b.nominalSpeed, prev.nominalSpeed});
  }
  blocks_.push_back(b);
  return true;
}

// planner.c plan_compute_profile_nominal_speed.
double Planner::nominalSpeedOf(const Block& b) const {
  constexpr double kMinimumRatePerS = 1.0 / 60.0;  // MINIMUM_FEED_RATE: 1 unit/min
  double v = b.programmedRate;
  if (b.rapid) {
    v *= 0.01 * rapidOverridePct_;
  } else {
    if (!b.noFeedOverride) v *= 0.01 * feedOverridePct_;
    v = std::min(v, b.rapidRate);
  }
  return std::max(v, kMinimumRatePerS);
}

void Planner::setOverrides(int feedPct, int rapidPct) {
  feedOverridePct_ = feedPct;
  rapidOverridePct_ = rapidPct;
  for (size_t i = 0; i < blocks_.size(); ++i) {
    Block& b = blocks_[i];
    b.nominalSpeed = nominalSpeedOf(b);
    if (i > 0)  // the front block runs from the current speed
      b.maxEntrySpeed = std::min({b.maxJunctionSpeed, b.nominalSpeed, blocks_[i - 1].nominalSpeed});
  }
}

// Backward pass over the queue: the highest speed the front block may have at its end so that
// every later block can still stop by the end of the queue.
double Planner::exitSpeedOfCurrent() const {
  double exit = 0.0;  // at the end of the last block
  for (size_t i = blocks_.size(); i-- > 1;) {
    const Block& b = blocks_[i];
    exit = std::min(b.maxEntrySpeed, std::sqrt(exit * exit + 2.0 * b.accel * b.length));
  }
  return blocks_.size() > 1 ? exit : 0.0;
}

void Planner::finishCurrent(const std::function<void(const Block&)>& done) {
  const Block b = blocks_.front();
  blocks_.pop_front();
  position_ = b.target;
  remaining_ = blocks_.empty() ? 0.0 : blocks_.front().length;
  if (blocks_.empty()) speed_ = 0.0;
  done(b);
}

void Planner::step(double& timeLeftS, bool holding, const std::function<void(const Block&)>& done) {
  const Block& b = blocks_.front();
  const double h = std::min(timeLeftS, kStepS);
  const double vExit = exitSpeedOfCurrent();
  const double brake = std::sqrt(vExit * vExit + 2.0 * b.accel * remaining_);
  double v = holding                  ? std::max(0.0, speed_ - b.accel * h)
             : speed_ > b.nominalSpeed ? std::min(std::max(b.nominalSpeed, speed_ - b.accel * h), brake)
                                       : std::min({speed_ + b.accel * h, b.nominalSpeed, brake});
  if (!holding) v = std::max(v, 0.5 * b.accel * h);  // never stall just before a block end
  const double ds = 0.5 * (speed_ + v) * h;
  speed_ = v;
  if (ds >= remaining_) {
    timeLeftS -= speed_ > 0.0 ? h * std::clamp(remaining_ / std::max(ds, 1e-12), 0.0, 1.0) : h;
    finishCurrent(done);
    return;
  }
  remaining_ -= ds;
  for (size_t i = 0; i < 3; ++i) position_[i] = b.target[i] - b.unit[i] * remaining_;
  timeLeftS -= h;
}

void Planner::advance(double dtS, bool holding, bool instant,
                      const std::function<void(const Block&)>& done) {
  if (instant) {
    if (!holding)
      while (!blocks_.empty()) finishCurrent(done);
    return;
  }
  double timeLeftS = dtS;
  while (timeLeftS > 1e-12 && !blocks_.empty()) {
    if (holding && speed_ <= 0.0) break;
    step(timeLeftS, holding, done);
  }
  if (blocks_.empty()) speed_ = 0.0;
}

void Planner::clear() {
  blocks_.clear();
  speed_ = 0.0;
  remaining_ = 0.0;
}

void Planner::setPosition(const Axes3& p) {
  clear();
  position_ = p;
}

}  // namespace fivebar::sim
