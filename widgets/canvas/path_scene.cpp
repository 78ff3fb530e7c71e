// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/path_scene.hpp"

#include <QPen>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/support/memory_hint.hpp"
#include "paint/studio_palette.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kGrid = 32;                // buckets per side
constexpr int kMaxLevels = 8;
constexpr double kFirstToleranceMm = 0.02;
constexpr double kLevelFactor = 4.0;
constexpr double kHalfPixel = 0.5;
// Stop adding levels once a level keeps more than this share of the previous one's segments.
constexpr double kUselessLevelShare = 0.9;

constexpr std::size_t kMaxMergedPoints = 64;  // bounds the simplification's cost per segment

// Squared distance from q to the segment a-b.
double distance2(const QPointF& q, const QPointF& a, const QPointF& b) {
  const QPointF ab = b - a, aq = q - a;
  const double len2 = ab.x() * ab.x() + ab.y() * ab.y();
  double t = len2 > 0.0 ? (aq.x() * ab.x() + aq.y() * ab.y()) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const QPointF d = aq - t * ab;
  return d.x() * d.x() + d.y() * d.y();
}

// Level-of-detail simplification step: the farthest index j > from (at most kMaxMergedPoints
// ahead, at most `last`) such that every point between `from` and j lies within sqrt(tol2) of
// the chord.
std::size_t farthestWithin(const std::vector<QPointF>& pts, std::size_t from, std::size_t last,
                           double tol2) {
  last = std::min(last, from + kMaxMergedPoints);
  std::size_t best = from + 1;
  for (std::size_t j = from + 2; j <= last; ++j) {
    bool ok = true;
    for (std::size_t k = from + 1; k < j && ok; ++k) ok = distance2(pts[k], pts[from], pts[j]) <= tol2;
    if (!ok) break;
    best = j;
  }
  return best;
}

// One pyramid step: each path's points simplified within toleranceMm; a kept segment carries
// the order and colour class of the first segment it replaces (a path has one kind, so only the
// speed shade, a sub-pixel detail at that level, can be approximated).
PathScene::LevelPaths simplifyLevel(const PathScene::LevelPaths& in, double toleranceMm) {
  const double tol2 = toleranceMm * toleranceMm;
  PathScene::LevelPaths out;
  out.points.reserve(in.points.size());
  out.orders.reserve(in.points.size());
  out.classes.reserve(in.points.size());
  out.begin.reserve(in.begin.size());
  const auto keep = [&](std::size_t k) {
    out.points.push_back(in.points[k]);
    out.orders.push_back(in.orders[k]);
    out.classes.push_back(in.classes[k]);
  };
  for (std::size_t i = 0; i < in.pathCount(); ++i) {
    const std::size_t first = in.begin[i], last = in.begin[i + 1] - 1;
    std::size_t kept = first;
    keep(kept);
    while (kept < last) {
      kept = last - kept == 1 ? last : farthestWithin(in.points, kept, last, tol2);
      keep(kept);
    }
    out.begin.push_back(out.points.size());
  }
  return out;
}

// A level's simplified paths, as the bucketing reads them.
struct LevelView {
  const PathScene::LevelPaths& p;
  std::size_t pathCount() const { return p.pathCount(); }
  std::size_t segmentCount() const { return p.segmentCount(); }
  std::size_t begin(std::size_t i) const { return p.begin[i]; }
  std::size_t end(std::size_t i) const { return p.begin[i + 1]; }
  const QPointF& point(std::size_t k) const { return p.points[k]; }
  int order(std::size_t, std::size_t k) const { return p.orders[k]; }
  int colourClass(std::size_t, std::size_t k) const { return p.classes[k]; }
};

// Colour class of the segment that starts at point k of path p: travel, problem, or the speed
// shade (the fastest shade without speeds).
struct Classifier {
  const ScenePathList& list;
  double speedScale = 0.0;
  int operator()(const ScenePathList::Info& p, std::size_t k) const {
    if (p.kind == PathKind::Travel) return PathScene::kTravelClass;
    if (p.flagged) return PathScene::kProblemClass;
    if (list.speedsMmPerS.empty() || std::isnan(list.speedsMmPerS[k])) return 2 + PathScene::kSpeedClasses - 1;
    const double t = list.speedsMmPerS[k] * speedScale;
    return 2 + std::clamp(static_cast<int>(t * PathScene::kSpeedClasses), 0, PathScene::kSpeedClasses - 1);
  }
};

