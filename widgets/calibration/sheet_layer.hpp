// SPDX-License-Identifier: GPL-3.0-or-later
// The studio canvas's picture of the calibration sheet while the wizard is open: the pattern as
// planned and, on the simulated imperfect machine, what its pen really drew, as its own layer with
// a legend (bottom left). Empty (paints nothing) when the wizard is closed.
#pragma once

#include <QObject>
#include <vector>

#include "core/kinematics/geometry.hpp"
#include "widgets/canvas/canvas_layer.hpp"

namespace fivebar::widgets::calibration {

class SheetLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  explicit SheetLayer(QObject* parent = nullptr) : QObject(parent) {}
  void setSheet(std::vector<std::vector<Vec2>> plan, std::vector<std::vector<Vec2>> trace);
  void clear() { setSheet({}, {}); }
  bool empty() const { return plan_.empty() && trace_.empty(); }
  void paint(QPainter& painter, const paint::ViewTransform& view) override;

 signals:
  void changed();

 private:
  std::vector<std::vector<Vec2>> plan_, trace_;
};

}  // namespace fivebar::widgets::calibration
