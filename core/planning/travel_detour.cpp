// SPDX-License-Identifier: GPL-3.0-or-later
// planSafeTravel: a straight joint move when it is safe, else a detour found by A* over a lazily
// checked joint-space grid, then shortened. Contract: safety.hpp. Every leg passes checkJointMove.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/planning/safety.hpp"

namespace fivebar {
namespace {

// Joint-space grid pitch of the detour search, rad, and the cap on cells per motor.
constexpr double kDetourGridStepRad = radFromDeg(3.0);
constexpr int kDetourMaxCellsPerMotor = 140;

// Motor time of a continuous joint move, s (the search cost).
double moveTimeS(const MachineProfile& pr, const JointAngles& a, const JointAngles& b) {
  return std::max(std::abs(b.theta1 - a.theta1) / pr.motors.maxSpeedRadPerS1,
                  std::abs(b.theta2 - a.theta2) / pr.motors.maxSpeedRadPerS2);
}

WorkingMode modeAt(const MachineProfile& pr, const JointAngles& q, const Vec2& p) {
  return workingModeOf(pr.geometry, makePose(pr.geometry, q, p));
}

// Lazily evaluated joint-space grid for the detour search: a node is usable when its pose
// passes checkPose and lies in the working mode of the travel's start.
class DetourGrid {
 public:
  DetourGrid(const MachineProfile& pr, const JointAngles& from, const JointAngles& to,
             WorkingMode mode)
      : pr_(pr), mode_(mode) {
    const double pad = kPi;
    // The grid walks kinematic angles; the profile's limits are on commanded angles.
    const JointLimits l = kinematicLimits(pr.calibration, pr.limits);
    lo1_ = std::max(l.theta1Min, std::min(from.theta1, to.theta1) - pad);
    lo2_ = std::max(l.theta2Min, std::min(from.theta2, to.theta2) - pad);
    const double hi1 = std::min(l.theta1Max, std::max(from.theta1, to.theta1) + pad);
    const double hi2 = std::min(l.theta2Max, std::max(from.theta2, to.theta2) + pad);
    n1_ = std::clamp(static_cast<int>(std::ceil((hi1 - lo1_) / kDetourGridStepRad)) + 1, 2,
                     kDetourMaxCellsPerMotor);
    n2_ = std::clamp(static_cast<int>(std::ceil((hi2 - lo2_) / kDetourGridStepRad)) + 1, 2,
                     kDetourMaxCellsPerMotor);
    h1_ = (hi1 - lo1_) / (n1_ - 1);
    h2_ = (hi2 - lo2_) / (n2_ - 1);
    state_.assign(static_cast<std::size_t>(n1_) * n2_, 0);
  }
  int size() const { return n1_ * n2_; }
  JointAngles at(int node) const { return {lo1_ + (node % n1_) * h1_, lo2_ + (node / n1_) * h2_}; }
  bool usable(int node) {
    auto& st = state_[node];
    if (st == 0) {
      const JointAngles q = at(node);
      const MoveCheck c = checkPose(pr_, q);
      st = (c.ok() && modeAt(pr_, q, c.where) == mode_) ? 1 : 2;
    }
    return st == 1;
  }
  // Usable nodes within `radius` cells of q.
  std::vector<int> near(const JointAngles& q, int radius) {
    const int c1 = static_cast<int>(std::lround((q.theta1 - lo1_) / h1_));
    const int c2 = static_cast<int>(std::lround((q.theta2 - lo2_) / h2_));
    std::vector<int> out;
    for (int j = c2 - radius; j <= c2 + radius; ++j)
      for (int i = c1 - radius; i <= c1 + radius; ++i)
        if (i >= 0 && j >= 0 && i < n1_ && j < n2_ && usable(j * n1_ + i)) out.push_back(j * n1_ + i);
    return out;
  }
  std::vector<int> neighbours(int node) {
    const int i = node % n1_, j = node / n1_;
    std::vector<int> out;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if ((di || dj) && a >= 0 && b >= 0 && a < n1_ && b < n2_ && usable(b * n1_ + a))
          out.push_back(b * n1_ + a);
      }
    return out;
  }

 private:
  const MachineProfile& pr_;
  WorkingMode mode_;
  double lo1_, lo2_, h1_, h2_;
  int n1_, n2_;
  std::vector<unsigned char> state_;  // 0 unknown, 1 usable, 2 unusable
};

// A* over the grid from `from` to `to` with lazily checked edges; returns the waypoint poses
// (grid nodes) between them, or nullopt.
std::optional<std::vector<JointAngles>> searchDetour(const MachineProfile& pr,
                                                     const JointAngles& from,
                                                     const JointAngles& to, DetourGrid& grid) {
  const int start = grid.size(), goal = grid.size() + 1;
  auto pose = [&](int n) { return n == start ? from : n == goal ? to : grid.at(n); };
  std::vector<double> cost(grid.size() + 2, std::numeric_limits<double>::infinity());
  std::vector<int> parent(grid.size() + 2, -1);
  std::vector<char> closed(grid.size() + 2, 0);
  const std::vector<int> goalSide = grid.near(to, 2);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  cost[start] = 0.0;
  open.push({moveTimeS(pr, from, to), start});
  while (!open.empty()) {
    const int n = open.top().second;
    open.pop();
    if (closed[n]) continue;
    closed[n] = 1;
    if (n == goal) break;
    std::vector<int> next = n == start ? grid.near(from, 2) : grid.neighbours(n);
    if (n != start && std::find(goalSide.begin(), goalSide.end(), n) != goalSide.end())
      next.push_back(goal);
    for (int m : next) {
      if (closed[m]) continue;
      const double c = cost[n] + moveTimeS(pr, pose(n), pose(m));
      if (c >= cost[m] || !checkJointMove(pr, pose(n), pose(m)).ok()) continue;
      cost[m] = c;
      parent[m] = n;
      open.push({c + moveTimeS(pr, pose(m), to), m});
    }
  }
  if (parent[goal] < 0) return std::nullopt;
  std::vector<JointAngles> path;
  for (int n = goal; n != start; n = parent[n]) path.push_back(pose(n));
  std::reverse(path.begin(), path.end());
  return path;
}

// Drops waypoints whose neighbours can be joined by a safe straight move.
std::vector<JointAngles> shortcut(const MachineProfile& pr, const JointAngles& from,
                                  const std::vector<JointAngles>& path) {
  std::vector<JointAngles> out;
  JointAngles here = from;
  std::size_t i = 0;
  while (i < path.size()) {
    std::size_t best = i;
    for (std::size_t j = path.size() - 1; j > i; --j)
      if (checkJointMove(pr, here, path[j]).ok()) {
        best = j;
        break;
      }
    out.push_back(path[best]);
    here = path[best];
    i = best + 1;
  }
  return out;
}

}  // namespace

std::optional<std::vector<JointAngles>> planSafeTravel(const MachineProfile& profile,
                                                       const JointAngles& from,
                                                       const JointAngles& to) {
  if (checkJointMove(profile, from, to).ok()) return std::vector<JointAngles>{to};
  const MoveCheck a = checkPose(profile, from), b = checkPose(profile, to);
  if (!a.ok() || !b.ok()) return std::nullopt;
  const WorkingMode mode = modeAt(profile, from, a.where);
  if (modeAt(profile, to, b.where) != mode) return std::nullopt;  // needs a type I crossing
  DetourGrid grid(profile, from, to, mode);
  const auto path = searchDetour(profile, from, to, grid);
  if (!path) return std::nullopt;
  return shortcut(profile, from, *path);
}

}  // namespace fivebar
