// SPDX-License-Identifier: GPL-3.0-or-later
// The four working modes' workspace maps and analyses for the document's machine, computed once
// per geometry (and limits, margins, step angles) off the UI thread and cached, so switching the
// mode is instant. A result for an outdated profile is dropped.
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <array>
#include <memory>
#include <optional>

#include "core/workspace/workspace.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

struct WorkspaceSet {
  Geometry geometry;
  WorkspaceSettings settings;
  std::array<WorkspaceMap, 4> maps;            // indexed like kAllWorkingModes
  std::array<WorkspaceAnalysis, 4> analyses;
  const WorkspaceMap& map(WorkingMode m) const { return maps[static_cast<std::size_t>(m)]; }
  const WorkspaceAnalysis& analysis(WorkingMode m) const {
    return analyses[static_cast<std::size_t>(m)];
  }
};

// Cells along the longer side of the maps: fine enough for smooth curves at full-window zoom.
inline constexpr int kWorkspaceCells = 400;

// Computes everything for one profile (blocking; what the worker runs).
std::shared_ptr<const WorkspaceSet> computeWorkspaceSet(const MachineProfile& profile,
                                                        int cellsOnLongSide = kWorkspaceCells);

class WorkspaceCache : public QObject {
  Q_OBJECT
 public:
  explicit WorkspaceCache(StudioDocument& doc, QObject* parent = nullptr);

  // The set for the current profile, or nullptr while it is being computed.
  std::shared_ptr<const WorkspaceSet> current() const { return current_; }
  // The set for the current profile, waiting for (or computing) it if needed.
  std::shared_ptr<const WorkspaceSet> waitForCurrent();
  // Largest singularity-free rectangle of `mode`, machine frame.
  std::optional<RectMm> fitRectangle(WorkingMode mode);

 signals:
  void ready();

 private:
  void restart();
  void onFinished();

  StudioDocument& doc_;
  QFutureWatcher<std::shared_ptr<const WorkspaceSet>> watcher_;
  std::shared_ptr<const WorkspaceSet> current_;
  bool pendingRestart_ = false;
};

}  // namespace fivebar::widgets
