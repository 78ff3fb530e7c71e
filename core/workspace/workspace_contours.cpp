// SPDX-License-Identifier: GPL-3.0-or-later
// Marching squares on cell-centre samples, with the segments joined into polylines.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

// A contour crossing lies on a grid edge between two neighbouring sample nodes; its key names
// the edge (horizontal edges even, vertical edges odd) so that neighbouring squares share it.
struct Crossing {
  std::uint64_t key = 0;
  Vec2 point = Vec2::Zero();
};
struct Segment {
  Crossing a, b;
};

class SegmentCollector {
 public:
  SegmentCollector(const GridSpec& grid, std::span<const float> v) : grid_(grid), v_(v) {}

  // The segments of square (ix, iy)..(ix+1, iy+1) appended to `out`.
  void square(int ix, int iy, std::vector<Segment>& out) const {
    const double bl = at(ix, iy), br = at(ix + 1, iy), tr = at(ix + 1, iy + 1), tl = at(ix, iy + 1);
    if (std::isnan(bl) || std::isnan(br) || std::isnan(tr) || std::isnan(tl)) return;
    const int code = (bl > 0) | (br > 0) << 1 | (tr > 0) << 2 | (tl > 0) << 3;
    if (code == 0 || code == 15) return;
    // Edges: 0 bottom (bl-br), 1 right (br-tr), 2 top (tl-tr), 3 left (bl-tl).
    const std::array<Crossing, 4> e{horizontal(ix, iy, bl, br), vertical(ix + 1, iy, br, tr),
                                    horizontal(ix, iy + 1, tl, tr), vertical(ix, iy, bl, tl)};
    const bool centreInside = (bl + br + tr + tl) > 0;
    if (code == 5 || code == 10) {  // saddle: cut off the two corners not joined through the centre
      const bool cutBlTr = (code == 5) != centreInside;
      if (cutBlTr) {
        out.push_back({e[3], e[0]});
        out.push_back({e[1], e[2]});
      } else {
        out.push_back({e[0], e[1]});
        out.push_back({e[2], e[3]});
      }
      return;
    }
    const bool crossed[4] = {(bl > 0) != (br > 0), (br > 0) != (tr > 0), (tl > 0) != (tr > 0),
                             (bl > 0) != (tl > 0)};
    int first = -1;
    for (int k = 0; k < 4; ++k) {
      if (!crossed[k]) continue;
      if (first < 0) first = k;
      else out.push_back({e[first], e[k]});
    }
  }

 private:
  double at(int ix, int iy) const { return v_[grid_.index(ix, iy)]; }
  static double fraction(double v0, double v1) { return v0 / (v0 - v1); }
  Crossing horizontal(int ix, int iy, double v0, double v1) const {
    const double t = (v0 > 0) != (v1 > 0) ? fraction(v0, v1) : 0.5;
    return {(static_cast<std::uint64_t>(grid_.index(ix, iy)) << 1),
            Vec2(grid_.xCenter(ix) + t * grid_.cellMm, grid_.yCenter(iy))};
  }
  Crossing vertical(int ix, int iy, double v0, double v1) const {
    const double t = (v0 > 0) != (v1 > 0) ? fraction(v0, v1) : 0.5;
    return {(static_cast<std::uint64_t>(grid_.index(ix, iy)) << 1) | 1U,
            Vec2(grid_.xCenter(ix), grid_.yCenter(iy) + t * grid_.cellMm)};
  }

  const GridSpec& grid_;
  std::span<const float> v_;
};

// Joins segments sharing crossings into polylines.
std::vector<Polyline> chain(const std::vector<Segment>& segments) {
  std::unordered_map<std::uint64_t, std::array<int, 2>> byKey;
  byKey.reserve(segments.size() * 2);
  auto link = [&](std::uint64_t key, int s) {
    auto [it, inserted] = byKey.try_emplace(key, std::array<int, 2>{-1, -1});
    (it->second[0] < 0 ? it->second[0] : it->second[1]) = s;
  };
  for (int s = 0; s < static_cast<int>(segments.size()); ++s) {
    link(segments[s].a.key, s);
    link(segments[s].b.key, s);
  }
  std::vector<bool> used(segments.size(), false);
  // Next unused segment at `key`, other than `from`; -1 when none.
  auto next = [&](std::uint64_t key, int from) {
    for (int s : byKey[key])
      if (s >= 0 && s != from && !used[s]) return s;
    return -1;
  };
  std::vector<Polyline> out;
  for (int start = 0; start < static_cast<int>(segments.size()); ++start) {
    if (used[start]) continue;
    used[start] = true;
    std::vector<Crossing> forward{segments[start].a, segments[start].b};
    // Extend from the b end, then from the a end (backwards).
    for (int pass = 0; pass < 2; ++pass) {
      int from = start;
      for (int s = next(forward.back().key, from); s >= 0; s = next(forward.back().key, from)) {
        used[s] = true;
        forward.push_back(segments[s].a.key == forward.back().key ? segments[s].b : segments[s].a);
        from = s;
      }
      std::reverse(forward.begin(), forward.end());
    }
    Polyline line;
    line.closed = forward.size() > 2 && forward.front().key == forward.back().key;
    if (line.closed) forward.pop_back();
    line.points.reserve(forward.size());
    for (const Crossing& c : forward) line.points.push_back(c.point);
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace

std::vector<Polyline> contoursOf(const GridSpec& grid, std::span<const float> values) {
  std::vector<Segment> segments;
  if (grid.nx < 2 || grid.ny < 2 || values.size() != grid.size()) return {};
  const SegmentCollector collector(grid, values);
  for (int iy = 0; iy + 1 < grid.ny; ++iy)
    for (int ix = 0; ix + 1 < grid.nx; ++ix) collector.square(ix, iy, segments);
  return chain(segments);
}

}  // namespace fivebar