// The scene's own paths (those with a segment, in drawing order), as the bucketing reads them.
struct ListView {
  const ScenePathList& list;
  const std::vector<std::size_t>& byOrder;  // indices into list.paths
  Classifier classOf;
  std::size_t segments = 0;  // of those paths (PathScene counted them)
  std::size_t pathCount() const { return byOrder.size(); }
  std::size_t segmentCount() const { return segments; }
  std::size_t begin(std::size_t i) const { return list.paths[byOrder[i]].pointBegin; }
  std::size_t end(std::size_t i) const { return list.pointEnd(byOrder[i]); }
  const QPointF& point(std::size_t k) const { return list.pointsMm[k]; }
  int order(std::size_t i, std::size_t k) const {
    const ScenePathList::Info& p = list.paths[byOrder[i]];
    return p.firstOrder + static_cast<int>(k - p.pointBegin);
  }
  int colourClass(std::size_t i, std::size_t k) const { return classOf(list.paths[byOrder[i]], k); }
};

}  // namespace

QColor PathScene::speedColour(double t) {
  // A perceptual ramp on a light background: deep blue (slow) -> teal -> amber -> red (fast).
  static const std::array<QColor, 5> stops{QColor(0x31, 0x2e, 0x81), QColor(0x1d, 0x4e, 0xd8),
                                           QColor(0x0d, 0x94, 0x88), QColor(0xd9, 0x77, 0x06),
                                           QColor(0xdc, 0x26, 0x26)};
  t = std::clamp(t, 0.0, 1.0) * (stops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(i);
  const auto mix = [f](int a, int b) { return static_cast<int>(std::lround(a + (b - a) * f)); };
  return QColor(mix(stops[i].red(), stops[i + 1].red()), mix(stops[i].green(), stops[i + 1].green()),
                mix(stops[i].blue(), stops[i + 1].blue()));
}

void ScenePathList::add(const ScenePath& path) {
  beginPath(path.kind, path.flagged, path.firstOrder);
  for (std::size_t k = 0; k < path.pointsMm.size(); ++k) {
    if (path.speedsMmPerS.empty())
      addPoint(path.pointsMm[k]);
    else
      addPoint(path.pointsMm[k], path.speedsMmPerS[std::min(k, path.speedsMmPerS.size() - 1)]);
  }
}

namespace {
ScenePathList listOf(const std::vector<ScenePath>& paths) {
  ScenePathList list;
  std::size_t points = 0;
  for (const ScenePath& p : paths) points += p.pointsMm.size();
  list.pointsMm.reserve(points);
  list.paths.reserve(paths.size());
  for (const ScenePath& p : paths) list.add(p);
  return list;
}
}  // namespace

PathScene::PathScene(const std::vector<ScenePath>& paths) : PathScene(listOf(paths)) {}

PathScene::PathScene(const ScenePathList& paths) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (std::size_t i = 0; i < paths.paths.size(); ++i) {
    const std::size_t begin = paths.paths[i].pointBegin, end = paths.pointEnd(i);
    if (end - begin < 2) continue;
    segmentCount_ += end - begin - 1;
    orderCount_ = std::max(orderCount_, paths.paths[i].firstOrder + static_cast<int>(end - begin) - 1);
    for (std::size_t k = begin; k < end; ++k) {
      const QPointF& q = paths.pointsMm[k];
      x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y());
      x1 = std::max(x1, q.x()), y1 = std::max(y1, q.y());
      if (!paths.speedsMmPerS.empty() && k + 1 < end) maxSpeed_ = std::max(maxSpeed_, paths.speedsMmPerS[k]);
    }
  }
  if (segmentCount_ == 0) return;
  boundsMm_ = QRectF(QPointF(x0, y0), QPointF(x1, y1));
  // Paths in drawing order, so that a stable bucket sort keeps orders ascending (the pipeline's
  // paths come in that order already).
  std::vector<std::size_t> order;
  order.reserve(paths.paths.size());
  for (std::size_t i = 0; i < paths.paths.size(); ++i)
    if (paths.pointEnd(i) - paths.paths[i].pointBegin >= 2) order.push_back(i);
  const auto byOrder = [&](std::size_t a, std::size_t b) {
    return paths.paths[a].firstOrder < paths.paths[b].firstOrder;
  };
  if (!std::is_sorted(order.begin(), order.end(), byOrder)) std::stable_sort(order.begin(), order.end(), byOrder);
  // A simplified path keeps at least one segment: with that many paths (a job or drawing of
  // short lines) no coarser level can be useful, and the one level is bucketed straight from
  // the paths, without copying their points first.
  if (static_cast<double>(order.size()) > kUselessLevelShare * static_cast<double>(segmentCount_)) {
    Level level;
    bucket(ListView{paths, order, Classifier{paths, maxSpeed_ > 0.0f ? 1.0 / maxSpeed_ : 0.0}, segmentCount_}, 0.0,
           level);
    levels_.push_back(std::move(level));
    return;
  }
  // A pyramid: each level simplifies the previous one's points with a 4x larger tolerance, so
  // every level merges at most kMaxMergedPoints of the previous level's points per segment.
  LevelPaths current = baseLevel(paths, order);
  double tolerance = 0.0;
  for (int l = 0; l < kMaxLevels; ++l) {
    if (tolerance > 0.0) {
      // No coarser level can be useful once nearly every segment is a path of its own.
      if (static_cast<double>(current.pathCount()) >
          kUselessLevelShare * static_cast<double>(current.segmentCount()))
        break;
      LevelPaths simpler = simplifyLevel(current, tolerance);
      // A level that keeps nearly every segment (e.g. of two-point paths, where nothing merges)
      // is not worth its memory: the previous one is painted instead.
      if (static_cast<double>(simpler.segmentCount()) >
          kUselessLevelShare * static_cast<double>(current.segmentCount()))
        break;
      current = std::move(simpler);
    }
    Level level;
    bucket(LevelView{current}, tolerance, level);
    levels_.push_back(std::move(level));
    tolerance = (tolerance == 0.0) ? kFirstToleranceMm : tolerance * kLevelFactor;
  }
}

