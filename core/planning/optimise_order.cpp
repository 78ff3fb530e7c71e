// SPDX-License-Identifier: GPL-3.0-or-later
// Stroke ordering: greedy nearest neighbour and 2-opt. Contract: optimise_order.hpp.
#include "core/planning/optimise_order.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <memory>

namespace fivebar::order {
namespace {

constexpr int kNeighbours = 5;  // neighbour-list length of the 2-opt

// Uniform bucket grid over a set of scaled nodes in one flat array (bucket b holds
// items_[first_[b] .. first_[b] + count_[b])); supports lazy deletion via `alive`.
class NodeGrid {
 public:
  NodeGrid(const std::vector<Vec2>& pts, const std::vector<int>& ids) {
    Eigen::AlignedBox2d box;
    for (int id : ids) box.extend(pts[id]);
    lo_ = box.min();
    const Vec2 size = (box.max() - box.min()).cwiseMax(1e-12);
    const double cells = std::max<double>(1.0, 0.5 * static_cast<double>(ids.size()));
    cell_ = std::max(std::sqrt(size.x() * size.y() / cells), 1e-3 * size.maxCoeff());
    nx_ = std::min(4096, static_cast<int>(size.x() / cell_) + 1);
    ny_ = std::min(4096, static_cast<int>(size.y() / cell_) + 1);
    cell_ = std::max(size.x() / nx_, size.y() / ny_) * (1.0 + 1e-9);
    const std::size_t nb = static_cast<std::size_t>(nx_) * ny_;
    first_.assign(nb + 1, 0);
    count_.assign(nb, 0);
    for (int id : ids) ++count_[bucketOf(pts[id])];
    for (std::size_t b = 0; b < nb; ++b) first_[b + 1] = first_[b] + count_[b];
    items_.resize(ids.size());
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (int id : ids) items_[fill[bucketOf(pts[id])]++] = id;
  }
  // Visits alive nodes in rings of cells around p until `done(bound)` holds, where bound is a
  // lower bound on the distance of every node not yet visited.
  template <class Visit, class Done>
  void search(const Vec2& p, Visit&& visit, Done&& done) {
    const int cx = cellX(p.x()), cy = cellY(p.y());
    const int maxRing = std::max(nx_, ny_);
    for (int r = 0; r <= maxRing; ++r) {
      for (int y = std::max(cy - r, 0); y <= std::min(cy + r, ny_ - 1); ++y) {
        const bool edgeRow = (y == cy - r || y == cy + r);
        for (int x = cx - r; x <= cx + r; x += edgeRow ? 1 : 2 * std::max(r, 1)) {
          if (x >= 0 && x < nx_) visitBucket(static_cast<std::size_t>(y) * nx_ + x, visit);
          if (r == 0) break;
        }
      }
      if (done(r * cell_)) return;
    }
  }
  std::vector<char> alive;  // indexed by node id; empty = all alive

 private:
  template <class Visit>
  void visitBucket(std::size_t b, Visit& visit) {
    int* items = items_.data() + first_[b];
    for (int k = 0; k < count_[b];) {
      if (!alive.empty() && !alive[items[k]]) {
        items[k] = items[--count_[b]];
        continue;
      }
      visit(items[k]);
      ++k;
    }
  }
  int cellX(double v) const { return std::clamp(static_cast<int>((v - lo_.x()) / cell_), 0, nx_ - 1); }
  int cellY(double v) const { return std::clamp(static_cast<int>((v - lo_.y()) / cell_), 0, ny_ - 1); }
  std::size_t bucketOf(const Vec2& p) const {
    return static_cast<std::size_t>(cellY(p.y())) * nx_ + cellX(p.x());
  }
  Vec2 lo_;
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> first_, count_, items_;
};


// k nearest nodes of other strokes, computed on first use: 2-opt only asks for the nodes at
// the ends of long edges.
class NeighbourLists {
 public:
  explicit NeighbourLists(const Ends& e) : e_(e), grid_(e.node, allIds(e)), lists_(e.node.size()),
                                           have_(e.node.size(), 0) {}
  const std::array<int, kNeighbours>& of(int node) {
    if (!have_[node]) compute(node);
    return lists_[node];
  }

