// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/run_panel.hpp"

#include "widgets/machine/override_controls.hpp"

#include <QMessageBox>

#include "widgets/document/job_pipeline.hpp"
#include "widgets/machine/alarm_strip.hpp"
#include "session/settings_advice.hpp"

#include <QCoreApplication>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace fivebar::widgets {
namespace {

QString runStateName(stream::RunState s) {
  switch (s) {
    case stream::RunState::Ready: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Ready");
    case stream::RunState::Running: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Running");
    case stream::RunState::Holding: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Holding…");
    case stream::RunState::Held: return QCoreApplication::translate("fivebar::widgets::RunPanel", "On hold");
    case stream::RunState::Paused: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Paused by a problem");
    case stream::RunState::Stopping: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Stopping…");
    case stream::RunState::Stopped: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Stopped");
    case stream::RunState::Finished: return QCoreApplication::translate("fivebar::widgets::RunPanel", "Finished");
  }
  return {};
}

}  // namespace

QString formatTimeLeft(double seconds) {
  if (!(seconds >= 0.0)) return QStringLiteral("–");
  const long s = std::lround(seconds);
  if (s >= 3600)
    return QCoreApplication::translate("fivebar::widgets::RunPanel", "%1 h %2 min").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0'));
  if (s >= 60)
    return QCoreApplication::translate("fivebar::widgets::RunPanel", "%1 min %2 s").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
  return QCoreApplication::translate("fivebar::widgets::RunPanel", "%1 s").arg(s);
}

RunPanel::RunPanel(session::RunController& run, session::MachineView& view,
                   session::BoardSettingsPort& settings, QWidget* parent)
    : QWidget(parent), run_(run), view_(view), settings_(settings) {
  setObjectName(QStringLiteral("runPanel"));
  start_ = new QPushButton(tr("Start"), this);
  start_->setToolTip(tr("Write the planned job as G-code and stream it to the machine"));
  hold_ = new QPushButton(tr("Hold"), this);
  hold_->setToolTip(tr("Feed hold: the machine decelerates and waits"));
  continue_ = new QPushButton(tr("Continue"), this);
  continue_->setToolTip(tr("Continue after a hold"));
  stop_ = new QPushButton(tr("Stop"), this);
  stop_->setToolTip(tr("Stop the job: hold, reset and unlock; the progress is kept for a resume"));
  resume_ = new QPushButton(tr("Resume"), this);
  resume_->setToolTip(tr("Continue the interrupted job from its last completed pen-down point, "
                         "with a safe pen-up approach"));
  resumeInfo_ = new QLabel(this);
  resumeInfo_->setWordWrap(true);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setTextVisible(true);
  state_ = new QLabel(this);
  QFont bold = state_->font();
  bold.setBold(true);
  state_->setFont(bold);
  eta_ = new QLabel(this);
  eta_->setToolTip(tr("Machine time left by the plan, planned again at the feed and rapid override "
                      "the machine reports"));
  message_ = new QLabel(this);
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  overrides_ = new OverrideControls(run_, this);

  auto* buttons = new QGridLayout;
  buttons->addWidget(start_, 0, 0);
  buttons->addWidget(hold_, 0, 1);
  buttons->addWidget(continue_, 0, 2);
  buttons->addWidget(stop_, 0, 3);
  auto* stateRow = new QHBoxLayout;
  stateRow->addWidget(state_);
  stateRow->addStretch(1);
  stateRow->addWidget(eta_);
  auto* resumeRow = new QVBoxLayout;
  resumeRow->addWidget(resumeInfo_);
  resumeRow->addWidget(resume_, 0, Qt::AlignLeft);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(8, 8, 8, 8);
  alarm_ = new AlarmStrip(view_, this);  // first: an alarm is the first thing to see
  layout->addWidget(alarm_);
  layout->addLayout(buttons);
  layout->addLayout(stateRow);
  layout->addWidget(progress_);
  layout->addWidget(overrides_);
  layout->addWidget(message_);
  layout->addLayout(resumeRow);
  layout->addStretch(1);

  connect(start_, &QPushButton::clicked, this, &RunPanel::startClicked);
  connect(resume_, &QPushButton::clicked, this, &RunPanel::resumeClicked);
  connect(hold_, &QPushButton::clicked, &run_, &session::RunController::hold);
  connect(continue_, &QPushButton::clicked, &run_, &session::RunController::continueRun);
  connect(stop_, &QPushButton::clicked, &run_, &session::RunController::stop);
  connect(&run_, &session::RunController::runChanged, this, &RunPanel::refresh);
  connect(&run_, &session::RunController::progressChanged, this, &RunPanel::refreshProgress);
  refresh();
}

