// SPDX-License-Identifier: GPL-3.0-or-later
// Painting functions for the canvas background and the machine, each taking a QPainter& so the
// studio, tests and benchmarks paint the same pixels into widgets or QImages. They only draw
// what core computed (a Pose); no kinematics here.
#pragma once

#include <QPainter>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "paint/view_transform.hpp"

namespace fivebar::paint {

// Background colour and the millimetre grid of the visible region, spacing adapted to the zoom
// (minor lines at least ~8 px apart, a major line every 5 or 10 minor ones, labelled in mm).
void paintGrid(QPainter& painter, const ViewTransform& view);

// The machine to scale: base between the motors, motors, driving links a1/a2 to the elbows,
// floating links b1/b2 to the pen, joints and the pen point. `opacity` in [0, 1] fades it (used
// while the drawing is edited so the machine does not hide it). `penMm`: where the pen is when it
// is not at P (a calibrated pen offset): a bracket from P to it on link b1's side, the pen point
// there and a plain joint at P.
void paintMachine(QPainter& painter, const QTransform& widgetFromMachine, const Geometry& g,
                  const Pose& pose, double opacity = 1.0, const std::optional<Vec2>& penMm = std::nullopt);

// The base and motors only, with "Position unknown" above them: the connected machine's pose
// is not known, so no linkage is drawn (never the reported pose through the base).
void paintUnknownPose(QPainter& painter, const QTransform& widgetFromMachine, const Geometry& g);

}  // namespace fivebar::paint
