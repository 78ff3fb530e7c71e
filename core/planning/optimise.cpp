// SPDX-License-Identifier: GPL-3.0-or-later
// Stroke optimisation: join, simplify, reorder (greedy nearest neighbour on a joint-space grid,
// then 2-opt with neighbour lists). Contract: optimise.hpp.
#include "core/planning/optimise.hpp"

#include <algorithm>
#include <limits>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "core/machine/pen_kinematics.hpp"
#include "core/planning/optimise_order.hpp"

namespace fivebar {
namespace {

using Clock = std::chrono::steady_clock;

// Joint angles that put the profile's pen (its calibrated pen offset honoured) on an end point in
// `mode`; pseudo angles (chord directions) when out of reach.
JointAngles endAngles(const MachineProfile& profile, const Vec2& p, WorkingMode mode) {
  const Geometry& g = profile.geometry;
  const IkResult ik = penInverse(g, calibratedPenOffset(profile), p, mode);
  if (ik.ok()) return ik.angles;
  const Vec2 c1 = p - g.motor1(), c2 = p - g.motor2();
  return {std::atan2(c1.y(), c1.x()), std::atan2(c2.y(), c2.x())};
}

// ---- joining -------------------------------------------------------------------------------

// Endpoints of one run of strokes on a grid of pitch 2 x join tolerance: the points within the
// tolerance of p lie in the 2 x 2 cells nearest to p. Entries are sorted by cell key and an
// open-addressing table maps a key to its first entry, so a query costs a few probes.
class EndpointHash {
 public:
  explicit EndpointHash(double toleranceMm) : cell_(std::max(2.0 * toleranceMm, 1e-9)) {}
  void insert(const Vec2& p, int id) {
    if (p.allFinite()) entries_.push_back({key(cellOf(p.x()), cellOf(p.y())), id});
  }
  void finish() {
    std::sort(entries_.begin(), entries_.end());
    std::size_t size = 16;
    shift_ = 60;
    while (size < 2 * entries_.size()) size *= 2, --shift_;
    table_.assign(size, {0, -1});
    for (std::size_t i = 0; i < entries_.size(); ++i)
      if (i == 0 || entries_[i].first != entries_[i - 1].first) {
        std::size_t h = slot(entries_[i].first);
        while (table_[h].second >= 0) h = (h + 1) & (table_.size() - 1);
        table_[h] = {entries_[i].first, static_cast<int>(i)};
      }
  }
  template <class F>
  void forEachNear(const Vec2& p, F&& f) const {
    if (!p.allFinite()) return;
    const double fx = p.x() / cell_, fy = p.y() / cell_;
    const std::int64_t cx = static_cast<std::int64_t>(std::floor(fx));
    const std::int64_t cy = static_cast<std::int64_t>(std::floor(fy));
    const std::int64_t nx = fx - static_cast<double>(cx) < 0.5 ? cx - 1 : cx + 1;
    const std::int64_t ny = fy - static_cast<double>(cy) < 0.5 ? cy - 1 : cy + 1;
    for (std::int64_t y : {cy, ny})
      for (std::int64_t x : {cx, nx}) {
        const std::uint64_t k = key(x, y);
        for (std::size_t h = slot(k); table_[h].second >= 0; h = (h + 1) & (table_.size() - 1))
          if (table_[h].first == k) {
            for (std::size_t i = static_cast<std::size_t>(table_[h].second);
                 i < entries_.size() && entries_[i].first == k; ++i)
              f(entries_[i].second);
            break;
          }
      }
  }

