// Plans the job off the UI thread whenever the document's job inputs change (debounced), and
// holds the latest result for the canvas, the preview panel and the simulation. A result that
// arrives after a newer request was made is dropped. Also owns the preview scrubber position
// (UI state: how much of the drawing order is shown).
#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include "widgets/job_pipeline.hpp"
#include "widgets/studio_document.hpp"

namespace fivebar::widgets {

class PreviewController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kDebounceMs = 150;

  explicit PreviewController(StudioDocument& doc, QObject* parent = nullptr);

  const PreviewResult& result() const { return result_; }
  bool busy() const { return watcher_.isRunning() || debounce_.isActive(); }
  // Placement the current result was computed for (to show a stale scene moved live).
  const Placement& resultPlacement() const { return resultPlacement_; }

  // Scrubber: show the job up to this move index (-1 = all).
  int scrubLimit() const { return scrubLimit_; }

 public slots:
  void setScrubLimit(int moveLimit);
  // Starts planning now (skipping the debounce); used by tests and after an import.
  void replanNow();

 signals:
  void planningStarted();
  void resultChanged();
  void scrubLimitChanged(int moveLimit);

 private:
  void startPlanning();
  void onFinished();

  StudioDocument& doc_;
  QTimer debounce_;
  QFutureWatcher<PreviewResult> watcher_;
  PreviewResult result_;
  Placement resultPlacement_;
  Placement runningPlacement_;
  bool pendingRestart_ = false;
  int scrubLimit_ = -1;
};

}  // namespace fivebar::widgets
