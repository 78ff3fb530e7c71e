#include "widgets/document/job_pipeline.hpp"

#include <QCoreApplication>
#include <QLocale>
#include <set>
#include <utility>

#include "core/kinematics/units.hpp"
#include "core/support/memory_hint.hpp"
#include "widgets/document/core_message.hpp"

namespace fivebar::widgets {
namespace {

// Problems listed in the studio (the CLI lists 20).
constexpr int kListedProblems = 200;

QString trPipe(const char* text) { return QCoreApplication::translate("JobPipeline", text); }

QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }

std::shared_ptr<PathScene> drawingSceneOf(const std::vector<Stroke>& strokes,
                                          const std::vector<PreviewProblem>& problems) {
  std::set<std::pair<int, int>> flagged;
  for (const PreviewProblem& p : problems) flagged.insert({p.layerIndex, p.pathIndex});
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

}  // namespace

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

QString longJobQuestion(const PlannedJob& job) {
  const JobSummary& s = job.summary;
  if (s.estimatedTimeS <= kLongJobS && s.segments <= kLongJobSegments) return {};
  return trPipe(QT_TRANSLATE_NOOP("JobPipeline",
                                  "This job is long: about %1 hours and %2 pen-down moves. The "
                                  "machine will be busy all that time. Start it anyway?"))
      .arg(QLocale().toString(s.estimatedTimeS / 3600.0, 'f', 1))
      .arg(s.segments);
}

PlanOptions studioPlanOptions(const Placement& placement, ModeSelection mode, double toleranceMm) {
  PlanOptions options;
  options.mode = mode;
  options.toleranceMm = toleranceMm;
  setFixedPlacement(options, placement);
  return options;
}

namespace {

bool hasVisiblePath(const Drawing& drawing) {
  for (const Layer& layer : drawing.layers)
    if (layer.visible)
      for (const Polyline& path : layer.paths)
        if (!path.points.empty()) return true;
  return false;
}

bool cancelled(const PipelineInput& input) { return input.cancel && input.cancel->load(); }

PreviewResult cancelledResult(PreviewResult out) {
  out.status = PreviewStatus::Cancelled;
  out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Planning cancelled."));
  return out;
}

}  // namespace

PreviewResult runPipeline(const PipelineInput& input) {
  PreviewResult out;
  if (!input.drawing || !hasVisiblePath(*input.drawing)) {
    out.status = PreviewStatus::Empty;
    out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Nothing to plan: the drawing has no visible path."));
    out.drawingScene = std::make_shared<PathScene>();
    return out;
  }
  PlanOptions options = studioPlanOptions(input.placement, input.modeSelection, input.toleranceMm);
  options.maxListedProblems = kListedProblems;
  options.cancel = input.cancel.get();
  std::string importError;
  std::optional<Drawing> refined;
  PlanResult plan = planRefining(*input.drawing, input.source, input.profile, options, refined, importError);
  if (refined) out.refinedDrawing = std::make_shared<const Drawing>(std::move(*refined));
  out.report = plan.report;
  out.mode = plan.report.mode;
  out.minMarginRad = radFromDeg(plan.report.minSingularityMarginDeg);
  for (const PlanProblem& p : plan.report.problems) {
    PreviewProblem q;
    q.text = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "%1: %2")).arg(translated(p.path), translated(p.why));
    q.fixes = translated(p.fixes);
    q.whereMm = toQ(p.whereMm);
    q.layerIndex = p.layerIndex;
    q.pathIndex = p.pathIndex;
    out.problems.push_back(std::move(q));
  }
  out.timings = plan.timings;
  if (plan.status == PlanStatus::Cancelled || cancelled(input)) return cancelledResult(std::move(out));
  StageClock clock(out.timings);
  // A planned job needs no drawing scene: its own scene (draw moves, travels hidden) shows the
  // drawing while the next plan runs (job_layer.cpp). Placing the drawing again and bucketing its
  // paths (0.7 s for 400k paths) is left to plans without a job, whose offending paths are shown.
  // The trajectory shares the job and times it chain by chain as it is sampled: nothing to build.
  std::shared_ptr<const PlannedJob> job;
  if (plan.status == PlanStatus::Ok) {
    job = std::make_shared<const PlannedJob>(std::move(plan.job));
    out.trajectory = std::make_shared<Trajectory>(job, input.profile);
    out.jobScene = jobSceneOf(*job);
    clock.lap("job scene");
  } else {
    out.drawingScene = drawingSceneOf(
        placeDrawing(out.refinedDrawing ? *out.refinedDrawing : *input.drawing, input.placement), out.problems);
    clock.lap("drawing scene");
  }
  switch (plan.status) {
    case PlanStatus::Ok: break;
    case PlanStatus::Infeasible:
      out.status = PreviewStatus::Infeasible;
      out.message = translated(plan.message);
      return out;
    case PlanStatus::EmptyDrawing:
      out.status = PreviewStatus::Empty;
      out.message = translated(plan.message);
      return out;
    default:
      out.status = PreviewStatus::Failed;
      out.message = importError.empty() ? translated(plan.message) : QString::fromStdString(importError);
      return out;
  }
  out.job = std::move(job);
  if (cancelled(input)) return cancelledResult(std::move(out));
  out.status = PreviewStatus::Planned;
  out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Planned in working mode %1.")).arg(QString::fromUtf8(toString(*out.mode).data(), static_cast<int>(toString(*out.mode).size())));
  return out;
}

}  // namespace fivebar::widgets
