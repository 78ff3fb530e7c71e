// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/feeds.hpp"

#include <algorithm>
#include <cmath>

#include "core/kinematics/move_samples.hpp"

namespace fivebar {
namespace {

// FK samples per move for the peak XY speed inside it.
constexpr int kSpeedSamples = 8;
// A move counts as running at the asked speed when its duration is within this factor of
// length / asked (the XY speed of a joint-linear move is never exactly uniform).
constexpr double kAskedSpeedSlack = 1.02;

// Largest XY speed (mm per unit of the move parameter u in [0, 1]) along the move, by samples.
double peakSpeedPerUnit(const Geometry& g, AssemblyMode assembly, const JointAngles& a,
                        const JointAngles& b, double fallbackLengthMm) {
  Vec2 p[kSpeedSamples + 1];
  if (!sampleJointMove(g, assembly, a, b, kSpeedSamples, p)) return fallbackLengthMm;
  double peak = 0.0;
  for (int k = 1; k <= kSpeedSamples; ++k) peak = std::max(peak, (p[k] - p[k - 1]).norm() * kSpeedSamples);
  return peak;
}

}  // namespace

FeedLimits feedLimitsOf(const MachineProfile& profile) {
  return {profile.motors.maxSpeedRadPerS1, profile.motors.maxSpeedRadPerS2, kMinSegmentDurationS};
}

std::vector<SegmentFeed> planFeeds(const Geometry& g, AssemblyMode assembly,
                                   std::span<const JointWaypoint> waypoints, double askedMmPerS,
                                   const FeedLimits& limits) {
  const size_t n = waypoints.size() > 1 ? waypoints.size() - 1 : 0;
  std::vector<SegmentFeed> feeds(n);
  for (size_t k = 0; k < n; ++k) {
    const JointWaypoint& a = waypoints[k];
    const JointWaypoint& b = waypoints[k + 1];
    const Eigen::Vector2d dq(b.q.theta1 - a.q.theta1, b.q.theta2 - a.q.theta2);
    const double asked = b.pathLengthMm / askedMmPerS;
    const double motor = std::max(std::abs(dq[0]) / limits.maxSpeedRadPerS1,
                                  std::abs(dq[1]) / limits.maxSpeedRadPerS2);
    const double peakMm = b.peakSpeedMmPerUnit > 0.0
                              ? b.peakSpeedMmPerUnit
                              : peakSpeedPerUnit(g, assembly, a.q, b.q, b.pathLengthMm);
    const double peak = peakMm / askedMmPerS;
    SegmentFeed& f = feeds[k];
    double t = std::max(asked, peak);
    if (peak > kAskedSpeedSlack * asked) f.limit = FeedLimit::PeakXYSpeed;
    if (motor > t) { t = motor; f.limit = FeedLimit::MotorSpeed; }
    if (limits.minSegmentDurationS > t) {
      t = limits.minSegmentDurationS;
      f.limit = FeedLimit::MinDuration;
    }
    f.durationS = t;
    f.feedMmPerS = b.pathLengthMm / t;
    f.jointFeedRadPerS = dq.norm() / t;
  }
  return feeds;
}

}  // namespace fivebar
