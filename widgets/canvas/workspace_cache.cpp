// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/workspace_cache.hpp"

#include <QtConcurrent/QtConcurrentRun>

namespace fivebar::widgets {
namespace {

bool sameInputs(const WorkspaceSet& set, const MachineProfile& p) {
  const WorkspaceSettings s = workspaceSettings(p);
  return set.geometry == p.geometry && set.settings.limits == s.limits &&
         set.settings.typeIIMarginRad == s.typeIIMarginRad &&
         set.settings.typeIMarginRad == s.typeIMarginRad && set.settings.stepRad1 == s.stepRad1 &&
         set.settings.stepRad2 == s.stepRad2;
}

}  // namespace

std::shared_ptr<const WorkspaceSet> computeWorkspaceSet(const MachineProfile& profile,
                                                        int cellsOnLongSide) {
  auto set = std::make_shared<WorkspaceSet>();
  set->geometry = profile.geometry;
  set->settings = workspaceSettings(profile);
  const GridSpec grid = gridCovering(profile.geometry, cellsOnLongSide);
  computeAllModes(set->geometry, set->settings, grid, set->maps, 2);
  for (std::size_t i = 0; i < set->maps.size(); ++i) {
    set->analyses[i] = analyse(set->maps[i], set->geometry, set->settings);
  }
  return set;
}

WorkspaceCache::WorkspaceCache(StudioDocument& doc, QObject* parent)
    : QObject(parent), doc_(doc) {
  connect(&watcher_, &QFutureWatcher<std::shared_ptr<const WorkspaceSet>>::finished, this,
          &WorkspaceCache::onFinished);
  connect(&doc_, &StudioDocument::profileChanged, this, &WorkspaceCache::restart);
  restart();
}

void WorkspaceCache::restart() {
  if (current_ && sameInputs(*current_, doc_.profile())) return;
  current_.reset();
  if (watcher_.isRunning()) {
    pendingRestart_ = true;
    return;
  }
  watcher_.setFuture(QtConcurrent::run(
      [profile = doc_.profile()] { return computeWorkspaceSet(profile); }));
}

void WorkspaceCache::onFinished() {
  auto set = watcher_.result();
  if (pendingRestart_ || !sameInputs(*set, doc_.profile())) {
    pendingRestart_ = false;
    restart();
    return;
  }
  current_ = std::move(set);
  emit ready();
}

std::shared_ptr<const WorkspaceSet> WorkspaceCache::waitForCurrent() {
  if (current_) return current_;
  if (watcher_.isRunning()) watcher_.waitForFinished();
  auto set = watcher_.isFinished() && !watcher_.future().isCanceled() &&
                     watcher_.future().resultCount() > 0
                 ? watcher_.result()
                 : nullptr;
  if (!set || !sameInputs(*set, doc_.profile())) set = computeWorkspaceSet(doc_.profile());
  current_ = set;
  return current_;
}

std::optional<RectMm> WorkspaceCache::fitRectangle(WorkingMode mode) {
  const auto set = waitForCurrent();
  const auto& r = set->analysis(mode).largestRectangle;
  if (!r) return std::nullopt;
  return RectMm{r->xMin, r->yMin, r->xMax, r->yMax};
}

}  // namespace fivebar::widgets
