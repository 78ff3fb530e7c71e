// SPDX-License-Identifier: GPL-3.0-or-later
// A paint-ready, level-of-detail representation of many machine-frame paths (a planned job or a
// placed drawing) that pans and zooms a million segments within a frame budget:
//  - per level of detail, polylines are simplified (points within the level's tolerance of the
//    chord that replaces them are dropped), and the level whose tolerance is below half a pixel
//    is painted;
//  - segments are bucketed on a grid so only visible buckets are painted;
//  - within a level segments are grouped by colour class, each class painted with one
//    cosmetic pen in drawLines batches (no antialiasing, no wide pens).
// Built once (off the UI thread if large), immutable afterwards, painted many times.
#pragma once

#include <QColor>
#include <QLineF>
#include <QPainter>
#include <QRectF>
#include <QTransform>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "paint/view_transform.hpp"

namespace fivebar::widgets {

enum class PathKind : std::uint8_t { Draw, Travel };

struct ScenePath {
  std::vector<QPointF> pointsMm;       // machine frame, mm
  std::vector<float> speedsMmPerS;     // per segment (size points-1), or empty
  PathKind kind = PathKind::Draw;
  bool flagged = false;                // part of a pre-flight problem: painted red
  int firstOrder = 0;                  // drawing-order index of the first segment; one per segment
};

// Many paths in flat arrays: one allocation per array, not three per path, for the hundreds of
// thousands of short paths a planned job or a hatched drawing has.
struct ScenePathList {
  struct Info {
    std::size_t pointBegin = 0;  // index of the path's first point in pointsMm
    PathKind kind = PathKind::Draw;
    bool flagged = false;
    int firstOrder = 0;
  };
  std::vector<QPointF> pointsMm;    // every path's points, path after path (machine frame, mm)
  // Empty (no speeds), or one per point: the speed of the segment that starts at that point (a
  // path's last entry is unused; NaN for a path without speeds).
  std::vector<float> speedsMmPerS;
  std::vector<Info> paths;

  // Starts a path; its points follow with addPoint.
  void beginPath(PathKind kind, bool flagged, int firstOrder) {
    paths.push_back({pointsMm.size(), kind, flagged, firstOrder});
  }
  void addPoint(const QPointF& p) {
    pointsMm.push_back(p);
    if (!speedsMmPerS.empty()) speedsMmPerS.push_back(std::numeric_limits<float>::quiet_NaN());
  }
  // A point with the speed of the segment that starts at it (mm/s).
  void addPoint(const QPointF& p, float speedMmPerS) {
    speedsMmPerS.resize(pointsMm.size(), std::numeric_limits<float>::quiet_NaN());
    pointsMm.push_back(p);
    speedsMmPerS.push_back(speedMmPerS);
  }
  void add(const ScenePath& path);
  std::size_t pointEnd(std::size_t i) const {
    return i + 1 < paths.size() ? paths[i + 1].pointBegin : pointsMm.size();
  }
};

struct ScenePaintOptions {
  bool colourBySpeed = false;
  bool showTravel = true;
  int orderBegin = 0;         // paint only segments with orderBegin <= order
  int orderLimit = -1;        //   and order < orderLimit (-1 = no upper limit)
  QTransform machineFromScene;  // extra transform of the scene (identity: scene is machine mm)
  double opacity = 1.0;
  QColor drawColour;          // invalid = paint::palette::drawing()
  double penWidthPx = 1.0;    // cosmetic width
  bool showFlags = true;      // flagged (offending) paths in the problem colour
};

class PathScene {
 public:
  static constexpr int kSpeedClasses = 8;
  // Colour classes: travel, problem, then the speed ramp from slow to fast.
  static constexpr int kTravelClass = 0;
  static constexpr int kProblemClass = 1;
  static constexpr int kClassCount = 2 + kSpeedClasses;

  PathScene() = default;
  explicit PathScene(const std::vector<ScenePath>& paths);
  explicit PathScene(const ScenePathList& paths);

  bool empty() const { return segmentCount_ == 0; }
  std::size_t segmentCount() const { return segmentCount_; }  // level 0 segments
  int orderCount() const { return orderCount_; }              // one past the largest order
  QRectF boundsMm() const { return boundsMm_; }
  float maxSpeedMmPerS() const { return maxSpeed_; }
  int levelCount() const { return static_cast<int>(levels_.size()); }
  // Level painted at this zoom: the coarsest whose tolerance is below half a pixel.
  int levelFor(double pxPerMm) const;
  std::size_t segmentCount(int level) const;

  void paint(QPainter& painter, const paint::ViewTransform& view, const ScenePaintOptions& options) const;

  // Speed ramp colour for t in [0, 1] (slow to fast), shared with the legend.
  static QColor speedColour(double t);

  // A level's simplified paths, flat: path i has the points [begin[i], begin[i + 1]); per point
  // the order and colour class of the segment that starts there (a path's last entry unused).
  struct LevelPaths {
    std::vector<QPointF> points;
    std::vector<std::size_t> begin{0};
    std::vector<int> orders;
    std::vector<std::uint8_t> classes;
    std::size_t pathCount() const { return begin.size() - 1; }
    std::size_t segmentCount() const { return points.size() - pathCount(); }
  };

 private:
  struct Run {
    int colourClass = 0;
    int bucket = 0;
    std::size_t begin = 0;
    std::size_t end = 0;
  };
  struct Level {
    double toleranceMm = 0.0;
    std::vector<QLineF> lines;
    std::vector<int> orders;       // parallel to lines, ascending within each run
    std::vector<Run> runs;         // sorted by class, then bucket
    std::vector<QRectF> bucketBounds;
  };
  LevelPaths baseLevel(const ScenePathList& paths, const std::vector<std::size_t>& order) const;
  // Buckets a level's segments; View (path_scene.cpp) reads a LevelPaths or, for a scene where
  // no coarser level is useful, the ScenePathList itself (no copy of its points).
  template <typename View>
  void bucket(const View& paths, double toleranceMm, Level& level) const;

  std::vector<Level> levels_;
  std::size_t segmentCount_ = 0;
  int orderCount_ = 0;
  QRectF boundsMm_;
  float maxSpeed_ = 0.0f;
};

}  // namespace fivebar::widgets
