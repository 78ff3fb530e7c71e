#include "widgets/canvas/path_scene.hpp"

#include <QPen>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "widgets/canvas/studio_palette.hpp"

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
// ahead) such that every point between `from` and j lies within sqrt(tol2) of the chord.
std::size_t farthestWithin(const std::vector<QPointF>& pts, std::size_t from, double tol2) {
  const std::size_t last = std::min(pts.size() - 1, from + kMaxMergedPoints);
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
std::vector<PathScene::LevelPath> simplifyLevel(const std::vector<PathScene::LevelPath>& in,
                                                double toleranceMm) {
  const double tol2 = toleranceMm * toleranceMm;
  std::vector<PathScene::LevelPath> out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto& p = in[i];
    auto& q = out[i];
    const std::size_t n = p.points.size();
    std::size_t kept = 0;
    q.points.push_back(p.points[0]);
    while (kept + 1 < n) {
      const std::size_t next = farthestWithin(p.points, kept, tol2);
      q.points.push_back(p.points[next]);
      q.orders.push_back(p.orders[kept]);
      q.classes.push_back(p.classes[kept]);
      kept = next;
    }
  }
  return out;
}

struct Pending {
  QLineF line;
  int order;
  int key;
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

PathScene::PathScene(const std::vector<ScenePath>& paths) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const ScenePath& p : paths) {
    if (p.pointsMm.size() >= 2) {
      segmentCount_ += p.pointsMm.size() - 1;
      orderCount_ = std::max(orderCount_, p.firstOrder + static_cast<int>(p.pointsMm.size()) - 1);
    }
    for (const QPointF& q : p.pointsMm) {
      x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y());
      x1 = std::max(x1, q.x()), y1 = std::max(y1, q.y());
    }
    for (float s : p.speedsMmPerS) maxSpeed_ = std::max(maxSpeed_, s);
  }
  if (segmentCount_ == 0) return;
  boundsMm_ = QRectF(QPointF(x0, y0), QPointF(x1, y1));
  // A pyramid: each level simplifies the previous one's points with a 4x larger tolerance, so
  // every level merges at most kMaxMergedPoints of the previous level's points per segment.
  std::vector<LevelPath> current = baseLevel(paths);
  double tolerance = 0.0;
  for (int l = 0; l < kMaxLevels; ++l) {
    if (tolerance > 0.0) current = simplifyLevel(current, tolerance);
    Level level;
    bucket(current, tolerance, level);
    const bool useless = !levels_.empty() &&
        level.lines.size() > kUselessLevelShare * static_cast<double>(levels_.back().lines.size());
    if (useless && l > 1) break;
    levels_.push_back(std::move(level));
    tolerance = (tolerance == 0.0) ? kFirstToleranceMm : tolerance * kLevelFactor;
  }
}

std::vector<PathScene::LevelPath> PathScene::baseLevel(const std::vector<ScenePath>& paths) const {
  const double speedScale = maxSpeed_ > 0.0f ? 1.0 / maxSpeed_ : 0.0;
  const auto classOf = [&](const ScenePath& p, std::size_t segment) {
    if (p.kind == PathKind::Travel) return kTravelClass;
    if (p.flagged) return kProblemClass;
    if (p.speedsMmPerS.empty()) return 2 + kSpeedClasses - 1;
    const double t = p.speedsMmPerS[std::min(segment, p.speedsMmPerS.size() - 1)] * speedScale;
    return 2 + std::clamp(static_cast<int>(t * kSpeedClasses), 0, kSpeedClasses - 1);
  };
  // Paths in drawing order, so that a stable bucket sort keeps orders ascending.
  std::vector<const ScenePath*> sorted;
  sorted.reserve(paths.size());
  for (const ScenePath& p : paths) {
    if (p.pointsMm.size() >= 2) sorted.push_back(&p);
  }
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](auto* a, auto* b) { return a->firstOrder < b->firstOrder; });
  std::vector<LevelPath> out(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const ScenePath& p = *sorted[i];
    LevelPath& lp = out[i];
    lp.points = p.pointsMm;
    const std::size_t segments = p.pointsMm.size() - 1;
    lp.orders.resize(segments);
    lp.classes.resize(segments);
    for (std::size_t k = 0; k < segments; ++k) {
      lp.orders[k] = p.firstOrder + static_cast<int>(k);
      lp.classes[k] = static_cast<std::uint8_t>(classOf(p, k));
    }
  }
  return out;
}

void PathScene::bucket(const std::vector<LevelPath>& paths, double toleranceMm,
                       Level& level) const {
  level.toleranceMm = toleranceMm;
  const double cellW = std::max(boundsMm_.width() / kGrid, 1e-9);
  const double cellH = std::max(boundsMm_.height() / kGrid, 1e-9);
  const auto bucketOf = [&](const QPointF& m) {
    const int bx = std::clamp(static_cast<int>((m.x() - boundsMm_.left()) / cellW), 0, kGrid - 1);
    const int by = std::clamp(static_cast<int>((m.y() - boundsMm_.top()) / cellH), 0, kGrid - 1);
    return by * kGrid + bx;
  };
  std::size_t total = 0;
  for (const LevelPath& p : paths) total += p.orders.size();
  std::vector<Pending> pending;
  pending.reserve(total);
  for (const LevelPath& p : paths) {
    for (std::size_t k = 0; k < p.orders.size(); ++k) {
      const QLineF line(p.points[k], p.points[k + 1]);
      pending.push_back({line, p.orders[k], p.classes[k] * kGrid * kGrid + bucketOf(line.center())});
    }
  }
  // Stable counting sort by key (class, bucket).
  constexpr int kKeys = kClassCount * kGrid * kGrid;
  std::vector<std::size_t> start(kKeys + 1, 0);
  for (const Pending& s : pending) ++start[s.key + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  level.lines.resize(pending.size());
  level.orders.resize(pending.size());
  level.bucketBounds.assign(kGrid * kGrid, QRectF());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const Pending& s : pending) {
    const std::size_t at = next[s.key]++;
    level.lines[at] = s.line;
    level.orders[at] = s.order;
    QRectF& b = level.bucketBounds[s.key % (kGrid * kGrid)];
    const QRectF r = QRectF(s.line.p1(), s.line.p2()).normalized();
    b = b.isNull() ? r.adjusted(-1e-6, -1e-6, 1e-6, 1e-6) : b.united(r);
  }
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

void PathScene::paint(QPainter& painter, const ViewTransform& view,
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
  const QColor drawColour = options.drawColour.isValid() ? options.drawColour : palette::drawing();
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
      if (currentClass == kTravelClass) c = palette::travel();
      else if (currentClass == kProblemClass) c = options.showFlags ? palette::problem() : drawColour;
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
