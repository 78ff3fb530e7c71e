// SPDX-License-Identifier: GPL-3.0-or-later
// A QPaintDevice/QPaintEngine pair that records what QSvgRenderer paints as polylines instead of
// pixels: every path, polygon, line, rectangle, ellipse and text outline, mapped by the painter's
// current transform into the page frame (mm, y down) and flattened within the tolerance.
//
// Layer tracking: the sanitiser inserts, before each top-level element k, a sentinel
// <line> whose stroke width is kSentinelPenWidth and whose stroke colour is k + 1. Drawing it
// switches the engine's current top-level index; it is never recorded.
//
// Qt SVG paints a filled and stroked shape twice (a fill pass with no pen, then a stroke pass
// with the same geometry); the engine keeps the stroke pass only. A fill-only shape is recorded
// as its outline (colour = fill colour) when outlineFills is set.
#pragma once

#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainterPath>
#include <QTransform>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "clip.hpp"
#include "core/planning/drawing.hpp"

namespace fivebar::svg {

inline constexpr double kSentinelPenWidth = 0.0009765625;  // 2^-10: exact in text and binary

// Clip paths (svg_sanitize_clip.cpp writes them, clip.hpp cuts): sentinel <line>s of stroke width
// 2^-11 whose stroke colour is the command. Begin: what follows is recorded into a buffer of its
// own; ShapesUser/ShapesBox: the shapes drawn until Apply are the clip region (their geometry
// only, whatever their paint), in the current user space or in its objectBoundingBox units of
// the buffered lines; Apply: the buffer is cut by the region and handed to the enclosing level.
inline constexpr double kClipSentinelPenWidth = 0.00048828125;  // 2^-11
enum ClipCommand : std::uint32_t { kClipBegin = 1, kClipShapesUser = 2, kClipShapesBox = 3, kClipApply = 4 };

// Consecutive polylines painted by one top-level element in one colour.
struct CapturedRun {
  int topIndex = -1;        // index into the sanitiser's top-level list; -1 = before any
  std::uint32_t rgb = 0;    // 0xRRGGBB of the stroke (or of the fill for outlined fills)
  std::vector<Polyline> paths;  // page frame: mm, y down
};

struct CaptureSettings {
  double toleranceMm = 0.05;
  bool outlineFills = true;
  bool dashes = true;  // dashed strokes drawn as their dashes (dashes.hpp); false: solid
  std::function<void(long long shapesPainted)> onShape;  // progress hook, may be empty
  const std::atomic<bool>* cancel = nullptr;             // when raised, further shapes are ignored
  // Points recorded at most (0 = no limit): past it further shapes are ignored and
  // CaptureEngine::overBudget() is true.
  std::size_t maxPoints = 0;
};

class CaptureEngine final : public QPaintEngine {
 public:
  explicit CaptureEngine(CaptureSettings settings);

  bool begin(QPaintDevice*) override { return true; }
  bool end() override;
  void updateState(const QPaintEngineState&) override {}
  Type type() const override { return QPaintEngine::User; }

  using QPaintEngine::drawEllipse;
  using QPaintEngine::drawLines;
  using QPaintEngine::drawPolygon;
  using QPaintEngine::drawRects;
  void drawPath(const QPainterPath& path) override;
  void drawPolygon(const QPointF* points, int count, PolygonDrawMode mode) override;
  void drawLines(const QLineF* lines, int count) override;
  void drawRects(const QRectF* rects, int count) override;
  void drawEllipse(const QRectF& rect) override;
  void drawTextItem(const QPointF& p, const QTextItem& textItem) override;
  void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}

  std::vector<CapturedRun> takeRuns();
  // More than CaptureSettings::maxPoints points were painted: the runs are incomplete.
  bool overBudget() const { return overBudget_; }

 private:
  struct Paint {
    bool stroke = false;
    bool fill = false;
    std::uint32_t rgb = 0;  // stroke colour when stroke, else fill colour
  };
  // What one draw call painted; two calls with equal signatures paint the same geometry.
  struct Signature {
    int kind = 0;
    const void* data = nullptr;
    int count = 0;
    QRectF rect;
    QPainterPath path;
    QTransform transform;
    bool operator==(const Signature& other) const;
  };

