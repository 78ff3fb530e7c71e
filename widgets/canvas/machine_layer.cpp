// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/canvas/machine_layer.hpp"

#include "core/machine/pen_kinematics.hpp"
#include "paint/machine_painter.hpp"

namespace fivebar::widgets {

std::optional<Pose> poseOf(const MachineProfile& profile, const JointAngles& angles) {
  const FkResult fk = forward(profile.geometry, angles, profile.assembly);
  if (!fk.ok()) return std::nullopt;
  return makePose(profile.geometry, angles, fk.p);
}

Vec2 penOf(const MachineProfile& profile, const Pose& pose) {
  return penFromDistal(calibratedPenOffset(profile), profile.geometry, pose.R1, pose.P);
}

MachineLayer::MachineLayer(const StudioDocument& doc, const SimulationController& sim,
                           QObject* parent)
    : QObject(parent), doc_(doc), sim_(sim) {
  connect(&sim_, &SimulationController::timeChanged, this, &MachineLayer::refresh);
  connect(&sim_, &SimulationController::trajectoryChanged, this, &MachineLayer::refresh);
  connect(&doc_, &StudioDocument::profileChanged, this, &MachineLayer::refresh);
  refresh();
}

void MachineLayer::setExternalAngles(std::optional<JointAngles> angles) {
  if (external_ == angles && !unknown_) return;
  external_ = angles;
  unknown_ = false;
  refresh();
}

void MachineLayer::setExternalPoseUnknown() {
  if (unknown_) return;
  external_.reset();
  unknown_ = true;
  refresh();
}

void MachineLayer::refresh() {
  const MachineProfile& profile = doc_.profile();
  // The connected machine wins: the simulation is then a ghost while it runs or is scrubbed.
  const bool simulating =
      sim_.trajectory() != nullptr && (sim_.playing() || sim_.timeS() > 0.0);
  ghost_.reset();
  // The simulation's samples carry the pen (Trajectory::at): the linkage comes from the angles.
  if (unknown_) {
    pose_.reset();
    if (simulating) ghost_ = poseOf(profile, sim_.sample().q);
  } else if (external_) {
    pose_ = poseOf(profile, kinematicFromCommanded(profile.calibration, *external_));  // MPos is commanded
    if (simulating) ghost_ = poseOf(profile, sim_.sample().q);
  } else if (sim_.trajectory() != nullptr) {
    pose_ = poseOf(profile, sim_.sample().q);
  } else {
    pose_ = poseOf(profile, kinematicFromCommanded(profile.calibration, profile.homeAngles));
  }
  pen_ = pose_ ? std::optional<Vec2>(penOf(profile, *pose_)) : std::nullopt;
  ghostPen_ = ghost_ ? std::optional<Vec2>(penOf(profile, *ghost_)) : std::nullopt;
  emit changed();
}

void MachineLayer::paint(QPainter& painter, const paint::ViewTransform& view) {
  if (ghost_)
    paint::paintMachine(painter, view.widgetFromMachine(), doc_.profile().geometry, *ghost_, kGhostOpacity, ghostPen_);
  if (unknown_) {
    paint::paintUnknownPose(painter, view.widgetFromMachine(), doc_.profile().geometry);
    return;
  }
  if (!pose_) return;
  // Slightly see-through so the drawing under the arms stays readable.
  paint::paintMachine(painter, view.widgetFromMachine(), doc_.profile().geometry, *pose_, kOpacity, pen_);
}

}  // namespace fivebar::widgets