 private:
  static std::vector<int> allIds(const Ends& e) {
    std::vector<int> ids(e.node.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<int>(i);
    return ids;
  }
  void compute(int node) {
    best_.clear();
    const Vec2 p = e_.node[node];
    grid_.search(p, [&](int id) {
      if (id / 2 != node / 2) best_.push_back({cost(p, e_.node[id]), id});
    }, [&](double bound) {
      if (best_.size() < kNeighbours) return false;
      std::nth_element(best_.begin(), best_.begin() + kNeighbours - 1, best_.end());
      best_.resize(kNeighbours);
      return std::max_element(best_.begin(), best_.end())->first <= bound;
    });
    std::sort(best_.begin(), best_.end());
    lists_[node].fill(-1);
    for (std::size_t k = 0; k < best_.size() && k < kNeighbours; ++k) lists_[node][k] = best_[k].second;
    have_[node] = 1;
  }
  const Ends& e_;
  NodeGrid grid_;
  std::vector<std::array<int, kNeighbours>> lists_;
  std::vector<char> have_;
  std::vector<std::pair<double, int>> best_;
};

// 2-opt on the open tour (fixed start node when given) with segment reversal; strokes inside a
// reversed segment are flipped, which keeps the cost symmetric. A move reverses at most
// kMaxReversal strokes, so that a step costs microseconds on a tour of any length (the greedy
// tour's long jumps are mostly repaired by partners close to them in tour order).
constexpr int kMaxReversal = 1000;
class TwoOpt {
 public:
  TwoOpt(const Ends& e, Tour& t, const std::optional<Vec2>& start)
      : e_(e), t_(t), start_(start), n_(static_cast<int>(t.order.size())), pos_(t.order.size()) {
    for (int p = 0; p < n_; ++p) pos_[t.order[p]] = p;
  }
  // Runs passes until none improves, or the pass / step budget ends. Only edges longer than
  // the median edge of the starting tour are worked on: greedy leaves its waste in long jumps.
  void run(int maxPasses, std::size_t& stepsLeft) {
    if (maxPasses <= 0 || n_ < 3) return;
    std::vector<double> edges;
    for (int p = 0; p + 1 < n_; ++p) edges.push_back(cost(exit(p), entry(p + 1)));
    std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
    const double longEdge = edges[edges.size() / 2];
    NeighbourLists nbr(e_);
    for (int pass = 0; pass < maxPasses; ++pass) {
      bool improved = false;
      for (int p = 0; p + 1 < n_; ++p) {
        if (cost(exit(p), entry(p + 1)) <= longEdge) continue;
        if (stepsLeft == 0) return;
        --stepsLeft;
        improved |= tryForward(p, nbr) || tryBackward(p, nbr);
      }
      if (!improved) return;
    }
  }

