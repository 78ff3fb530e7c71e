#include "widgets/path_scene.hpp"

#include <QPen>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "widgets/studio_palette.hpp"

namespace fivebar::widgets {
namespace {

constexpr int kGrid = 32;                // buckets per side
constexpr int kMaxLevels = 8;
constexpr double kFirstToleranceMm = 0.02;
constexpr double kLevelFactor = 4.0;
constexpr double kHalfPixel = 0.5;
// Stop adding levels once a level keeps more than this share of the previous one's segments.
constexpr double kUselessLevelShare = 0.9;

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
  // Paths are processed in drawing order so that a stable bucket sort keeps orders ascending.
  std::vector<ScenePath const*> sorted;
  sorted.reserve(paths.size());
  for (const ScenePath& p : paths) sorted.push_back(&p);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](auto* a, auto* b) { return a->firstOrder < b->firstOrder; });
  std::vector<ScenePath> ordered;  // cheap relative to the level data; keeps buildLevel simple
  ordered.reserve(sorted.size());
  for (auto* p : sorted) ordered.push_back(*p);

  double tolerance = 0.0;
  for (int l = 0; l < kMaxLevels; ++l) {
    Level level;
    buildLevel(ordered, tolerance, level);
    const bool useless = !levels_.empty() &&
        level.lines.size() > kUselessLevelShare * static_cast<double>(levels_.back().lines.size());
    if (useless && l > 1) break;
    levels_.push_back(std::move(level));
    tolerance = (tolerance == 0.0) ? kFirstToleranceMm : tolerance * kLevelFactor;
  }
}

void PathScene::buildLevel(const std::vector<ScenePath>& paths, double toleranceMm,
                           Level& level) const {
  level.toleranceMm = toleranceMm;
  const double cellW = std::max(boundsMm_.width() / kGrid, 1e-9);
  const double cellH = std::max(boundsMm_.height() / kGrid, 1e-9);
  const auto bucketOf = [&](const QPointF& m) {
    const int bx = std::clamp(static_cast<int>((m.x() - boundsMm_.left()) / cellW), 0, kGrid - 1);
    const int by = std::clamp(static_cast<int>((m.y() - boundsMm_.top()) / cellH), 0, kGrid - 1);
    return by * kGrid + bx;
  };
  const double speedScale = maxSpeed_ > 0.0f ? 1.0 / maxSpeed_ : 0.0;
  const auto classOf = [&](const ScenePath& p, std::size_t segment) {
    if (p.kind == PathKind::Travel) return kTravelClass;
    if (p.flagged) return kProblemClass;
    if (p.speedsMmPerS.empty()) return 2 + kSpeedClasses - 1;
    const double t = p.speedsMmPerS[std::min(segment, p.speedsMmPerS.size() - 1)] * speedScale;
    return 2 + std::clamp(static_cast<int>(t * kSpeedClasses), 0, kSpeedClasses - 1);
  };
  std::vector<Pending> pending;
  pending.reserve(toleranceMm == 0.0 ? segmentCount_ : segmentCount_ / 4 + 16);
  const double tol2 = toleranceMm * toleranceMm;
  for (const ScenePath& p : paths) {
    const std::size_t n = p.pointsMm.size();
    if (n < 2) continue;
    std::size_t kept = 0;
    for (std::size_t i = 1; i < n; ++i) {
      const QPointF d = p.pointsMm[i] - p.pointsMm[kept];
      if (i + 1 < n && d.x() * d.x() + d.y() * d.y() < tol2) continue;
      const QLineF line(p.pointsMm[kept], p.pointsMm[i]);
      const int key = classOf(p, kept) * kGrid * kGrid + bucketOf(line.center());
      pending.push_back({line, p.firstOrder + static_cast<int>(kept), key});
      kept = i;
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
      else if (currentClass == kProblemClass) c = palette::problem();
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
