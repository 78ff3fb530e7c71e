// The preflight step of the studio pipeline (working-mode choice and pre-flight problems). Its
// own header and translation unit so that core/feasibility.hpp and core/job.hpp are never
// included together.
#pragma once

#include <QPointF>
#include <QString>
#include <optional>
#include <vector>

#include "core/planning/drawing.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/strokes.hpp"
#include "widgets/studio_document.hpp"

namespace fivebar::widgets {

// One pre-flight or planning problem, ready for the problems list.
struct PreviewProblem {
  QString text;        // what and why, names the layer and path
  QPointF whereMm;     // machine frame
  int layerIndex = -1;
  int pathIndex = -1;
};

struct PreflightSummary {
  std::optional<WorkingMode> mode;  // chosen or picked mode; nullopt when Auto found none
  bool feasible = false;
  double minMarginRad = 0.0;
  std::vector<PreviewProblem> problems;
};
PreflightSummary runPreflight(const std::vector<Stroke>& strokes, const Drawing& drawing,
                              const MachineProfile& profile, ModeSelection choice);

}  // namespace fivebar::widgets
