// SPDX-License-Identifier: GPL-3.0-or-later
#include "capture_engine.hpp"

#include <QGradient>
#include <QPainter>

#include <algorithm>
#include <cmath>

#include "dashes.hpp"
#include "flatten.hpp"

namespace fivebar::svg {
namespace {

enum Kind { kPath = 1, kPolygon, kPolyline, kRects, kEllipse };

Vec2 mapped(const QTransform& t, double x, double y) {
  const QPointF p = t.map(QPointF(x, y));
  return {p.x(), p.y()};
}

std::uint32_t rgbOf(const QBrush& brush) {
  QColor colour = brush.color();
  if (const QGradient* g = brush.gradient(); g && !g->stops().isEmpty())
    colour = g->stops().front().second;
  return static_cast<std::uint32_t>(colour.rgb() & 0xFFFFFFu);
}

bool visible(const QBrush& brush) {
  if (brush.style() == Qt::NoBrush) return false;
  if (brush.gradient()) return true;
  return brush.color().alpha() > 0;
}

}  // namespace

void finishPolyline(Polyline& line, bool closed, std::vector<Polyline>& out) {
  auto& pts = line.points;
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() > 2 && pts.front() == pts.back()) {
    pts.pop_back();
    closed = true;
  }
  if (pts.size() < 2) return;
  line.closed = closed && pts.size() > 2;
  out.push_back(std::move(line));
}

void dropInvisibleStrokes(std::vector<Polyline>& lines, double extentMm) {
  const double limit2 = extentMm * extentMm;
  std::erase_if(lines, [&](const Polyline& line) {
    const Vec2& first = line.points.front();
    const Vec2* far = &first;
    for (const Vec2& p : line.points) {
      if ((p - first).squaredNorm() > limit2) return false;
      if ((p - first).squaredNorm() > (*far - first).squaredNorm()) far = &p;
    }
    const Vec2 axis = *far - first;
    const double length = axis.norm();
    if (length == 0.0) return true;
    return std::all_of(line.points.begin(), line.points.end(), [&](const Vec2& p) {
      const Vec2 d = p - first;
      return std::abs(axis.x() * d.y() - axis.y() * d.x()) / length <= 0.01 * extentMm;
    });
  });
}

void closeFillOutlines(std::vector<Polyline>& lines) {
  for (Polyline& line : lines) line.closed = line.closed || line.points.size() > 2;
}

void markFill(std::vector<Polyline>& lines, FillRule rule, bool fillOnly) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    lines[i].fill = rule;
    lines[i].fillStart = lines[i].fillStart || i == 0;
    lines[i].fillOnly = fillOnly;
  }
}

bool appendFlattenedPath(const QPainterPath& path, const QTransform& transform,
                         double toleranceMm, std::vector<Polyline>& out, std::size_t maxPoints) {
  // Points gather in a reused scratch buffer; each polyline then gets one exact allocation.
  thread_local std::vector<Vec2> scratch;
  scratch.clear();
  bool curved = false;  // the subpath so far holds a curve: its points are flattened
  std::size_t finished = 0;  // points of the polylines already made
  const auto room = [&]() -> std::size_t {  // points the budget leaves for the current subpath
    if (maxPoints == 0) return 0;
    const std::size_t used = finished + scratch.size();
    return used < maxPoints ? maxPoints - used : std::size_t{1};
  };
  auto finish = [&] {
    finished += scratch.size();
    Polyline line;
    line.points.assign(scratch.begin(), scratch.end());
    line.flattened = curved;
    finishPolyline(line, false, out);
    scratch.clear();
    curved = false;
  };
  const int n = path.elementCount();
  for (int i = 0; i < n; ++i) {
    const QPainterPath::Element& e = path.elementAt(i);
    if (e.type == QPainterPath::MoveToElement) {
      finish();
      scratch.push_back(mapped(transform, e.x, e.y));
    } else if (e.type == QPainterPath::LineToElement) {
      scratch.push_back(mapped(transform, e.x, e.y));
    } else if (e.type == QPainterPath::CurveToElement && i + 2 < n) {
      if (scratch.empty()) scratch.push_back(mapped(transform, 0, 0));
      const QPainterPath::Element& c2 = path.elementAt(i + 1);
      const QPainterPath::Element& p3 = path.elementAt(i + 2);
      const Vec2 start = scratch.back();
      const Vec2 a = mapped(transform, e.x, e.y), b = mapped(transform, c2.x, c2.y);
      const Vec2 end = mapped(transform, p3.x, p3.y);
      // A piece of an arc (path_data.hpp) is flattened within what its own error leaves of the
      // tolerance, so that the polyline stays within the tolerance of the true arc. The floor
      // (half the tolerance) is out of reach in practice: the error is <= 1.1e-9 x radius.
      const double arcErrorMm = arcPieceErrorBound(start, a, b, end);
      curved = true;
      if (!flattenCubic(start, a, b, end, std::max(0.5 * toleranceMm, toleranceMm - arcErrorMm), scratch,
                        room())) {
        finish();
        return false;
      }
      i += 2;
    }
    if (maxPoints > 0 && finished + scratch.size() > maxPoints) {
      finish();
      return false;
    }
  }
  finish();
  return true;
}

