// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated machine's motion planner: a GRBL-like look-ahead buffer of joint-space line
// blocks (15 blocks), trapezoidal acceleration with junction-deviation cornering, executed in
// machine time. Pure logic; units are the board's: X, Y in degrees (theta1, theta2), Z in mm,
// time in seconds.
#pragma once

#include <array>
#include <deque>
#include <functional>

namespace fivebar::sim {

using Axes3 = std::array<double, 3>;

struct MotionLimits {
  Axes3 stepsPerUnit{35.5556, 35.5556, 100.0};      // $100-$102
  Axes3 maxRatePerS{172.0, 172.0, 10.0};             // $110-$112 / 60
  Axes3 accelPerS2{1146.0, 1146.0, 200.0};           // $120-$122
  double junctionDeviation = 0.01;                   // $11, board units
};

struct Block {
  Axes3 start{};
  Axes3 target{};
  Axes3 unit{};            // direction, unit length
  double length = 0.0;     // board units
  double nominalSpeed = 0.0;  // units/s, with the overrides (planner.c nominal speed)
  double programmedRate = 0.0;  // units/s: the F word, or the rapid rate for G0
  double rapidRate = 0.0;       // units/s: the highest speed $110-$112 allow along the block
  double maxJunctionSpeed = 0.0;  // units/s: the junction-deviation limit with the previous block
  bool rapid = false;             // G0: scaled by the rapid override
  bool noFeedOverride = false;    // jogs and homing: not scaled by the feed override
  double accel = 0.0;         // units/s^2 along the block
  double maxEntrySpeed = 0.0; // junction limit with the previous block
  bool penDown = false;
  bool jog = false;
};

class Planner {
 public:
  static constexpr std::size_t kCapacity = 15;
  // Machine time step of the integration (s); small against any block's duration.
  static constexpr double kStepS = 0.0005;

  explicit Planner(const MotionLimits& limits) : limits_(limits) {}
  void setLimits(const MotionLimits& limits) { limits_ = limits; }
  const MotionLimits& limits() const { return limits_; }

  bool full() const { return blocks_.size() >= kCapacity; }
  bool empty() const { return blocks_.empty(); }
  std::size_t size() const { return blocks_.size(); }
  const std::deque<Block>& blocks() const { return blocks_; }

  // Rounds a target to whole steps, as the firmware does.
  Axes3 quantize(const Axes3& target) const;
  // Appends a move from the end of the queue to `target` (quantised). rapid: at the axes' max
  // rates; otherwise at feedPerS, limited by them. Returns false for a zero-step move, which
  // the firmware drops without a block. Jogs and system motion (homing) ignore the feed
  // override.
  bool add(const Axes3& target, double feedPerS, bool rapid, bool penDown, bool jog,
           bool systemMotion = false);
  // GRBL 1.1h's feed and rapid override (percent): every queued block's nominal speed is
  // recomputed (planner.c plan_update_velocity_profile_parameters: programmed rate x feed
  // override, capped at the block's rapid rate; G0 at rapid rate x rapid override), and a block
  // under way faster than its new nominal speed decelerates to it at its acceleration (stepper.c
  // RAMP_DECEL_OVERRIDE). Later blocks are planned with these values.
  void setOverrides(int feedPct, int rapidPct);

  // Advances machine time by dtS. holding: decelerate to rest and stay there. instant: every
  // block completes at once (a simulator that acknowledges at once). done(block) is called for
  // each completed block, in order.
  void advance(double dtS, bool holding, bool instant, const std::function<void(const Block&)>& done);

  Axes3 position() const { return position_; }
  Axes3 plannedEnd() const { return blocks_.empty() ? position_ : blocks_.back().target; }
  double speed() const { return speed_; }
  bool moving() const { return speed_ > 0.0; }
  // Drops every block (reset, jog cancel) and stops at the current position.
  void clear();
  void setPosition(const Axes3& p);

 private:
  double exitSpeedOfCurrent() const;
  double nominalSpeedOf(const Block& b) const;
  void step(double& timeLeftS, bool holding, const std::function<void(const Block&)>& done);
  void finishCurrent(const std::function<void(const Block&)>& done);

  MotionLimits limits_;
  std::deque<Block> blocks_;
  Axes3 position_{};
  double speed_ = 0.0;
  double remaining_ = 0.0;  // distance left in the front block
  int feedOverridePct_ = 100;
  int rapidOverridePct_ = 100;
};

}  // namespace fivebar::sim
