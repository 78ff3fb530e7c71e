// SPDX-License-Identifier: GPL-3.0-or-later
#include "session/jog_controller.hpp"

#include <algorithm>
#include <cmath>

#include "core/kinematics/units.hpp"

namespace fivebar::session {

JogController::JogController(MachineSession& session, QObject* parent)
    : QObject(parent), session_(session) {
  holdTimer_.setSingleShot(true);
  holdTimer_.setInterval(kHoldThresholdMs);
  connect(&holdTimer_, &QTimer::timeout, this, [this] {
    if (!pressed_) return;
    streaming_ = pressed_;
    topUp();
    if (streaming_) streamTimer_.start();
  });
  streamTimer_.setInterval(kStreamPeriodMs);
  connect(&streamTimer_, &QTimer::timeout, this, &JogController::topUp);
  connect(&session_, &MachineSession::connectionChanged, this, [this](bool connected) {
    if (connected) return;
    holdTimer_.stop();
    streamTimer_.stop();
    pressed_.reset();
    streaming_.reset();
  });
}

jog::JogPlan JogController::plan(const JogDirection& direction, double amount) const {
  const auto start = session_.jogStart();
  if (!start) {
    jog::JogPlan refused;
    refused.status = jog::JogStatus::NoPosition;
    refused.reason = FB_TR("Jog", "the machine position is not known yet");
    return refused;
  }
  return session_.boardChecked(plannedFrom(*start, direction, amount), true);
}

jog::JogPlan JogController::plannedFrom(const JointAngles& start, const JogDirection& direction,
                                        double amount) const {
  const MachineProfile& profile = session_.profile();
  if (direction.kind == JogDirection::Kind::Cartesian) {
    return jog::planCartesianJog(profile, start, direction.xy, amount, speedMmPerS_);
  }
  const double maxRadPerS = direction.motor == 1 ? profile.motors.maxSpeedRadPerS1
                                                 : profile.motors.maxSpeedRadPerS2;
  const double speedRadPerS = std::min(radFromDeg(kMotorSpeedDegPerS), maxRadPerS);
  return jog::planMotorJog(profile, start, direction.motor, direction.sign * amount,
                           degFromRad(speedRadPerS) * 60.0);
}

bool JogController::jogStep(const JogDirection& direction) {
  if (!session_.canJog()) {
    emit message(tr("Jog refused: the machine is not connected, not idle, or a job is running."));
    return false;
  }
  const jog::JogPlan p = plan(direction, step_);
  report(p);
  return p.ok() && session_.sendJog(p);
}

void JogController::press(const JogDirection& direction) {
  if (pressed_) return;
  pressed_ = direction;
  pressClock_.start();
  holdTimer_.start();
}

void JogController::release() {
  if (!pressed_) return;
  const JogDirection direction = *pressed_;
  pressed_.reset();
  if (holdTimer_.isActive()) {  // a tap: one step
    holdTimer_.stop();
    jogStep(direction);
    return;
  }
  streamTimer_.stop();
  if (streaming_) {
    streaming_.reset();
    session_.cancelJog();
  }
}

void JogController::topUp() {
  if (!streaming_ || !session_.link()) return;
  if (!session_.canJog()) return;  // waiting for the machine; the stream resumes when it can
  const grbl::GrblProtocol& protocol = session_.link()->protocol();
  while (streaming_ && protocol.linesInFlight() + protocol.linesQueued() < kLinesAhead &&
         leadS(*streaming_) < kLeadS) {
    double amount = speedMmPerS_ * kChunkS;
    if (streaming_->kind == JogDirection::Kind::Motor) amount = kMotorSpeedDegPerS * kChunkS;
    const jog::JogPlan p = plan(*streaming_, amount);
    if (p.ok() && !session_.sendJog(p)) {
      streaming_.reset();
      break;
    }
    if (p.status != jog::JogStatus::Ok) {
      // The edge of the safe region: the machine stops at the last safe point by itself.
      report(p);
      streaming_.reset();
    }
  }
  if (!streaming_) streamTimer_.stop();
}

double JogController::leadS(const JogDirection& direction) const {
  const auto reported = session_.motorAngles();
  const auto planned = session_.jogStart();
  if (!reported || !planned) return 0.0;
  if (direction.kind == JogDirection::Kind::Motor) {
    const double deltaDeg = degFromRad(std::hypot(planned->theta1 - reported->theta1,
                                                  planned->theta2 - reported->theta2));
    return deltaDeg / kMotorSpeedDegPerS;
  }
  const MachineProfile& profile = session_.profile();
  const FkResult a = forward(profile.geometry, *reported, profile.assembly);
  const FkResult b = forward(profile.geometry, *planned, profile.assembly);
  if (!a.ok() || !b.ok()) return 0.0;
  return (b.p - a.p).norm() / std::max(speedMmPerS_, 1e-6);
}

void JogController::report(const jog::JogPlan& p) {
  switch (p.status) {
    case jog::JogStatus::Ok: emit message(QString()); break;
    case jog::JogStatus::Clipped:
      emit message(tr("Jog stopped at the last safe point: %1").arg(MachineSession::studioText(p.reason)));
      break;
    case jog::JogStatus::Blocked:
    case jog::JogStatus::NoPosition:
      emit message(tr("Jog refused: %1").arg(MachineSession::studioText(p.reason)));
      break;
  }
}

}  // namespace fivebar::session