PathScene::LevelPaths PathScene::baseLevel(const ScenePathList& paths,
                                           const std::vector<std::size_t>& order) const {
  const ListView view{paths, order, Classifier{paths, maxSpeed_ > 0.0f ? 1.0 / maxSpeed_ : 0.0}, segmentCount_};
  LevelPaths out;
  const std::size_t points = segmentCount_ + order.size();
  reserveWithHugePages(out.points, points);
  reserveWithHugePages(out.orders, points);
  reserveWithHugePages(out.classes, points);
  reserveWithHugePages(out.begin, order.size() + 1);
  for (std::size_t i = 0; i < view.pathCount(); ++i) {
    const std::size_t begin = view.begin(i), end = view.end(i);
    out.points.insert(out.points.end(), paths.pointsMm.begin() + static_cast<std::ptrdiff_t>(begin),
                      paths.pointsMm.begin() + static_cast<std::ptrdiff_t>(end));
    for (std::size_t k = begin; k < end; ++k) {
      const bool last = k + 1 == end;
      out.orders.push_back(last ? 0 : view.order(i, k));
      out.classes.push_back(static_cast<std::uint8_t>(last ? 0 : view.colourClass(i, k)));
    }
    out.begin.push_back(out.points.size());
  }
  return out;
}

template <typename View>
void PathScene::bucket(const View& paths, double toleranceMm, Level& level) const {
  level.toleranceMm = toleranceMm;
  const double cellW = std::max(boundsMm_.width() / kGrid, 1e-9);
  const double cellH = std::max(boundsMm_.height() / kGrid, 1e-9);
  const auto bucketOf = [&](const QPointF& m) {
    const int bx = std::clamp(static_cast<int>((m.x() - boundsMm_.left()) / cellW), 0, kGrid - 1);
    const int by = std::clamp(static_cast<int>((m.y() - boundsMm_.top()) / cellH), 0, kGrid - 1);
    return by * kGrid + bx;
  };
  // Key (class, bucket) of each segment, segment after segment in drawing order.
  constexpr int kKeys = kClassCount * kGrid * kGrid;
  static_assert(kKeys <= 65536, "keys are stored in 16 bits");
  std::vector<std::uint16_t> keys;
  reserveWithHugePages(keys, paths.segmentCount());
  std::vector<std::size_t> start(kKeys + 1, 0);
  for (std::size_t i = 0; i < paths.pathCount(); ++i)
    for (std::size_t k = paths.begin(i); k + 1 < paths.end(i); ++k) {
      const int key = paths.colourClass(i, k) * kGrid * kGrid +
                      bucketOf((paths.point(k) + paths.point(k + 1)) * 0.5);
      keys.push_back(static_cast<std::uint16_t>(key));
      ++start[static_cast<std::size_t>(key) + 1];
    }
  // Stable counting sort by key.
  std::partial_sum(start.begin(), start.end(), start.begin());
  reserveWithHugePages(level.lines, start.back());
  reserveWithHugePages(level.orders, start.back());
  level.lines.resize(start.back());
  level.orders.resize(start.back());
  struct Box {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  };
  std::vector<Box> boxes(kGrid * kGrid);
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  std::size_t s = 0;
  for (std::size_t i = 0; i < paths.pathCount(); ++i)
    for (std::size_t k = paths.begin(i); k + 1 < paths.end(i); ++k) {
      const int key = keys[s++];
      const std::size_t at = next[static_cast<std::size_t>(key)]++;
      const QPointF& p1 = paths.point(k);
      const QPointF& p2 = paths.point(k + 1);
      level.lines[at] = QLineF(p1, p2);
      level.orders[at] = paths.order(i, k);
      Box& b = boxes[static_cast<std::size_t>(key % (kGrid * kGrid))];
      b.x0 = std::min({b.x0, p1.x(), p2.x()}), b.x1 = std::max({b.x1, p1.x(), p2.x()});
      b.y0 = std::min({b.y0, p1.y(), p2.y()}), b.y1 = std::max({b.y1, p1.y(), p2.y()});
    }
  level.bucketBounds.assign(kGrid * kGrid, QRectF());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (boxes[i].x0 <= boxes[i].x1)
      level.bucketBounds[i] = QRectF(QPointF(boxes[i].x0 - 1e-6, boxes[i].y0 - 1e-6),
                                     QPointF(boxes[i].x1 + 1e-6, boxes[i].y1 + 1e-6));
  for (int key = 0; key < kKeys; ++key) {
    if (start[key] == start[key + 1]) continue;
    level.runs.push_back({key / (kGrid * kGrid), key % (kGrid * kGrid), start[key], start[key + 1]});
  }
}