 private:
  std::int64_t cellOf(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(y) & 0xffffffffu);
  }
  std::size_t slot(std::uint64_t k) const {
    return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  double cell_;
  int shift_ = 60;  // 64 - log2(table size): multiplicative hashing keeps the top bits
  std::vector<std::pair<std::uint64_t, int>> entries_;
  std::vector<std::pair<std::uint64_t, int>> table_;  // key -> first entry; second < 0 = empty
};

struct Piece {
  int stroke;
  bool reversed;
};

void appendPoints(std::vector<Vec2>& out, const Stroke& s, bool reversed) {
  const auto add = [&](const Vec2& p) {
    if (out.empty() || out.back() != p) out.push_back(p);  // drop only an exact duplicate
  };
  if (reversed)
    std::for_each(s.points.rbegin(), s.points.rend(), add);
  else
    std::for_each(s.points.begin(), s.points.end(), add);
}

// Joins chains of strokes of one layer whose ends meet within the tolerance. Endpoint id
// 2 i = start of stroke i, 2 i + 1 = its end.
std::vector<Stroke> joinRun(std::vector<Stroke> run, const OptimiseOptions& o, std::size_t& joins) {
  EndpointHash hash(o.joinToleranceMm);
  for (std::size_t i = 0; i < run.size(); ++i) {
    hash.insert(run[i].points.front(), static_cast<int>(2 * i));
    hash.insert(run[i].points.back(), static_cast<int>(2 * i + 1));
  }
  hash.finish();
  std::vector<char> used(run.size(), 0);
  const double tol2 = o.joinToleranceMm * o.joinToleranceMm;
  // An unused stroke with an end near p: wantStart selects its start (kept direction) or end.
  auto find = [&](const Vec2& p, bool wantStart) -> std::optional<Piece> {
    std::optional<Piece> best;
    hash.forEachNear(p, [&](int id) {
      const int s = id / 2;
      const bool isStart = (id % 2) == 0;
      if (best || used[s]) return;
      const Vec2& q = isStart ? run[s].points.front() : run[s].points.back();
      if ((q - p).squaredNorm() > tol2) return;
      if (isStart == wantStart) best = Piece{s, false};
      else if (o.allowReverse) best = Piece{s, true};
    });
    return best;
  };
  std::vector<Stroke> out;
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (used[i]) continue;
    used[i] = 1;
    std::vector<Piece> chain{{static_cast<int>(i), false}};
    auto endOf = [&](const Piece& pc) { return pc.reversed ? run[pc.stroke].points.front() : run[pc.stroke].points.back(); };
    auto startOf = [&](const Piece& pc) { return pc.reversed ? run[pc.stroke].points.back() : run[pc.stroke].points.front(); };
    while (auto next = find(endOf(chain.back()), true)) {
      used[next->stroke] = 1;
      chain.push_back(*next);
    }
    std::vector<Piece> before;
    while (auto prev = find(startOf(before.empty() ? chain.front() : before.back()), false)) {
      used[prev->stroke] = 1;
      before.push_back(*prev);
    }
    std::reverse(before.begin(), before.end());
    chain.insert(chain.begin(), before.begin(), before.end());
    joins += chain.size() - 1;
    Stroke joined;
    joined.layerIndex = run[chain.front().stroke].layerIndex;
    joined.pathIndex = run[chain.front().stroke].pathIndex;
    joined.reversed = run[chain.front().stroke].reversed != chain.front().reversed;
    if (chain.size() == 1) {
      out.push_back(std::move(run[i]));
      continue;
    }
    for (const Piece& pc : chain) {
      const Stroke& part = run[pc.stroke];
      if (!joined.points.empty()) {  // the bridge from the chain so far to this piece
        const Vec2& start = pc.reversed ? part.points.back() : part.points.front();
        joined.bridgedGapMm = std::max(joined.bridgedGapMm, (start - joined.points.back()).norm());
      }
      joined.bridgedGapMm = std::max(joined.bridgedGapMm, part.bridgedGapMm);
      appendPoints(joined.points, part, pc.reversed);
      joined.flattened = joined.flattened || part.flattened;
    }
    out.push_back(std::move(joined));
  }
  return out;
}

// ---- ordering ------------------------------------------------------------------------------

using order::Ends;
using order::Tour;

Ends scaledEnds(const std::vector<Stroke>& run, const MachineProfile& pr, WorkingMode mode,
                const JointAngles& reference) {
  Ends e;
  e.node.resize(2 * run.size());
  const double v1 = pr.motors.maxSpeedRadPerS1, v2 = pr.motors.maxSpeedRadPerS2;
  for (std::size_t i = 0; i < run.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const JointAngles q =
          endAngles(pr, k == 0 ? run[i].points.front() : run[i].points.back(), mode);
      const Vec2 node(unwrapNear(q.theta1, reference.theta1) / v1,
                      unwrapNear(q.theta2, reference.theta2) / v2);
      // A non-finite point (bad input, reported by preflight) must not poison the grid.
      e.node[2 * i + k] = node.allFinite() ? node : Vec2(reference.theta1 / v1, reference.theta2 / v2);
    }
  return e;
}

void applyTour(std::vector<Stroke>& run, const Tour& t) {
  std::vector<Stroke> out;
  out.reserve(run.size());
  for (std::size_t p = 0; p < t.order.size(); ++p) {
    Stroke s = std::move(run[t.order[p]]);
    if (t.flip[p]) {
      std::reverse(s.points.begin(), s.points.end());
      s.reversed = !s.reversed;
    }
    out.push_back(std::move(s));
  }
  run.swap(out);
}

}  // namespace

