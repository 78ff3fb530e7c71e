// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/job_pipeline.hpp"

#include <QCoreApplication>
#include <QLocale>
#include <utility>

#include "core/kinematics/units.hpp"
#include "i18n/translated.hpp"
#include "widgets/document/plan_words.hpp"

namespace fivebar::widgets {
namespace {

// Problems listed in the studio (the CLI lists 20).
constexpr int kListedProblems = 200;

QString trPipe(const char* text) { return QCoreApplication::translate("JobPipeline", text); }

QPointF toQ(const Vec2& v) { return {v.x(), v.y()}; }

}  // namespace

QString longJobQuestion(const PlannedJob& job) {
  const JobSummary& s = job.summary;
  if (s.estimatedTimeS <= kLongJobS && s.segments <= kLongJobSegments) return {};
  return trPipe(QT_TRANSLATE_NOOP("JobPipeline",
                                  "This job is long: about %1 hours and %2 pen-down moves. The "
                                  "machine will be busy all that time. Start it anyway?"))
      .arg(QLocale().toString(s.estimatedTimeS / 3600.0, 'f', 1))
      .arg(QLocale().toString(qlonglong(s.segments)));
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
  job::JobError importError;
  std::optional<Drawing> refined;
  PlanResult plan = job::planRefining(*input.drawing, input.source, input.profile, options, refined, importError);
  if (refined) out.refinedDrawing = std::make_shared<const Drawing>(std::move(*refined));
  out.report = plan.report;
  out.mode = plan.report.mode;
  out.minMarginRad = radFromDeg(plan.report.minSingularityMarginDeg);
  for (const PlanProblem& p : plan.report.problems) {
    PreviewProblem q;
    q.text = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "%1: %2")).arg(translated(p.path), translated(p.why));
    q.fixes = fixWords(p.fixes);
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
    std::vector<std::pair<int, int>> flagged;
    for (const PreviewProblem& p : out.problems) flagged.emplace_back(p.layerIndex, p.pathIndex);
    out.drawingScene = drawingSceneOf(
        placeDrawing(out.refinedDrawing ? *out.refinedDrawing : *input.drawing, input.placement), flagged);
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
      out.message = importError.empty() ? translated(plan.message) : QString::fromStdString(importError.text);
      return out;
  }
  out.job = std::move(job);
  if (cancelled(input)) return cancelledResult(std::move(out));
  out.status = PreviewStatus::Planned;
  out.message = trPipe(QT_TRANSLATE_NOOP("JobPipeline", "Planned in working mode %1.")).arg(QString::fromUtf8(toString(*out.mode).data(), static_cast<int>(toString(*out.mode).size())));
  return out;
}

}  // namespace fivebar::widgets
