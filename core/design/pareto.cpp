// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/design/pareto.hpp"

#include <cmath>

namespace fivebar::design {

std::vector<std::size_t> spreadIndices(const std::vector<double>& sortedF2, std::size_t count) {
  const std::size_t n = sortedF2.size();
  std::vector<std::size_t> out;
  if (n == 0 || count == 0) return out;
  if (n <= count) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  // Target values evenly spaced between the ends; each takes the nearest unused point.
  const double lo = sortedF2.front(), hi = sortedF2.back();
  std::size_t next = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double target = count == 1 ? lo : lo + (hi - lo) * static_cast<double>(k) / (count - 1);
    std::size_t best = next;
    for (std::size_t i = next; i < n; ++i) {
      if (std::abs(sortedF2[i] - target) < std::abs(sortedF2[best] - target)) best = i;
      if (sortedF2[i] > target) break;
    }
    if (k == count - 1) best = n - 1;
    if (!out.empty() && best <= out.back()) continue;
    out.push_back(best);
    next = best + 1;
    if (next >= n) break;
  }
  return out;
}

}  // namespace fivebar::design
