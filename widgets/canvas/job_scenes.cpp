// SPDX-License-Identifier: GPL-3.0-or-later
// Scenes of the planning results. Contract: job_scenes.hpp.
#include "widgets/canvas/job_scenes.hpp"

#include <set>

#include "core/support/memory_hint.hpp"

namespace fivebar::widgets {
namespace {

QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }

}  // namespace

std::shared_ptr<PathScene> drawingSceneOf(const std::vector<Stroke>& strokes,
                                          const std::vector<std::pair<int, int>>& flaggedPaths) {
  const std::set<std::pair<int, int>> flagged(flaggedPaths.begin(), flaggedPaths.end());
  ScenePathList paths;
  std::size_t points = 0;
  for (const Stroke& s : strokes) points += s.points.size();
  paths.pointsMm.reserve(points);
  paths.paths.reserve(strokes.size());
  int order = 0;
  for (const Stroke& s : strokes) {
    paths.beginPath(PathKind::Draw, !flagged.empty() && flagged.count({s.layerIndex, s.pathIndex}) > 0, order);
    for (const Vec2& p : s.points) paths.addPoint(toQ(p));
    order += static_cast<int>(s.points.size());
  }
  return std::make_shared<PathScene>(paths);
}


std::shared_ptr<PathScene> jobSceneOf(const PlannedJob& job) {
  // Allocated once for the most a job can need (a path per motion move, a point more per path):
  // counting first would read the moves (over 100 bytes each) twice, and reserved pages that are
  // never written cost nothing. With the huge-page hint (memory_hint.hpp).
  ScenePathList paths;
  reserveWithHugePages(paths.pointsMm, 2 * job.moves.size());
  reserveWithHugePages(paths.speedsMmPerS, 2 * job.moves.size());
  reserveWithHugePages(paths.paths, job.moves.size());
  Vec2 at = job.startXY;
  bool open = false;  // a path of `kind` is being built
  PathKind kind = PathKind::Draw;
  for (std::size_t i = 0; i < job.moves.size(); ++i) {
    const JobMove& m = job.moves[i];
    if (!isMotion(m.kind)) {
      open = false;
      continue;
    }
    const PathKind k = m.kind == JobMoveKind::Draw ? PathKind::Draw : PathKind::Travel;
    if (!open || k != kind) {
      paths.beginPath(k, false, static_cast<int>(i));
      paths.addPoint(toQ(at), 0.0f);
      open = true;
      kind = k;
    }
    // The segment that ends at the target starts at the previous point: its speed goes there.
    paths.speedsMmPerS.back() = static_cast<float>(m.feedMmPerS);
    paths.addPoint(toQ(m.targetXY), 0.0f);
    at = m.targetXY;
  }
  return std::make_shared<PathScene>(paths);
}

}  // namespace fivebar::widgets
