// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/simulation_panel.hpp"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "core/kinematics/singularity.hpp"
#include "core/kinematics/units.hpp"
#include "widgets/panels/preview_panel.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {
namespace {
// A value as printed with `decimals` decimals, without a "-0.00".
double printable(double value, int decimals) {
  return std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}
}  // namespace

SimulationPanel::SimulationPanel(SimulationController& sim, const StudioDocument& doc,
                                 QWidget* parent)
    : QWidget(parent), sim_(sim), doc_(doc) {
  auto* layout = new QVBoxLayout(this);
  auto* controls = new QHBoxLayout;
  const auto button = [&](QStyle::StandardPixmap icon, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(style()->standardIcon(icon));
    b->setToolTip(tip);
    controls->addWidget(b);
    return b;
  };
  back_ = button(QStyle::SP_MediaSkipBackward, tr("Step back one move"));
  play_ = button(QStyle::SP_MediaPlay, tr("Play / pause the simulation"));
  play_->setObjectName(QStringLiteral("simulationPlay"));
  forward_ = button(QStyle::SP_MediaSkipForward, tr("Step forward one move"));
  speed_ = new QComboBox(this);
  speed_->setToolTip(tr("Simulation speed"));
  for (double s : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    speed_->addItem(tr("x%1").arg(s), s);
  }
  speed_->setCurrentIndex(1);
  controls->addWidget(speed_);
  controls->addStretch(1);
  layout->addLayout(controls);
  timeline_ = new QSlider(Qt::Horizontal, this);
  timeline_->setRange(0, kTimelineSteps);
  timeline_->setObjectName(QStringLiteral("simulationTimeline"));
  layout->addWidget(timeline_);
  time_ = new QLabel(this);
  layout->addWidget(time_);
  readout_ = new QLabel(this);
  readout_->setTextFormat(Qt::RichText);
  readout_->setObjectName(QStringLiteral("simulationReadout"));
  layout->addWidget(readout_);
  layout->addStretch(1);

  connect(play_, &QToolButton::clicked, &sim_, &SimulationController::togglePlay);
  connect(back_, &QToolButton::clicked, &sim_, &SimulationController::stepBackward);
  connect(forward_, &QToolButton::clicked, &sim_, &SimulationController::stepForward);
  connect(speed_, &QComboBox::currentIndexChanged, this,
          [this] { sim_.setSpeed(speed_->currentData().toDouble()); });
  connect(timeline_, &QSlider::valueChanged, this, [this](int v) {
    sim_.setTimeS(sim_.durationS() * v / kTimelineSteps);
  });
  connect(&sim_, &SimulationController::timeChanged, this, &SimulationPanel::showTime);
  connect(&sim_, &SimulationController::trajectoryChanged, this, &SimulationPanel::showTime);
  connect(&sim_, &SimulationController::playingChanged, this, &SimulationPanel::showPlaying);
  showTime();
}

void SimulationPanel::showPlaying(bool playing) {
  play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
}

void SimulationPanel::showTime() {
  const bool has = sim_.trajectory() != nullptr;
  for (QWidget* w : {static_cast<QWidget*>(play_), static_cast<QWidget*>(back_),
                     static_cast<QWidget*>(forward_), static_cast<QWidget*>(timeline_)}) {
    w->setEnabled(has);
  }
  {
    const QSignalBlocker blocker(timeline_);
    const double d = sim_.durationS();
    timeline_->setValue(d > 0.0 ? static_cast<int>(sim_.timeS() / d * kTimelineSteps) : 0);
  }
  if (!has) {
    time_->setText(tr("No planned job to simulate."));
    readout_->clear();
    return;
  }
  time_->setText(tr("%1 of %2").arg(formatJobTime(sim_.timeS()), formatJobTime(sim_.durationS())));
  const TrajectorySample s = sim_.sample();
  const Geometry& g = doc_.profile().geometry;
  const Pose pose = makePose(g, s.q, s.p);
  const TransmissionAngles mu = transmissionAngles(g, pose);
  const SingularityMargins m = singularityMargins(g, pose);
  readout_->setText(
      tr("<table>"
         "<tr><td>Motor angles:</td><td>%1 deg, %2 deg</td></tr>"
         "<tr><td>Pen:</td><td>x %3 mm, y %4 mm (%5)</td></tr>"
         "<tr><td>Transmission angle:</td><td>%6 deg at the pen</td></tr>"
         "<tr><td></td><td>%7 / %8 deg at the elbows</td></tr>"
         "<tr><td>Type II margin:</td><td><b>%9 deg</b></td></tr></table>")
          .arg(QLocale().toString(degFromRad(s.q.theta1), 'f', 2))
          .arg(QLocale().toString(degFromRad(s.q.theta2), 'f', 2))
          .arg(QLocale().toString(printable(s.p.x(), 2), 'f', 2))
          .arg(QLocale().toString(printable(s.p.y(), 2), 'f', 2))
          .arg(s.penDown ? tr("down") : tr("up"))
          .arg(QLocale().toString(degFromRad(mu.mu), 'f', 1))
          .arg(QLocale().toString(degFromRad(mu.mu1), 'f', 1))
          .arg(QLocale().toString(degFromRad(mu.mu2), 'f', 1))
          .arg(QLocale().toString(degFromRad(m.typeII), 'f', 1)));
}

}  // namespace fivebar::widgets
