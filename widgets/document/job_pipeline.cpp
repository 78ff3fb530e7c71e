#include "widgets/document/job_pipeline.hpp"

#include <QCoreApplication>
#include <QLocale>
#include <set>
#include <utility>

#include "core/kinematics/units.hpp"
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

PreviewResult runPipeline(const PipelineInput& input) {
  PreviewResult out;
  Drawing drawing = input.drawing;
  std::vector<Stroke> strokes = placeDrawing(drawing, input.placement);
  if (strokes.empty()) {
    out.status = PreviewStatus::Empty;
    out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Nothing to plan: the drawing has no visible path."));
    out.drawingScene = std::make_shared<PathScene>();
    return out;
  }
  PlanOptions options = studioPlanOptions(input.placement, input.modeSelection, input.toleranceMm);
  options.maxListedProblems = kListedProblems;
  options.cancel = input.cancel.get();
  std::string importError;
  PlanResult plan = planRefining(drawing, input.source, input.profile, options, importError);
  if (drawing.flatteningToleranceMm != input.drawing.flatteningToleranceMm) {
    out.refinedDrawing = std::make_shared<const Drawing>(drawing);
    strokes = placeDrawing(drawing, input.placement);
  }
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
  out.drawingScene = drawingSceneOf(strokes, out.problems);
  switch (plan.status) {
    case PlanStatus::Ok: break;
    case PlanStatus::Cancelled:
      out.status = PreviewStatus::Cancelled;
      out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Planning cancelled."));
      return out;
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
  auto job = std::make_shared<PlannedJob>(std::move(plan.job));
  out.trajectory = std::make_shared<Trajectory>(*job, input.profile);
  out.jobScene = jobSceneOf(*job);
  out.job = std::move(job);
  out.status = PreviewStatus::Planned;
  out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Planned in working mode %1.")).arg(QString::fromUtf8(toString(*out.mode).data(), static_cast<int>(toString(*out.mode).size())));
  return out;
}

}  // namespace fivebar::widgets