 private:
  Vec2 entry(int p) const { return e_.node[2 * t_.order[p] + (t_.flip[p] ? 1 : 0)]; }
  Vec2 exit(int p) const { return e_.node[2 * t_.order[p] + (t_.flip[p] ? 0 : 1)]; }
  bool isExitNode(int node) const { const int p = pos_[node / 2]; return (node % 2 == 1) != (t_.flip[p] != 0); }
  // Cost of arriving at position p's entry from p's predecessor (0 at a free start).
  double inCost(int p, const Vec2& at) const {
    if (p > 0) return cost(exit(p - 1), at);
    return start_ ? cost(*start_, at) : 0.0;
  }
  double outCost(int p, const Vec2& from) const { return p + 1 < n_ ? cost(from, entry(p + 1)) : 0.0; }
  // New edge exit(p) -> exit(q), q > p: reverse [p+1, q].
  bool tryForward(int p, NeighbourLists& nbr) {
    const Vec2 a = exit(p), b = entry(p + 1);
    const double dab = cost(a, b);
    for (int c : nbr.of(2 * t_.order[p] + (t_.flip[p] ? 0 : 1))) {
      if (c < 0 || cost(a, e_.node[c]) >= dab) break;
      const int q = pos_[c / 2];
      if (q <= p || q - p > kMaxReversal || !isExitNode(c)) continue;
      const double gain = dab + outCost(q, exit(q)) - cost(a, exit(q)) - outCost(q, b);
      if (gain > 1e-12) return reverse(p + 1, q), true;
    }
    return false;
  }
  // New edge entry(q) -> entry(p+1), q <= p: reverse [q, p].
  bool tryBackward(int p, NeighbourLists& nbr) {
    const Vec2 a = exit(p), b = entry(p + 1);
    const double dab = cost(a, b);
    for (int c : nbr.of(2 * t_.order[p + 1] + (t_.flip[p + 1] ? 1 : 0))) {
      if (c < 0 || cost(b, e_.node[c]) >= dab) break;
      const int q = pos_[c / 2];
      if (q > p || p - q > kMaxReversal || isExitNode(c)) continue;
      const double gain = inCost(q, entry(q)) + dab - inCost(q, a) - cost(entry(q), b);
      if (gain > 1e-12) return reverse(q, p), true;
    }
    return false;
  }
  void reverse(int i, int j) {
    for (; i < j; ++i, --j) {
      std::swap(t_.order[i], t_.order[j]);
      std::swap(t_.flip[i], t_.flip[j]);
      t_.flip[i] ^= 1, t_.flip[j] ^= 1;
      pos_[t_.order[i]] = i, pos_[t_.order[j]] = j;
    }
    if (i == j) t_.flip[i] ^= 1;
  }
  const Ends& e_;
  Tour& t_;
  std::optional<Vec2> start_;
  int n_;
  std::vector<int> pos_;
};

}  // namespace

Tour greedyTour(const Ends& e, std::size_t n, const std::optional<Vec2>& start, bool allowReverse) {
  Tour t;
  std::vector<char> taken(n, 0);
  std::vector<int> ids;
  for (std::size_t i = 0; i < n; ++i) {
    ids.push_back(static_cast<int>(2 * i));
    if (allowReverse) ids.push_back(static_cast<int>(2 * i + 1));
  }
  Vec2 cur = start ? *start : e.node[0];
  std::size_t remaining = n, builtFor = n;
  auto grid = std::make_unique<NodeGrid>(e.node, ids);
  grid->alive.assign(e.node.size(), 1);
  while (remaining > 0) {
    if (remaining * 4 < builtFor && remaining > 64) {  // shrink the grid as it empties
      std::vector<int> live;
      for (int id : ids)
        if (!taken[id / 2]) live.push_back(id);
      ids.swap(live);
      auto alive = std::move(grid->alive);
      grid = std::make_unique<NodeGrid>(e.node, ids);
      grid->alive = std::move(alive);
      builtFor = remaining;
    }
    int best = -1;
    double bestCost = std::numeric_limits<double>::infinity();
    if (!start && t.order.empty()) best = 0;  // no start pose: the first stroke stays first
    else
      grid->search(cur, [&](int id) {
        const double c = cost(cur, e.node[id]);
        if (c < bestCost || (c == bestCost && id < best)) bestCost = c, best = id;
      }, [&](double bound) { return best >= 0 && bestCost <= bound; });
    const int s = best / 2;
    taken[s] = 1;
    grid->alive[2 * s] = 0;
    grid->alive[2 * s + 1] = 0;
    t.order.push_back(s);
    t.flip.push_back(static_cast<char>(best % 2));
    cur = e.node[best % 2 ? 2 * s : 2 * s + 1];
    --remaining;
  }
  return t;
}

void twoOpt(const Ends& e, Tour& t, const std::optional<Vec2>& start, int maxPasses,
            std::size_t& stepsLeft) {
  TwoOpt(e, t, start).run(maxPasses, stepsLeft);
}

// Travel cost (s) of a tour in the scaled joint space, and of the input order.
double tourCost(const Ends& e, const Tour& t, const std::optional<Vec2>& start) {
  double c = 0.0;
  std::optional<Vec2> at = start;
  for (std::size_t p = 0; p < t.order.size(); ++p) {
    const int s = t.order[p];
    if (at) c += cost(*at, e.node[2 * s + (t.flip[p] ? 1 : 0)]);
    at = e.node[2 * s + (t.flip[p] ? 0 : 1)];
  }
  return c;
}
double inputCost(const Ends& e, const std::optional<Vec2>& start) {
  Tour t;
  t.order.resize(e.node.size() / 2);
  for (std::size_t i = 0; i < t.order.size(); ++i) t.order[i] = static_cast<int>(i);
  t.flip.assign(t.order.size(), 0);
  return tourCost(e, t, start);
}

}  // namespace fivebar::order
