// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/machine/run_layer.hpp"

#include <algorithm>

#include "core/kinematics/units.hpp"

namespace fivebar::widgets {

QColor runDoneColour() { return QColor(0x16, 0xa3, 0x4a); }  // green: apart from the speed colours

RunLayer::RunLayer(const session::RunController& run, const session::MachineView& view, QObject* parent)
    : QObject(parent), run_(run), view_(view) {
  connect(&run_, &session::RunController::runChanged, this, &RunLayer::rebuild);
  connect(&run_, &session::RunController::progressChanged, this, &RunLayer::changed);
  connect(&view_, &session::MachineView::statusUpdated, this, &RunLayer::changed);
  connect(&view_, &session::MachineView::connectionChanged, this, &RunLayer::changed);
}

void RunLayer::rebuild() {
  const stream::GcodeJob* job = run_.job();
  if (job == builtFor_) return;
  builtFor_ = job;
  segments_.clear();
  if (job == nullptr) return;
  const MachineProfile& profile = view_.profile();
  std::optional<QPointF> previous;
  for (std::size_t i = 0; i < job->lines.size(); ++i) {
    const stream::JobLine& line = job->lines[i];
    // G-code angles are commanded; the kinematics takes commanded + zero offset.
    const JointAngles q =
        kinematicFromCommanded(profile.calibration, {radFromDeg(line.endDeg[0]), radFromDeg(line.endDeg[1])});
    const FkResult fk = forward(profile.geometry, q, profile.assembly);
    const std::optional<QPointF> end =
        fk.ok() ? std::optional<QPointF>(QPointF(fk.p.x(), fk.p.y())) : std::nullopt;
    if (line.motion && line.penDownDuring && previous && end) segments_.push_back({i, QLineF(*previous, *end)});
    if (line.motion || end) previous = end;
  }
  emit changed();
}

std::size_t RunLayer::doneSegments() const {
  const auto& last = run_.snapshot().lastCompleted;
  if (!last || run_.job() != builtFor_) return 0;
  const auto it = std::upper_bound(segments_.begin(), segments_.end(), *last,
                                   [](std::size_t index, const Segment& s) { return index < s.lineIndex; });
  return std::size_t(it - segments_.begin());
}

void RunLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  painter.save();
  const std::size_t done = doneSegments();
  if (done > 0) {
    std::vector<QLineF> lines;
    lines.reserve(done);
    for (std::size_t i = 0; i < done; ++i) lines.push_back(segments_[i].mm);
    painter.setTransform(view.widgetFromMachine());
    QPen pen(runDoneColour(), 3.0);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::RoundCap);
    painter.setPen(pen);
    painter.setRenderHint(QPainter::Antialiasing, lines.size() < 20000);
    painter.drawLines(lines.data(), int(lines.size()));
    painter.resetTransform();
  }
  if (const auto p = view_.penMm()) {
    const QPointF at = view.widgetFromMachine(QPointF(p->x(), p->y()));
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(runDoneColour(), 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(at, 6.0, 6.0);
  }
  painter.restore();
}

}  // namespace fivebar::widgets
