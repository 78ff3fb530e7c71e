// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/preview_controller.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <exception>

namespace fivebar::widgets {

PreviewController::PreviewController(StudioDocument& doc, QObject* parent)
    : QObject(parent), doc_(doc) {
  debounce_.setSingleShot(true);
  debounce_.setInterval(kDebounceMs);
  connect(&debounce_, &QTimer::timeout, this, &PreviewController::startPlanning);
  connect(&doc_, &StudioDocument::jobInputsChanged, this, [this] {
    if (cancel_) cancel_->store(true);  // the running plan is outdated already
    debounce_.start();
  });
}

PreviewController::~PreviewController() {
  if (cancel_) cancel_->store(true);
}

void PreviewController::replanNow() {
  debounce_.stop();
  startPlanning();
}

void PreviewController::cancel() {
  debounce_.stop();
  if (cancel_) cancel_->store(true);
}

void PreviewController::setScrubLimit(int moveLimit) {
  if (moveLimit == scrubLimit_) return;
  scrubLimit_ = moveLimit;
  emit scrubLimitChanged(moveLimit);
}

void PreviewController::startPlanning() {
  if (cancel_) cancel_->store(true);  // an older run stops at its next chunk; its result is dropped
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  const int generation = ++generation_;
  PipelineInput input{doc_.drawingSnapshot(), doc_.source(), doc_.placement(), doc_.profile(),
                      doc_.modeSelection(), doc_.toleranceMm(), cancel_};
  const Placement placement = input.placement;
  running_ = 1;
  emit planningStarted();
  auto* watcher = new QFutureWatcher<PreviewResult>(this);
  connect(watcher, &QFutureWatcher<PreviewResult>::finished, this,
          [this, watcher, generation, placement] { onFinished(watcher, generation, placement); });
  watcher->setFuture(QtConcurrent::run([input = std::move(input)]() {
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

void PreviewController::onFinished(QFutureWatcher<PreviewResult>* watcher, int generation,
                                   Placement placement) {
  watcher->deleteLater();
  if (generation != generation_) return;  // a newer plan was asked for
  running_ = 0;
  PreviewResult r = watcher->result();
  if (r.status == PreviewStatus::Cancelled) {
    emit resultChanged();  // busy() changed: the views stop showing "planning"
    return;
  }
  if (r.refinedDrawing) doc_.applyRefinedDrawing(*r.refinedDrawing);
  result_ = std::move(r);
  resultPlacement_ = placement;
  scrubLimit_ = -1;
  doc_.setAutoResolvedMode(result_.mode);
  emit resultChanged();
  emit scrubLimitChanged(scrubLimit_);
}

}  // namespace fivebar::widgets