int PathScene::levelFor(double pxPerMm) const {
  const double halfPixelMm = kHalfPixel / pxPerMm;
  int best = 0;
  for (int l = 0; l < levelCount(); ++l) {
    if (levels_[l].toleranceMm <= halfPixelMm) best = l;
  }
  return best;
}

std::size_t PathScene::segmentCount(int level) const {
  return (level >= 0 && level < levelCount()) ? levels_[level].lines.size() : 0;
}

void PathScene::paint(QPainter& painter, const paint::ViewTransform& view,
                      const ScenePaintOptions& options) const {
  if (levels_.empty()) return;
  const Level& level = levels_[levelFor(view.pxPerMm())];
  const QRectF visible = options.machineFromScene.isIdentity()
      ? view.visibleMachineRect()
      : options.machineFromScene.inverted().mapRect(view.visibleMachineRect());
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, false);
  painter.setTransform(options.machineFromScene * view.widgetFromMachine(), true);
  painter.setOpacity(painter.opacity() * options.opacity);
  const QColor drawColour = options.drawColour.isValid() ? options.drawColour : paint::palette::drawing();
  int currentClass = -1;
  for (const Run& run : level.runs) {
    if (run.colourClass == kTravelClass && !options.showTravel) continue;
    if (!level.bucketBounds[run.bucket].intersects(visible)) continue;
    const auto first = level.orders.begin() + static_cast<std::ptrdiff_t>(run.begin);
    const auto last = level.orders.begin() + static_cast<std::ptrdiff_t>(run.end);
    const std::size_t begin = options.orderBegin > 0
        ? static_cast<std::size_t>(std::lower_bound(first, last, options.orderBegin) -
                                   level.orders.begin())
        : run.begin;
    const std::size_t end = options.orderLimit >= 0
        ? static_cast<std::size_t>(std::lower_bound(first, last, options.orderLimit) -
                                   level.orders.begin())
        : run.end;
    if (end <= begin) continue;
    if (run.colourClass != currentClass) {
      currentClass = run.colourClass;
      QColor c = drawColour;
      if (currentClass == kTravelClass) c = paint::palette::travel();
      else if (currentClass == kProblemClass) c = options.showFlags ? paint::palette::problem() : drawColour;
      else if (options.colourBySpeed)
        c = speedColour((currentClass - 2 + 0.5) / kSpeedClasses);
      QPen pen(c, options.penWidthPx);
      pen.setCosmetic(true);
      painter.setPen(pen);
    }
    painter.drawLines(level.lines.data() + begin, static_cast<int>(end - begin));
  }
  painter.restore();
}

}  // namespace fivebar::widgets
