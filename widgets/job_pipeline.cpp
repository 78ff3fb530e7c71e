#include "widgets/job_pipeline.hpp"

#include <QCoreApplication>
#include <set>
#include <utility>

#include "core/planning/optimise.hpp"

namespace fivebar::widgets {
namespace {

QString trPipe(const char* text) { return QCoreApplication::translate("JobPipeline", text); }

QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }

std::shared_ptr<PathScene> drawingSceneOf(const std::vector<Stroke>& strokes,
                                          const std::vector<PreviewProblem>& problems) {
  std::set<std::pair<int, int>> flagged;
  for (const PreviewProblem& p : problems) flagged.insert({p.layerIndex, p.pathIndex});
  std::vector<ScenePath> paths;
  paths.reserve(strokes.size());
  int order = 0;
  for (const Stroke& s : strokes) {
    ScenePath path;
    path.pointsMm.reserve(s.points.size());
    for (const Vec2& p : s.points) path.pointsMm.push_back(toQ(p));
    path.flagged = flagged.count({s.layerIndex, s.pathIndex}) > 0;
    path.firstOrder = order;
    order += static_cast<int>(s.points.size());
    paths.push_back(std::move(path));
  }
  return std::make_shared<PathScene>(paths);
}

}  // namespace

std::shared_ptr<PathScene> jobSceneOf(const PlannedJob& job) {
  std::vector<ScenePath> paths;
  ScenePath current;
  Vec2 at = job.startXY;
  const auto flush = [&] {
    if (current.pointsMm.size() >= 2) paths.push_back(std::move(current));
    current = ScenePath();
  };
  for (std::size_t i = 0; i < job.moves.size(); ++i) {
    const JobMove& m = job.moves[i];
    if (!isMotion(m.kind)) {
      flush();
      continue;
    }
    const PathKind kind = m.kind == JobMoveKind::Draw ? PathKind::Draw : PathKind::Travel;
    if (current.pointsMm.empty() || current.kind != kind) {
      flush();
      current.kind = kind;
      current.firstOrder = static_cast<int>(i);
      current.pointsMm.push_back(toQ(at));
    }
    current.pointsMm.push_back(toQ(m.targetXY));
    current.speedsMmPerS.push_back(static_cast<float>(m.feedMmPerS));
    at = m.targetXY;
  }
  flush();
  return std::make_shared<PathScene>(paths);
}

PreviewResult runPipeline(const PipelineInput& input) {
  PreviewResult out;
  std::vector<Stroke> strokes = placeDrawing(input.drawing, input.placement);
  if (strokes.empty()) {
    out.status = PreviewStatus::Empty;
    out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Nothing to plan: the drawing has no visible path."));
    out.drawingScene = std::make_shared<PathScene>();
    return out;
  }
  const PreflightSummary pre =
      runPreflight(strokes, input.drawing, input.profile, input.modeSelection);
  out.mode = pre.mode;
  out.minMarginRad = pre.minMarginRad;
  out.problems = pre.problems;
  out.drawingScene = drawingSceneOf(strokes, pre.problems);
  if (!pre.mode || !pre.feasible) {
    out.status = PreviewStatus::Infeasible;
    out.message = pre.mode ? trPipe(QT_TRANSLATE_NOOP("JobPipeline", "The job is not feasible in this working mode."))
                           : trPipe(QT_TRANSLATE_NOOP("JobPipeline", "No working mode can draw the whole job."));
    return out;
  }
  OptimiseOptions optimiseOptions;
  optimiseOptions.start = input.profile.homeAngles;
  OptimiseResult optimised =
      optimise(std::move(strokes), input.profile, *pre.mode, optimiseOptions);
  PlanOptions options;
  options.mode = pre.mode;
  options.toleranceMm = input.toleranceMm;
  PlanResult plan = planStrokes(optimised.strokes, input.drawing.layers, input.profile,
                                *pre.mode, options);
  out.report = plan.report;
  if (!plan.ok()) {
    out.status = plan.status == PlanStatus::Infeasible ? PreviewStatus::Infeasible
                                                        : PreviewStatus::Failed;
    out.message = QString::fromStdString(plan.message);
    for (const PlanProblem& p : plan.report.problems) {
      out.problems.push_back({QString::fromStdString(p.path + ": " + p.why), toQ(p.whereMm)});
    }
    return out;
  }
  auto job = std::make_shared<PlannedJob>(std::move(plan.job));
  out.trajectory = std::make_shared<Trajectory>(*job, input.profile);
  out.jobScene = jobSceneOf(*job);
  out.job = std::move(job);
  out.status = PreviewStatus::Planned;
  return out;
}

}  // namespace fivebar::widgets
