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
// Acceleration coupling: passes over the chain, and the relative excess accepted as converged.
constexpr int kAccelPasses = 60;
constexpr double kAccelConvergence = 1e-3;

// Largest XY speed (mm per unit of the move parameter u in [0, 1]) along the move, by samples.
double peakSpeedPerUnit(const Geometry& g, AssemblyMode assembly, const JointAngles& a,
                        const JointAngles& b, double fallbackLengthMm) {
  Vec2 p[kSpeedSamples + 1];
  if (!sampleJointMove(g, assembly, a, b, kSpeedSamples, p)) return fallbackLengthMm;
  double peak = 0.0;
  for (int k = 1; k <= kSpeedSamples; ++k) peak = std::max(peak, (p[k] - p[k - 1]).norm() * kSpeedSamples);
  return peak;
}

// One pass of the acceleration coupling; returns true when every junction already fits.
bool accelPass(const std::vector<Eigen::Vector2d>& dq, std::vector<double>& durations,
               const FeedLimits& limits, std::vector<bool>& slowed) {
  bool settled = true;
  const Eigen::Vector2d accel(limits.maxAccelRadPerS2_1, limits.maxAccelRadPerS2_2);
  for (size_t k = 1; k < dq.size(); ++k) {
    const Eigen::Vector2d change = dq[k] / durations[k] - dq[k - 1] / durations[k - 1];
    const double window = 0.5 * (durations[k] + durations[k - 1]);
    double factor = 1.0;  // velocity scale that makes this junction fit exactly
    for (int i = 0; i < 2; ++i) {
      const double need = std::abs(change[i]);
      if (need > accel[i] * window) factor = std::min(factor, std::sqrt(accel[i] * window / need));
    }
    if (factor < 1.0 - kAccelConvergence) {
      settled = false;
      slowed[k] = slowed[k - 1] = true;
    }
    if (factor < 1.0) {
      durations[k] /= factor;
      durations[k - 1] /= factor;
    }
  }
  return settled;
}

}  // namespace

FeedLimits feedLimitsOf(const MachineProfile& profile) {
  return {profile.motors.maxSpeedRadPerS1, profile.motors.maxSpeedRadPerS2,
          profile.motors.maxAccelRadPerS2_1, profile.motors.maxAccelRadPerS2_2,
          kMinSegmentDurationS};
}

std::vector<SegmentFeed> planFeeds(const Geometry& g, AssemblyMode assembly,
                                   std::span<const JointWaypoint> waypoints, double askedMmPerS,
                                   const FeedLimits& limits) {
  const size_t n = waypoints.size() > 1 ? waypoints.size() - 1 : 0;
  std::vector<SegmentFeed> feeds(n);
  std::vector<Eigen::Vector2d> dq(n);
  std::vector<double> durations(n);
  std::vector<FeedLimit> reasons(n, FeedLimit::AskedSpeed);
  for (size_t k = 0; k < n; ++k) {
    const JointWaypoint& a = waypoints[k];
    const JointWaypoint& b = waypoints[k + 1];
    dq[k] = {b.q.theta1 - a.q.theta1, b.q.theta2 - a.q.theta2};
    const double asked = b.pathLengthMm / askedMmPerS;
    const double motor = std::max(std::abs(dq[k][0]) / limits.maxSpeedRadPerS1,
                                  std::abs(dq[k][1]) / limits.maxSpeedRadPerS2);
    const double peakMm = b.peakSpeedMmPerUnit > 0.0
                              ? b.peakSpeedMmPerUnit
                              : peakSpeedPerUnit(g, assembly, a.q, b.q, b.pathLengthMm);
    const double peak = peakMm / askedMmPerS;
    double t = std::max(asked, peak);
    if (peak > kAskedSpeedSlack * asked) reasons[k] = FeedLimit::PeakXYSpeed;
    if (motor > t) { t = motor; reasons[k] = FeedLimit::MotorSpeed; }
    if (limits.minSegmentDurationS > t) {
      t = limits.minSegmentDurationS;
      reasons[k] = FeedLimit::MinDuration;
    }
    durations[k] = t;
  }
  std::vector<bool> slowed(n, false);
  for (int pass = 0; pass < kAccelPasses; ++pass)
    if (accelPass(dq, durations, limits, slowed)) break;
  for (size_t k = 0; k < n; ++k) {
    SegmentFeed& f = feeds[k];
    f.durationS = durations[k];
    f.feedMmPerS = waypoints[k + 1].pathLengthMm / durations[k];
    f.jointFeedRadPerS = dq[k].norm() / durations[k];
    f.limit = slowed[k] ? FeedLimit::Acceleration : reasons[k];
  }
  return feeds;
}

}  // namespace fivebar
