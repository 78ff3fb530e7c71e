#include "widgets/preview_controller.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <exception>

namespace fivebar::widgets {

PreviewController::PreviewController(StudioDocument& doc, QObject* parent)
    : QObject(parent), doc_(doc) {
  debounce_.setSingleShot(true);
  debounce_.setInterval(kDebounceMs);
  connect(&debounce_, &QTimer::timeout, this, &PreviewController::startPlanning);
  connect(&doc_, &StudioDocument::jobInputsChanged, &debounce_, qOverload<>(&QTimer::start));
  connect(&watcher_, &QFutureWatcher<PreviewResult>::finished, this,
          &PreviewController::onFinished);
}

void PreviewController::replanNow() {
  debounce_.stop();
  startPlanning();
}

void PreviewController::setScrubLimit(int moveLimit) {
  if (moveLimit == scrubLimit_) return;
  scrubLimit_ = moveLimit;
  emit scrubLimitChanged(moveLimit);
}

void PreviewController::startPlanning() {
  if (watcher_.isRunning()) {
    pendingRestart_ = true;  // plan again with the newest inputs when this run ends
    return;
  }
  PipelineInput input{doc_.drawing(), doc_.placement(), doc_.profile(), doc_.modeSelection()};
  runningPlacement_ = input.placement;
  emit planningStarted();
  watcher_.setFuture(QtConcurrent::run([input = std::move(input)]() {
    try {
      return runPipeline(input);
    } catch (const std::exception& e) {
      // A broken invariant in core must not reach the event loop: report it as a failure.
      PreviewResult failed;
      failed.status = PreviewStatus::Failed;
      failed.message = QObject::tr("Planning failed: %1").arg(QString::fromUtf8(e.what()));
      return failed;
    }
  }));
}

void PreviewController::onFinished() {
  if (pendingRestart_) {
    pendingRestart_ = false;
    startPlanning();  // the finished result is already stale
    return;
  }
  result_ = watcher_.result();
  resultPlacement_ = runningPlacement_;
  scrubLimit_ = -1;
  doc_.setAutoResolvedMode(result_.mode);
  emit resultChanged();
  emit scrubLimitChanged(scrubLimit_);
}

}  // namespace fivebar::widgets
