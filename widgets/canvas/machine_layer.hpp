// SPDX-License-Identifier: GPL-3.0-or-later
// Canvas layer showing the machine to scale at its current pose: the connected machine's
// reported pose (setExternalAngles) whenever there is one, with the simulation's pose as a
// faint ghost while the simulation runs or is scrubbed; without a machine the simulation's pose,
// else the simulation's start pose or the profile's home pose. The pose is recomputed when its
// source changes (not in paint); paint only draws it. With a calibrated pen offset the pen is
// drawn where it really is, fixed to link b1 off the distal joint P (pen_kinematics.hpp).
#pragma once

#include <QObject>
#include <optional>

#include "core/kinematics/kinematics.hpp"
#include "widgets/canvas/canvas_layer.hpp"
#include "widgets/document/simulation_controller.hpp"
#include "widgets/document/studio_document.hpp"

namespace fivebar::widgets {

class MachineLayer : public QObject, public CanvasLayer {
  Q_OBJECT
 public:
  static constexpr double kOpacity = 0.85;
  static constexpr double kGhostOpacity = 0.25;

  MachineLayer(const StudioDocument& doc, const SimulationController& sim,
               QObject* parent = nullptr);

  void paint(QPainter& painter, const paint::ViewTransform& view) override;
  // The pose drawn (nullopt when the home pose does not close).
  const std::optional<Pose>& pose() const { return pose_; }
  // The simulation's pose drawn faintly behind the machine's (nullopt when none).
  const std::optional<Pose>& ghost() const { return ghost_; }
  // Where the pen of pose() / ghost() is (machine frame, mm): P, or P plus the calibrated pen
  // offset; nullopt with no pose.
  const std::optional<Vec2>& penMm() const { return pen_; }
  const std::optional<Vec2>& ghostPenMm() const { return ghostPen_; }

 public slots:
  // Shows an externally reported pose (the connected machine's position), overriding the
  // simulation until cleared with nullopt.
  void setExternalAngles(std::optional<JointAngles> angles);
  // The connected machine's position is not known (power-up, reset in motion, never
  // referenced): no linkage is drawn for it (never the reported 0/0 through the base), and the
  // canvas says so at the base. Cleared by setExternalAngles.
  void setExternalPoseUnknown();
  bool externalPoseUnknown() const { return unknown_; }

 signals:
  void changed();

 private:
  void refresh();

  const StudioDocument& doc_;
  const SimulationController& sim_;
  std::optional<JointAngles> external_;
  bool unknown_ = false;
  std::optional<Pose> pose_;
  std::optional<Pose> ghost_;
  std::optional<Vec2> pen_, ghostPen_;
};

// The pose of kinematic `angles` in the profile's assembly mode (P the distal joint); nullopt when
// the loop cannot close.
std::optional<Pose> poseOf(const MachineProfile& profile, const JointAngles& angles);
// The pen of a pose of the profile: P, or P plus the calibrated pen offset.
Vec2 penOf(const MachineProfile& profile, const Pose& pose);

}  // namespace fivebar::widgets
