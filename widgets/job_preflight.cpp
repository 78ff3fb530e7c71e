// The preflight step of the studio pipeline. Kept apart from job_pipeline.cpp so that the
// feasibility and job models are never included together.
#include <QCoreApplication>
#include <algorithm>

#include "core/planning/feasibility.hpp"
#include "widgets/job_preflight.hpp"

namespace fivebar::widgets {
namespace {

PreviewProblem toPreview(const PreflightProblem& p) {
  PreviewProblem out;
  out.text = QString::fromStdString(p.reason);
  out.whereMm = QPointF(p.whereMm.x(), p.whereMm.y());
  out.layerIndex = p.layerIndex;
  out.pathIndex = p.pathIndex;
  return out;
}

void fillFrom(const FeasibilityReport& report, PreflightSummary& out) {
  out.feasible = report.feasible;
  out.minMarginRad = report.minTypeIIMarginRad;
  for (const PreflightProblem& p : report.problems) out.problems.push_back(toPreview(p));
}

}  // namespace

PreflightSummary runPreflight(const std::vector<Stroke>& strokes, const Drawing& drawing,
                              const MachineProfile& profile, ModeSelection choice) {
  (void)drawing;
  PreflightSummary out;
  PreflightOptions options;
  options.maxListedProblems = 200;
  if (choice) {
    out.mode = *choice;
    fillFrom(preflight(strokes, profile, *choice, options), out);
    return out;
  }
  const fivebar::ModeChoice choiceResult = fivebar::chooseMode(strokes, profile, options);
  // With no feasible mode, show what fails in the profile's own mode.
  const WorkingMode shown = choiceResult.mode.value_or(profile.defaultMode);
  out.mode = choiceResult.mode;
  const auto it = std::find_if(choiceResult.reports.begin(), choiceResult.reports.end(),
                               [&](const FeasibilityReport& r) { return r.mode == shown; });
  if (it != choiceResult.reports.end()) {
    fillFrom(*it, out);
  } else {
    fillFrom(preflight(strokes, profile, shown, options), out);
  }
  return out;
}

}  // namespace fivebar::widgets