bool CaptureEngine::Signature::operator==(const Signature& other) const {
  if (kind != other.kind || transform != other.transform) return false;
  switch (kind) {
    case kPath: return path == other.path;
    case kEllipse: return rect == other.rect;
    default: return data == other.data && count == other.count;
  }
}

CaptureEngine::CaptureEngine(CaptureSettings settings)
    : QPaintEngine(QPaintEngine::AllFeatures), settings_(std::move(settings)) {}

bool CaptureEngine::end() {
  flushPending();
  return true;
}

CaptureEngine::Paint CaptureEngine::currentPaint() const {
  const QPainter* p = painter();
  Paint paint;
  if (p->opacity() <= 0.0) return paint;
  const QPen& pen = p->pen();
  paint.stroke = pen.style() != Qt::NoPen && visible(pen.brush());
  paint.fill = visible(p->brush());
  if (paint.stroke) paint.rgb = rgbOf(pen.brush());
  else if (paint.fill) paint.rgb = rgbOf(p->brush());
  return paint;
}

void CaptureEngine::record(std::vector<Polyline>&& lines, std::uint32_t rgb) {
  if (lines.empty()) return;
  for (const Polyline& line : lines) points_ += line.points.size();
  store(CapturedRun{topIndex_, rgb, std::move(lines)});
  if (settings_.maxPoints > 0 && points_ > settings_.maxPoints) overBudget_ = true;
}

void CaptureEngine::flushPending() {
  if (!hasPending_) return;
  hasPending_ = false;
  if (settings_.outlineFills) {
    closeFillOutlines(pendingLines_);
    markFill(pendingLines_, pendingRule_, true);
    record(std::move(pendingLines_), pendingRgb_);
  }
  pendingLines_.clear();
  pendingSignature_ = Signature{};
}

bool CaptureEngine::admit(const Signature& signature, const Paint& paint,
                          std::vector<Polyline>&& lines, FillRule rule) {
  ++shapes_;
  if (settings_.onShape && (shapes_ & 255) == 0) settings_.onShape(shapes_);
  if (paint.stroke) {
    // The stroke pass of a filled shape replaces its fill pass.
    bool filled = paint.fill && rule != FillRule::None;
    if (hasPending_ && pendingSignature_ == signature) {
      hasPending_ = false;
      pendingLines_.clear();
      filled = true;
      rule = pendingRule_;
    }
    if (const std::optional<DashPattern> dash =
            settings_.dashes ? dashPatternOf(painter()->pen()) : std::nullopt) {
      lines = applyDashes(lines, *dash, signature.transform);
      filled = false;  // dashes are no rings: a dashed filled shape is not hatched
    }
    if (filled) markFill(lines, rule, false);
    flushPending();
    record(std::move(lines), paint.rgb);
    return true;
  }
  flushPending();
  if (!paint.fill) return false;
  hasPending_ = true;
  pendingSignature_ = signature;
  pendingLines_ = std::move(lines);
  pendingRgb_ = paint.rgb;
  pendingRule_ = rule == FillRule::None ? FillRule::NonZero : rule;
  return true;
}

