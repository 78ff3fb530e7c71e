// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/calibration/run_progress_box.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <algorithm>
#include <cmath>

#include "session/run_controller.hpp"
#include "widgets/machine/run_panel.hpp"

namespace fivebar::widgets::calibration {

RunProgressBox::RunProgressBox(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("patternRunProgress"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  bar_ = new QProgressBar(this);
  bar_->setRange(0, 1000);
  bar_->setTextVisible(true);
  eta_ = new QLabel(this);
  stop_ = new QPushButton(tr("Stop"), this);
  stop_->setToolTip(tr("Stop cleanly: feed hold, then reset with the position kept and the pen up"));
  layout->addWidget(bar_, 1);
  layout->addWidget(eta_);
  layout->addWidget(stop_);
  connect(stop_, &QPushButton::clicked, this, [this] {
    if (run_) run_->stop();
  });
  hide();
}

void RunProgressBox::watch(session::RunController* run) {
  if (run_ == run) {
    refresh();
    return;
  }
  if (run_) disconnect(run_, nullptr, this, nullptr);
  run_ = run;
  if (run_) {
    connect(run_, &session::RunController::progressChanged, this, &RunProgressBox::refresh);
    connect(run_, &session::RunController::runChanged, this, &RunProgressBox::refresh);
  }
  refresh();
}

void RunProgressBox::refresh() {
  if (!run_ || run_->job() == nullptr) {
    hide();
    return;
  }
  show();
  const stream::RunSnapshot& snap = run_->snapshot();
  const std::size_t done = snap.lastCompleted ? *snap.lastCompleted + 1 : 0;
  const double fraction = snap.totalLines > 0 ? double(done) / double(snap.totalLines) : 0.0;
  bar_->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000.0)));
  bar_->setFormat(tr("%1 % (%2)").arg(int(std::floor(fraction * 100.0))).arg(run_->progressText()));
  const bool running = run_->running();
  eta_->setText(running ? tr("%1 left").arg(formatTimeLeft(run_->etaS())) : QString());
  stop_->setEnabled(running);
}

}  // namespace fivebar::widgets::calibration
