// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas layer for a job running on the machine: the pen-down part of the job the machine has
// executed (by the runner's executed-line count, which follows the machine's status reports) is
// drawn over the drawing in the "done" colour, and the machine's reported pen position is marked.
// The job's line ends are converted to the machine frame once per run (forward kinematics of
// each line's joint target), never in paint.
#pragma once

#include <QLineF>
#include <QObject>
#include <optional>
#include <vector>

#include "widgets/canvas/canvas_layer.hpp"
#include "session/machine_view.hpp"
#include "session/run_controller.hpp"

namespace fivebar::widgets {

class RunLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  RunLayer(const session::RunController& run, const session::MachineView& view, QObject* parent = nullptr);

  void paint(QPainter& painter, const paint::ViewTransform& view) override;
  // Pen-down segments (machine frame, mm) executed so far.
  std::size_t doneSegments() const;
  std::size_t totalSegments() const { return segments_.size(); }

 signals:
  void changed();

 private:
  void rebuild();

  struct Segment {
    std::size_t lineIndex;  // the job line that draws it
    QLineF mm;
  };
  const session::RunController& run_;
  const session::MachineView& view_;
  const stream::GcodeJob* builtFor_ = nullptr;
  std::vector<Segment> segments_;  // in line order
};

// The "done" colour of executed strokes.
QColor runDoneColour();

}  // namespace fivebar::widgets