  Paint currentPaint() const;
  // Decides what to keep for a draw call; returns false when nothing is to be recorded now.
  // rule: the fill rule of the area the call paints (None: lines, polylines).
  bool admit(const Signature& signature, const Paint& paint, std::vector<Polyline>&& lines,
             FillRule rule);
  void record(std::vector<Polyline>&& lines, std::uint32_t rgb);
  void store(CapturedRun&& run);  // into the innermost clip buffer, else the result
  void flushPending();
  void clipCommand(std::uint32_t command);
  // While collecting a clip region: takes the shape's rings (closed) and returns true.
  bool collectClip(std::vector<Polyline>&& rings, FillRule rule);
  double clipTolerance() const { return collectBox_ ? 1e-3 * settings_.toleranceMm : settings_.toleranceMm; }
  bool cancelled() const { return overBudget_ || (settings_.cancel && settings_.cancel->load()); }

  CaptureSettings settings_;
  std::vector<CapturedRun> runs_;
  int topIndex_ = -1;
  long long shapes_ = 0;
  std::size_t points_ = 0;  // recorded so far
  bool overBudget_ = false;
  bool hasPending_ = false;
  Signature pendingSignature_;
  std::vector<Polyline> pendingLines_;
  std::uint32_t pendingRgb_ = 0;
  FillRule pendingRule_ = FillRule::NonZero;
  std::vector<std::vector<CapturedRun>> clipBuffers_;  // one per open Begin
  bool collecting_ = false;  // between Shapes and Apply
  bool collectBox_ = false;  // objectBoundingBox units
  QTransform clipSpace_;     // page from the user space the clip was referenced in
  std::vector<ClipShape> clipShapes_;
};

// The paint device handed to QPainter; size in device units (= mm after the render mapping).
class CaptureDevice final : public QPaintDevice {
 public:
  CaptureDevice(double widthMm, double heightMm, CaptureSettings settings);
  ~CaptureDevice() override;
  QPaintEngine* paintEngine() const override { return engine_.get(); }
  CaptureEngine& engine() { return *engine_; }

 protected:
  int metric(PaintDeviceMetric metric) const override;

 private:
  int width_;
  int height_;
  std::unique_ptr<CaptureEngine> engine_;
};

// Drops consecutive duplicate points; marks the polyline closed when it ends where it started;
// appends it to `out` when at least two points remain (shared with the direct reader).
void finishPolyline(Polyline& line, bool closed, std::vector<Polyline>& out);

// Drops the subpaths a renderer does not show when stroked with butt caps and not filled: the
// zero-length ones, i.e. those that enclose nothing (every point on one straight line, within
// 1 % of extentMm) and whose every point lies within extentMm of their first point, such as
// "M x y a 0 0 0 1 0 0.001 0 Z" (a zero-radius arc is a 0.001 line, there and back). A tiny
// closed curve is kept: its stroke shows as a dot. Round and square caps paint a dot too: the
// caller keeps those.
void dropInvisibleStrokes(std::vector<Polyline>& lines, double extentMm);

// A filled area is closed whatever its path data says: marks every outline of more than two
// points closed (the closing edge of a fill-only open path is drawn).
void closeFillOutlines(std::vector<Polyline>& lines);

// Marks the outlines of one filled shape: rule on every ring, fillStart on the first.
void markFill(std::vector<Polyline>& lines, FillRule rule, bool fillOnly);

// Flattening helpers, exposed for tests. Points are mapped by `transform` before flattening.
// maxPoints > 0: at most that many points in all (the rest of the path is dropped); returns false
// when the path needed more.
bool appendFlattenedPath(const QPainterPath& path, const QTransform& transform,
                         double toleranceMm, std::vector<Polyline>& out, std::size_t maxPoints = 0);

}  // namespace fivebar::svg