void CaptureEngine::drawPath(const QPainterPath& path) {
  if (collecting_) {
    std::vector<Polyline> rings;
    // A clip path within the points budget too (its points are not drawn, but a hostile curve
    // must not flatten into gigabytes before the budget is looked at).
    if (!appendFlattenedPath(path, painter()->combinedTransform(), clipTolerance(), rings,
                             settings_.maxPoints == 0 ? 0 : settings_.maxPoints + 1))
      overBudget_ = true;
    collectClip(std::move(rings), path.fillRule() == Qt::WindingFill ? FillRule::NonZero : FillRule::EvenOdd);
    return;
  }
  const Paint paint = currentPaint();
  if (cancelled() || (!paint.stroke && !paint.fill)) return flushPending();
  const QTransform t = painter()->combinedTransform();
  std::vector<Polyline> lines;
  // At most one point past the budget: record() then sees the budget passed and stops the import.
  const std::size_t room = settings_.maxPoints == 0 ? 0
                           : points_ < settings_.maxPoints ? settings_.maxPoints - points_ + 1
                                                           : std::size_t{1};
  if (!appendFlattenedPath(path, t, settings_.toleranceMm, lines, room)) overBudget_ = true;
  if (paint.stroke && !paint.fill && painter()->pen().capStyle() == Qt::FlatCap)
    dropInvisibleStrokes(lines, settings_.toleranceMm);
  Signature s;
  s.kind = kPath;
  s.path = path;
  s.transform = t;
  admit(s, paint, std::move(lines),
        path.fillRule() == Qt::WindingFill ? FillRule::NonZero : FillRule::EvenOdd);
}

void CaptureEngine::drawPolygon(const QPointF* points, int count, PolygonDrawMode mode) {
  if (collecting_) {
    const QTransform t = painter()->combinedTransform();
    Polyline ring;
    for (int i = 0; i < count; ++i) ring.points.push_back(mapped(t, points[i].x(), points[i].y()));
    std::vector<Polyline> rings{std::move(ring)};
    collectClip(std::move(rings), mode == OddEvenMode ? FillRule::EvenOdd : FillRule::NonZero);
    return;
  }
  Paint paint = currentPaint();
  // QPainter::drawPolyline strokes only: its brush paints nothing.
  if (mode == PolylineMode) paint.fill = false;
  if (cancelled() || (!paint.stroke && !paint.fill) || count < 2) return flushPending();
  const QTransform t = painter()->combinedTransform();
  Polyline line;
  line.points.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) line.points.push_back(mapped(t, points[i].x(), points[i].y()));
  std::vector<Polyline> lines;
  finishPolyline(line, mode != PolylineMode, lines);
  if (paint.stroke && !paint.fill && painter()->pen().capStyle() == Qt::FlatCap)
    dropInvisibleStrokes(lines, settings_.toleranceMm);
  Signature s;
  s.kind = mode == PolylineMode ? kPolyline : kPolygon;
  s.data = points;
  s.count = count;
  s.transform = t;
  admit(s, paint, std::move(lines),
        mode == PolylineMode ? FillRule::None
        : mode == OddEvenMode ? FillRule::EvenOdd
                              : FillRule::NonZero);
}

void CaptureEngine::drawLines(const QLineF* lines, int count) {
  const QPainter* p = painter();
  const QPen& pen = p->pen();
  if (count == 1 && pen.widthF() == kClipSentinelPenWidth) return clipCommand(rgbOf(pen.brush()));
  if (collecting_) return;  // lines enclose no area
  if (count == 1 && pen.widthF() == kSentinelPenWidth) {
    flushPending();
    topIndex_ = static_cast<int>(rgbOf(pen.brush())) - 1;  // sentinel colour = index + 1
    return;
  }
  const Paint paint = currentPaint();
  if (cancelled() || !paint.stroke) return flushPending();
  const QTransform t = p->combinedTransform();
  std::vector<Polyline> out;
  for (int i = 0; i < count; ++i) {
    Polyline line;
    line.points = {mapped(t, lines[i].x1(), lines[i].y1()), mapped(t, lines[i].x2(), lines[i].y2())};
    finishPolyline(line, false, out);
  }
  if (pen.capStyle() == Qt::FlatCap) dropInvisibleStrokes(out, settings_.toleranceMm);
  Signature s;
  s.kind = kPolyline;
  s.data = lines;
  s.count = count;
  s.transform = t;
  admit(s, paint, std::move(out), FillRule::None);
}

