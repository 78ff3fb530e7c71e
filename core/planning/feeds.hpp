// SPDX-License-Identifier: GPL-3.0-or-later
// Feeds: how fast each joint-linear move may run. GRBL plans what it can know itself: the
// acceleration along every block, the speed through each junction (junction deviation $11,
// core/machine/junction_deviation.hpp) and each motor's rate limit along a block. The feeds set only
// what it cannot know: the joint rate (the G-code F, GRBL's joint-space vector rate) that gives
// the asked XY speed on this five-bar, and never more than the XY speed peaks at the asked one
// inside the move; at most each motor's speed limit; and at least the minimum block duration the
// firmware can plan. A move's feed depends on that move only (no coupling to its neighbours: the
// velocity changes at junctions are GRBL's, docs/planning.md "Feeds").
// The G-code F of a move is |dtheta| / duration in deg/min.
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
  double minSegmentDurationS = kMinSegmentDurationS;
};
FeedLimits feedLimitsOf(const MachineProfile& profile);

enum class FeedLimit {
  AskedSpeed,       // runs at the asked XY speed
  MotorSpeed,       // a motor's speed limit
  PeakXYSpeed,      // the XY speed would peak above the asked one inside the move
  MinDuration,      // shorter than the firmware can stream
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
std::vector<SegmentFeed> planFeeds(const Geometry& g, AssemblyMode assembly,
                                   std::span<const JointWaypoint> waypoints, double askedMmPerS,
                                   const FeedLimits& limits);

}  // namespace fivebar
