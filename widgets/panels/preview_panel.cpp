// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/preview_panel.hpp"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLinearGradient>
#include <QListWidget>
#include <QLocale>
#include <QPainter>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "core/kinematics/units.hpp"
#include "widgets/canvas/job_layer.hpp"
#include "widgets/canvas/path_scene.hpp"
#include "widgets/document/preview_controller.hpp"
#include "paint/studio_palette.hpp"

namespace fivebar::widgets {

QString formatJobTime(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return QStringLiteral("-");
  if (seconds < 60.0) return PreviewPanel::tr("%1 s").arg(QLocale().toString(seconds, 'f', 1));
  const long total = std::lround(seconds);
  const long h = total / 3600, m = (total % 3600) / 60, s = total % 60;
  if (h > 0) return PreviewPanel::tr("%1 h %2 min").arg(h).arg(m, 2, 10, QLatin1Char('0'));
  return PreviewPanel::tr("%1 min %2 s").arg(m).arg(s, 2, 10, QLatin1Char('0'));
}

// The job time against the time-optimal reference (core/planning/time_optimal.hpp), as a share
// of what the machine can do (GRBL can beat the reference slightly at corners: shown as 100 %).
namespace {
QString speedShare(const JobSummary& s) {
  if (!(s.timeOptimalS > 0.0) || !(s.estimatedTimeS > 0.0)) return {};
  const int percent = static_cast<int>(std::lround(100.0 * s.timeOptimalS / s.estimatedTimeS));
  return PreviewPanel::tr("%1 % of what this machine can do").arg(std::min(percent, 100));
}
}  // namespace

SpeedLegend::SpeedLegend(QWidget* parent) : QWidget(parent) { setMinimumHeight(34); }

void SpeedLegend::setMaxSpeed(double mmPerS) {
  maxSpeed_ = mmPerS;
  update();
}

void SpeedLegend::paintEvent(QPaintEvent*) {
  QPainter p(this);
  const QRectF bar(4.0, 4.0, width() - 8.0, 10.0);
  QLinearGradient g(bar.topLeft(), bar.topRight());
  for (int k = 0; k <= 8; ++k) g.setColorAt(k / 8.0, PathScene::speedColour(k / 8.0));
  p.fillRect(bar, g);
  p.setPen(paint::palette::gridLabel());
  QFont f = font();
  f.setPointSizeF(8.0);
  p.setFont(f);
  const QRectF text(bar.left(), bar.bottom() + 2.0, bar.width(), 16.0);
  p.drawText(text, Qt::AlignLeft | Qt::AlignTop, tr("0 mm/s"));
  p.drawText(text, Qt::AlignRight | Qt::AlignTop, tr("%1 mm/s").arg(QLocale().toString(maxSpeed_, 'f', 0)));
}

namespace {
// The problems list asks for its minimum height only: the dock gives it the rest. (A list asks
// for 192 px, and the docks' scroll area gives a panel with wrapping labels its asked-for
// height, so the dock would scroll and cut the list off at the default window size.)
class ProblemList : public QListWidget {
 public:
  using QListWidget::QListWidget;
  QSize sizeHint() const override { return {QListWidget::sizeHint().width(), minimumHeight()}; }
};
}  // namespace

PreviewPanel::PreviewPanel(PreviewController& preview, JobLayer& layer, QWidget* parent)
    : QWidget(parent), preview_(preview), layer_(layer) {
  auto* layout = new QVBoxLayout(this);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->setObjectName(QStringLiteral("previewStatus"));
  layout->addWidget(status_);
  stats_ = new QLabel(this);
  stats_->setTextFormat(Qt::RichText);
  stats_->setObjectName(QStringLiteral("previewStatistics"));
  layout->addWidget(stats_);

  auto* show = new QGroupBox(tr("Show"), this);
  auto* showLayout = new QVBoxLayout(show);
  bySpeed_ = new QCheckBox(tr("Colour pen-down moves by speed"), show);
  travel_ = new QCheckBox(tr("Pen-up moves (grey)"), show);
  legend_ = new SpeedLegend(show);
  showLayout->addWidget(bySpeed_);
  showLayout->addWidget(legend_);
  showLayout->addWidget(travel_);
  layout->addWidget(show);

  auto* order = new QGroupBox(tr("Drawing order"), this);
  auto* orderLayout = new QVBoxLayout(order);
  scrubber_ = new QSlider(Qt::Horizontal, order);
  scrubber_->setObjectName(QStringLiteral("previewScrubber"));
  scrubLabel_ = new QLabel(order);
  orderLayout->addWidget(scrubber_);
  orderLayout->addWidget(scrubLabel_);
  layout->addWidget(order);

  layout->addWidget(new QLabel(tr("Pre-flight problems (click to show):"), this));
  problems_ = new ProblemList(this);
  problems_->setObjectName(QStringLiteral("previewProblems"));
  problems_->setWordWrap(true);
  problems_->setMinimumHeight(110);  // room to read a problem and what to do about it
  layout->addWidget(problems_, 1);

  bySpeed_->setChecked(layer_.colourBySpeed());
  travel_->setChecked(layer_.showTravel());
  connect(bySpeed_, &QCheckBox::toggled, &layer_, &JobLayer::setColourBySpeed);
  connect(bySpeed_, &QCheckBox::toggled, legend_, &QWidget::setVisible);
  connect(travel_, &QCheckBox::toggled, &layer_, &JobLayer::setShowTravel);
  connect(scrubber_, &QSlider::valueChanged, this, [this](int v) {
    preview_.setScrubLimit(v >= scrubber_->maximum() ? -1 : v);
    scrubLabel_->setText(tr("Moves shown: %1 of %2").arg(QLocale().toString(v), QLocale().toString(scrubber_->maximum())));
  });
  connect(problems_, &QListWidget::currentRowChanged, this, [this](int row) {
    const auto& problems = preview_.result().problems;
    if (!machineProblem_.isEmpty()) --row;  // the board's problem comes first; it has no place
    if (row < 0 || row >= static_cast<int>(problems.size())) {
      layer_.setMarker(std::nullopt);
      return;
    }
    layer_.setMarker(problems[static_cast<std::size_t>(row)].whereMm);
    emit showLocation(problems[static_cast<std::size_t>(row)].whereMm);
  });
  connect(&preview_, &PreviewController::planningStarted, this, &PreviewPanel::showPlanning);
  connect(&preview_, &PreviewController::resultChanged, this, &PreviewPanel::showResult);
  showResult();
}

void PreviewPanel::showPlanning() { status_->setText(tr("Planning...")); }

void PreviewPanel::showResult() {
  const PreviewResult& r = preview_.result();
  switch (r.status) {
    case PreviewStatus::Planned: status_->setText(tr("Planned.")); break;
    case PreviewStatus::Empty: status_->setText(tr("Open a drawing to plan a job.")); break;
    case PreviewStatus::Infeasible:
    case PreviewStatus::Failed:
    case PreviewStatus::Cancelled: status_->setText(r.message); break;
  }
  if (preview_.busy()) showPlanning();
  const QString mode = r.mode ? QString::fromLatin1(toString(*r.mode).data(), 2)
                              : QStringLiteral("-");
  if (r.status == PreviewStatus::Planned) {
    const JobSummary& s = r.job->summary;
    stats_->setText(tr("<table>"
                       "<tr><td>Working mode:</td><td><b>%1</b></td></tr>"
                       "<tr><td>Estimated time:</td><td><b>%2</b></td></tr>"
                       "<tr><td></td><td>%8</td></tr>"
                       "<tr><td>Pen down:</td><td>%3 mm</td></tr>"
                       "<tr><td>Pen up:</td><td>%4 mm</td></tr>"
                       "<tr><td>Segments:</td><td>%5</td></tr>"
                       "<tr><td>Max deviation:</td><td>%6 mm</td></tr>"
                       "<tr><td>Singularity margin:</td><td>%7 deg</td></tr></table>")
                        .arg(mode, formatJobTime(r.trajectory->durationS()))
                        .arg(QLocale().toString(s.penDownMm, 'f', 0))
                        .arg(QLocale().toString(s.travelMm, 'f', 0))
                        .arg(QLocale().toString(qlonglong(s.segments)))
                        .arg(QLocale().toString(r.report.maxDeviationMm, 'f', 3))
                        .arg(QLocale().toString(degFromRad(s.minTypeIIMarginRad), 'f', 1))
                        .arg(speedShare(s)));
  } else {
    stats_->setText(tr("Working mode: <b>%1</b>").arg(mode));
  }
  legend_->setMaxSpeed(r.jobScene ? r.jobScene->maxSpeedMmPerS() : 0.0);
  legend_->setVisible(bySpeed_->isChecked());
  const int moves = r.job ? static_cast<int>(r.job->moves.size()) : 0;
  {
    const QSignalBlocker blocker(scrubber_);
    scrubber_->setRange(0, moves);
    scrubber_->setValue(moves);
    scrubber_->setEnabled(moves > 0);
  }
  scrubLabel_->setText(tr("Moves shown: %1 of %2").arg(moves).arg(moves));
  problems_->clear();
  if (!machineProblem_.isEmpty()) {
    auto* item = new QListWidgetItem(machineProblem_, problems_);
    item->setForeground(paint::palette::problem());
    item->setToolTip(machineProblem_);
    item->setData(Qt::UserRole, QStringLiteral("board"));
  }
  for (const PreviewProblem& p : r.problems) {
    QString text = p.text;
    if (!p.fixes.isEmpty()) text += QStringLiteral("\n") + tr("What to do: %1").arg(p.fixes.join(tr("; ")));
    auto* item = new QListWidgetItem(text, problems_);
    item->setForeground(paint::palette::problem());
    item->setToolTip(text);
  }
  if (r.problems.empty() && machineProblem_.isEmpty() && r.status == PreviewStatus::Planned) {
    auto* item = new QListWidgetItem(tr("No problems: every move is reachable and safe."), problems_);
    item->setFlags(Qt::NoItemFlags);
  }
}

void PreviewPanel::setMachineProblem(const QString& problem) {
  if (problem == machineProblem_) return;
  machineProblem_ = problem;
  showResult();
}

}  // namespace fivebar::widgets
