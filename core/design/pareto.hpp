// SPDX-License-Identifier: GPL-3.0-or-later
// Non-dominated sets for two objectives, both minimised (docs/design.md "Trade-off").
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fivebar::design {

// A point of the trade-off: two objective values and what produced them.
template <typename Payload>
struct TradeOffPoint {
  double f1 = 0.0;
  double f2 = 0.0;
  Payload payload{};
};

// True when a is at least as good as b in both objectives and better in one.
inline bool dominates(double a1, double a2, double b1, double b2) {
  return a1 <= b1 && a2 <= b2 && (a1 < b1 || a2 < b2);
}

// Keeps the non-dominated points seen so far, sorted by f2 ascending (so f1 descending).
// Points equal in both objectives keep the first one inserted.
template <typename Payload>
class ParetoArchive {
 public:
  // Returns whether the point joined the set.
  bool insert(double f1, double f2, const Payload& payload) {
    for (const auto& p : points_)
      if (dominates(p.f1, p.f2, f1, f2) || (p.f1 == f1 && p.f2 == f2)) return false;
    std::erase_if(points_, [&](const auto& p) { return dominates(f1, f2, p.f1, p.f2); });
    const auto at = std::lower_bound(points_.begin(), points_.end(), f2,
                                     [](const auto& p, double v) { return p.f2 < v; });
    points_.insert(at, TradeOffPoint<Payload>{f1, f2, payload});
    return true;
  }
  const std::vector<TradeOffPoint<Payload>>& points() const { return points_; }
  std::size_t size() const { return points_.size(); }

 private:
  std::vector<TradeOffPoint<Payload>> points_;
};

// Indices of at most `count` points of a set sorted by f2, spread evenly along f2 and always
// including both ends.
std::vector<std::size_t> spreadIndices(const std::vector<double>& sortedF2, std::size_t count);

}  // namespace fivebar::design