void RunPanel::startClicked() {
  // A very long job is worth a second thought before the machine is busy for hours.
  if (const PlannedJob* job = run_.plannedJob()) {
    const QString question = longJobQuestion(*job);
    if (!question.isEmpty() &&
        QMessageBox::question(this, tr("Long job"), question, QMessageBox::Yes | QMessageBox::No,
                              QMessageBox::No) != QMessageBox::Yes)
      return;
  }
  if (!confirmDiscardResume() || !confirmSettings()) return;
  run_.start();
}

// A new Start writes the job again and drops the saved progress of the interrupted run.
bool RunPanel::confirmDiscardResume() {
  const QString offer = run_.resumeOffer();
  if (offer.isEmpty()) return true;
  QMessageBox box(QMessageBox::Question, tr("Start from the beginning?"),
                  tr("%1\n\nStart draws \"%2\" from the beginning and discards this saved progress. "
                     "Resume continues the interrupted run instead.")
                      .arg(offer, run_.drawingName()),
                  QMessageBox::NoButton, this);
  box.setObjectName(QStringLiteral("discardResumeQuestion"));
  QPushButton* start = box.addButton(tr("Discard and start over"), QMessageBox::DestructiveRole);
  start->setObjectName(QStringLiteral("discardAndStart"));
  box.addButton(QMessageBox::Cancel)->setText(tr("Cancel"));
  box.setDefaultButton(qobject_cast<QPushButton*>(box.button(QMessageBox::Cancel)));
  box.exec();
  return box.clickedButton() == start;
}

// The board's $ settings against the profile's: a difference is explained before the machine
// moves (soft limits, steps/deg, rates), with the offer to write the profile's values.
bool RunPanel::confirmSettings() {
  if (!view_.boardSettingsKnown()) {
    settings_.readBoardSettings();
    message_->setText(tr("Reading the board's settings to compare them with the profile: press "
                         "Start again in a moment."));
    return false;
  }
  const auto diffs = view_.settingDifferences();
  if (diffs.empty()) return true;
  QMessageBox box(QMessageBox::Warning, tr("The board's settings differ"), session::settingsMismatchText(diffs),
                  QMessageBox::NoButton, this);
  box.setObjectName(QStringLiteral("settingsMismatch"));
  box.setTextFormat(Qt::RichText);
  QPushButton* write = box.addButton(tr("Write the profile's settings..."), QMessageBox::ActionRole);
  write->setObjectName(QStringLiteral("writeSettings"));
  QPushButton* anyway = box.addButton(tr("Start anyway"), QMessageBox::DestructiveRole);
  anyway->setObjectName(QStringLiteral("startAnyway"));
  box.addButton(QMessageBox::Cancel)->setText(tr("Cancel"));
  box.setDefaultButton(qobject_cast<QPushButton*>(box.button(QMessageBox::Cancel)));
  box.exec();
  if (box.clickedButton() == write && openSettings_) openSettings_();
  if (box.clickedButton() == anyway) run_.ignoreSettingsOnce();  // the drivers compare them again
  return box.clickedButton() == anyway;
}

void RunPanel::resumeClicked() {
  if (confirmSettings()) run_.resume();
}

void RunPanel::refresh() {
  const stream::RunState s = run_.state();
  const bool running = run_.running();
  start_->setEnabled(run_.canStart());
  hold_->setEnabled(running && s == stream::RunState::Running);
  continue_->setEnabled(running && (s == stream::RunState::Held || s == stream::RunState::Holding));
  stop_->setEnabled(running && s != stream::RunState::Stopping);
  const auto saved = running ? std::nullopt : run_.savedProgress();
  resume_->setVisible(saved.has_value());
  resumeInfo_->setVisible(saved.has_value());
  resume_->setEnabled(saved.has_value() && run_.canResume());
  if (saved) resumeInfo_->setText(run_.resumeOffer());
  state_->setText(run_.job() ? runStateName(s) : tr("No job sent yet"));
  message_->setText(run_.lastMessage());
  message_->setStyleSheet(s == stream::RunState::Stopped || s == stream::RunState::Paused
                              ? QStringLiteral("color: #dc2626")
                              : QString());
  refreshProgress();
}

void RunPanel::refreshProgress() {
  const stream::RunSnapshot& snap = run_.snapshot();
  const std::size_t done = snap.lastCompleted ? *snap.lastCompleted + 1 : 0;
  const double fraction = snap.totalLines > 0 ? double(done) / double(snap.totalLines) : 0.0;
  progress_->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000.0)));
  progress_->setFormat(run_.job() ? tr("%1 % (%2)").arg(int(std::floor(fraction * 100.0))).arg(run_.progressText())
                                  : QString());
  const stream::RunState rs = run_.state();
  const bool held = rs == stream::RunState::Held || rs == stream::RunState::Holding;
  eta_->setText(!run_.running() ? QString()
                : held         ? tr("%1 left (on hold)").arg(formatTimeLeft(run_.etaS()))
                               : tr("%1 left").arg(formatTimeLeft(run_.etaS())));
  const stream::RunState s = run_.state();
  if (run_.job()) state_->setText(runStateName(s));
}

}  // namespace fivebar::widgets