double jointTravelTimeS(const MotorSettings& motors, const JointAngles& a, const JointAngles& b) {
  return std::max(std::abs(normalizeRad(b.theta1 - a.theta1)) / motors.maxSpeedRadPerS1,
                  std::abs(normalizeRad(b.theta2 - a.theta2)) / motors.maxSpeedRadPerS2);
}

double travelTimeS(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                   WorkingMode mode, const std::optional<JointAngles>& start) {
  double total = 0.0;
  std::optional<JointAngles> at = start;
  for (const Stroke& s : strokes) {
    if (s.points.empty()) continue;
    const JointAngles first = endAngles(profile, s.points.front(), mode);
    if (at) total += jointTravelTimeS(profile.motors, *at, first);
    at = endAngles(profile, s.points.back(), mode);
  }
  return total;
}

std::vector<Vec2> simplifyPolyline(const std::vector<Vec2>& points, double toleranceMm) {
  if (points.size() < 3 || !(toleranceMm > 0.0)) return points;
  std::vector<char> keep(points.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, points.size() - 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const Vec2 a = points[i], ab = points[j] - a;
    const double len2 = ab.squaredNorm();
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
      const Vec2 ap = points[k] - a;
      const double t = len2 > 0.0 ? std::clamp(ap.dot(ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (ap - t * ab).norm();
      if (d > worst) worst = d, at = k;
    }
    if (worst > toleranceMm) {
      keep[at] = 1;
      stack.push_back({i, at});
      stack.push_back({at, j});
    }
  }
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (keep[k]) out.push_back(points[k]);
  return out;
}

OptimiseResult optimise(std::vector<Stroke> strokes, const MachineProfile& profile,
                        WorkingMode mode, const OptimiseOptions& options) {
  const auto t0 = Clock::now();
  OptimiseResult r;
  std::erase_if(strokes, [](const Stroke& s) { return s.points.empty(); });
  r.report.strokesBefore = strokes.size();
  for (const Stroke& s : strokes) r.report.pointsBefore += s.points.size();
  if (options.measureTravel)
    r.report.travelBeforeS = travelTimeS(strokes, profile, mode, options.start);
  std::size_t stepsLeft = options.maxTwoOptSteps > 0 ? options.maxTwoOptSteps
                                                     : std::numeric_limits<std::size_t>::max();
  std::optional<JointAngles> at = options.start;
  for (std::size_t b = 0; b < strokes.size();) {
    std::size_t e = b;
    while (e < strokes.size() && strokes[e].layerIndex == strokes[b].layerIndex) ++e;
    std::vector<Stroke> run(std::make_move_iterator(strokes.begin() + b),
                            std::make_move_iterator(strokes.begin() + e));
    if (options.join) run = joinRun(std::move(run), options, r.report.joins);
    if (options.simplifyToleranceMm > 0.0)
      for (Stroke& s : run) s.points = simplifyPolyline(s.points, options.simplifyToleranceMm);
    if (options.reorder && run.size() > 1) {
      JointAngles ref = at ? *at : endAngles(profile, run.front().points.front(), mode);
      if (!std::isfinite(ref.theta1) || !std::isfinite(ref.theta2)) ref = {};
      const Ends ends = scaledEnds(run, profile, mode, ref);
      std::optional<Vec2> start;
      if (at) start = Vec2(ref.theta1 / profile.motors.maxSpeedRadPerS1, ref.theta2 / profile.motors.maxSpeedRadPerS2);
      Tour tour = order::greedyTour(ends, run.size(), start, options.allowReverse);
      if (options.allowReverse)
        order::twoOpt(ends, tour, start, options.maxTwoOptPasses, stepsLeft);
      if (order::tourCost(ends, tour, start) <= order::inputCost(ends, start)) applyTour(run, tour);
    }
    if (!run.empty()) at = endAngles(profile, run.back().points.back(), mode);
    for (Stroke& s : run) r.strokes.push_back(std::move(s));
    b = e;
  }
  r.report.strokesAfter = r.strokes.size();
  for (const Stroke& s : r.strokes) r.report.pointsAfter += s.points.size();
  if (options.measureTravel)
    r.report.travelAfterS = travelTimeS(r.strokes, profile, mode, options.start);
  r.report.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace fivebar