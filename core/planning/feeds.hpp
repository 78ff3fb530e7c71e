// Feeds: how fast each joint-linear move may run. The asked XY speed (mm/s) is turned into a
// duration per move; the duration grows where a motor would exceed its speed limit (joint speed =
// J^-1 v, large near singular regions), where the XY speed would peak above the asked one inside
// the move, where the move would be shorter than the firmware can stream (minimum duration), and
// where consecutive moves change joint velocity faster than the motors can accelerate.
// The G-code F of a move is |dtheta| / duration in deg/min (GRBL's joint-space vector rate).
#pragma once

#include <span>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/segmentation.hpp"

namespace fivebar {

// GRBL on an AVR plans about 200 blocks per second: a move shorter than this (s) would starve
// the planner buffer, so the feed is lowered instead.
inline constexpr double kMinSegmentDurationS = 0.005;

struct FeedLimits {
  double maxSpeedRadPerS1 = 3.0;
  double maxSpeedRadPerS2 = 3.0;
  double maxAccelRadPerS2_1 = 20.0;
  double maxAccelRadPerS2_2 = 20.0;
  double minSegmentDurationS = kMinSegmentDurationS;
};
FeedLimits feedLimitsOf(const MachineProfile& profile);

enum class FeedLimit {
  AskedSpeed,       // runs at the asked XY speed
  MotorSpeed,       // a motor's speed limit
  PeakXYSpeed,      // the XY speed would peak above the asked one inside the move
  MinDuration,      // shorter than the firmware can stream
  Acceleration,     // joint velocity change to a neighbour beyond the motors' acceleration
};

struct SegmentFeed {
  double durationS = 0.0;         // at cruise
  double feedMmPerS = 0.0;        // mean XY speed = pathLengthMm / durationS
  double jointFeedRadPerS = 0.0;  // |dtheta| / durationS (the G-code F, converted to deg/min)
  FeedLimit limit = FeedLimit::AskedSpeed;
  bool limited() const { return limit != FeedLimit::AskedSpeed; }
};

// Feeds of the moves waypoints[k-1] -> waypoints[k] (k >= 1) at the asked XY speed; the result
// has waypoints.size() - 1 entries. pathLengthMm of each waypoint is the XY length of its move.
// The chain is treated as one continuous motion (acceleration coupling between neighbours).
std::vector<SegmentFeed> planFeeds(const Geometry& g, AssemblyMode assembly,
                                   std::span<const JointWaypoint> waypoints, double askedMmPerS,
                                   const FeedLimits& limits);

}  // namespace fivebar
