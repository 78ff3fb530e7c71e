// SPDX-License-Identifier: GPL-3.0-or-later
// Plans the job off the UI thread whenever the document's job inputs change (debounced), and
// holds the latest result for the canvas, the preview panel and the simulation. A new request
// cancels the run in progress (core stops at its next chunk) and starts at once, so an undo never
// waits for an outdated plan; a result that arrives after a newer request was made is dropped.
// Also owns the preview scrubber position (UI state: how much of the drawing order is shown).
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>
#include <atomic>
#include <memory>

#include "widgets/document/job_pipeline.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

class PreviewController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kDebounceMs = 150;

  explicit PreviewController(StudioDocument& doc, QObject* parent = nullptr);
  ~PreviewController() override;

  const PreviewResult& result() const { return result_; }
  // A plan is waiting or running: result() is not that of the current document.
  bool busy() const { return running_ > 0 || debounce_.isActive(); }
  // Placement the current result was computed for (to show a stale scene moved live).
  const Placement& resultPlacement() const { return resultPlacement_; }

  // Scrubber: show the job up to this move index (-1 = all).
  int scrubLimit() const { return scrubLimit_; }

 public slots:
  void setScrubLimit(int moveLimit);
  // Starts planning now (skipping the debounce); used by tests and after an import.
  void replanNow();
  // Stops the plan in progress (the result stays that of the last finished plan).
  void cancel();

 signals:
  void planningStarted();
  void resultChanged();
  void scrubLimitChanged(int moveLimit);

 private:
  void startPlanning();
  void onFinished(QFutureWatcher<PreviewResult>* watcher, int generation, Placement placement);

  StudioDocument& doc_;
  QTimer debounce_;
  PreviewResult result_;
  Placement resultPlacement_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  int generation_ = 0;
  int running_ = 0;  // runs of the current generation not finished (0 or 1)
  int scrubLimit_ = -1;
};

}  // namespace fivebar::widgets