void CaptureEngine::drawRects(const QRectF* rects, int count) {
  if (collecting_) {
    const QTransform t = painter()->combinedTransform();
    for (int i = 0; i < count; ++i) {
      const QRectF& r = rects[i];
      Polyline ring;
      ring.points = {mapped(t, r.left(), r.top()), mapped(t, r.right(), r.top()),
                     mapped(t, r.right(), r.bottom()), mapped(t, r.left(), r.bottom())};
      std::vector<Polyline> rings{std::move(ring)};
      collectClip(std::move(rings), FillRule::NonZero);
    }
    return;
  }
  const Paint paint = currentPaint();
  if (cancelled() || (!paint.stroke && !paint.fill)) return flushPending();
  const QTransform t = painter()->combinedTransform();
  std::vector<Polyline> out;
  for (int i = 0; i < count; ++i) {
    const QRectF& r = rects[i];
    Polyline line;
    line.points = {mapped(t, r.left(), r.top()), mapped(t, r.right(), r.top()),
                   mapped(t, r.right(), r.bottom()), mapped(t, r.left(), r.bottom())};
    finishPolyline(line, true, out);
  }
  Signature s;
  s.kind = kRects;
  s.data = rects;
  s.count = count;
  s.transform = t;
  // Each rectangle is a shape of its own.
  for (Polyline& line : out) line.fillStart = true;
  admit(s, paint, std::move(out), FillRule::NonZero);
}

void CaptureEngine::drawEllipse(const QRectF& rect) {
  if (collecting_) {
    const QTransform t = painter()->combinedTransform();
    const QPointF c = rect.center();
    const Vec2 centre = mapped(t, c.x(), c.y());
    Polyline ring;
    flattenEllipse(centre, mapped(t, c.x() + 0.5 * rect.width(), c.y()) - centre,
                   mapped(t, c.x(), c.y() + 0.5 * rect.height()) - centre, clipTolerance(), ring.points);
    std::vector<Polyline> rings{std::move(ring)};
    collectClip(std::move(rings), FillRule::NonZero);
    return;
  }
  const Paint paint = currentPaint();
  if (cancelled() || (!paint.stroke && !paint.fill)) return flushPending();
  const QTransform t = painter()->combinedTransform();
  const QPointF c = rect.center();
  const Vec2 centre = mapped(t, c.x(), c.y());
  const Vec2 u = mapped(t, c.x() + 0.5 * rect.width(), c.y()) - centre;
  const Vec2 v = mapped(t, c.x(), c.y() + 0.5 * rect.height()) - centre;
  Polyline line;
  flattenEllipse(centre, u, v, settings_.toleranceMm, line.points);
  line.flattened = true;
  std::vector<Polyline> out;
  finishPolyline(line, true, out);
  Signature s;
  s.kind = kEllipse;
  s.rect = rect;
  s.transform = t;
  admit(s, paint, std::move(out), FillRule::NonZero);
}

void CaptureEngine::drawTextItem(const QPointF& p, const QTextItem& textItem) {
  // The base class turns the glyphs into outlines and fills them through drawPath.
  QPaintEngine::drawTextItem(p, textItem);
}

std::vector<CapturedRun> CaptureEngine::takeRuns() {
  flushPending();
  collecting_ = false;
  while (!clipBuffers_.empty()) {  // a Begin without Apply (cannot happen): unclipped
    std::vector<CapturedRun> runs = std::move(clipBuffers_.back());
    clipBuffers_.pop_back();
    for (CapturedRun& run : runs) store(std::move(run));
  }
  return std::move(runs_);
}

CaptureDevice::CaptureDevice(double widthMm, double heightMm, CaptureSettings settings)
    : width_(std::clamp(static_cast<int>(std::ceil(widthMm)), 1, 1 << 20)),
      height_(std::clamp(static_cast<int>(std::ceil(heightMm)), 1, 1 << 20)),
      engine_(std::make_unique<CaptureEngine>(std::move(settings))) {}

CaptureDevice::~CaptureDevice() = default;

int CaptureDevice::metric(PaintDeviceMetric metric) const {
  switch (metric) {
    case PdmWidth: return width_;
    case PdmHeight: return height_;
    case PdmWidthMM: return width_;
    case PdmHeightMM: return height_;
    case PdmNumColors: return 0x7FFFFFFF;
    case PdmDepth: return 32;
    case PdmDpiX:
    case PdmDpiY:
    case PdmPhysicalDpiX:
    case PdmPhysicalDpiY: return 96;
    case PdmDevicePixelRatio: return 1;
    case PdmDevicePixelRatioScaled: return static_cast<int>(devicePixelRatioFScale());
    default: return 0;
  }
}

}  // namespace fivebar::svg
