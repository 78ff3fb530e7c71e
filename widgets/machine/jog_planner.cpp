#include "widgets/machine/jog_planner.hpp"

#include <cmath>

#include "core/kinematics/units.hpp"
#include "drivers/jog.hpp"

namespace fivebar::widgets {
namespace {

// FK samples per joint-linear leg of the path preview.
constexpr int kLegSamples = 24;

// Converts the drivers' plan and samples the pen's path along its joint-linear legs.
JogPlan adapt(const MachineProfile& profile, const JointAngles& current, jog::JogPlan in) {
  JogPlan out;
  switch (in.status) {
    case jog::JogStatus::Ok: out.status = JogStatus::Full; break;
    case jog::JogStatus::Clipped: out.status = JogStatus::Clipped; break;
    case jog::JogStatus::Blocked:
    case jog::JogStatus::NoPosition: out.status = JogStatus::Refused; break;
  }
  out.lines = std::move(in.lines);
  out.targets = std::move(in.targets);
  out.reason = std::move(in.reason);
  if (out.lines.empty()) out.status = JogStatus::Refused;
  const FkResult start = forward(profile.geometry, current, profile.assembly);
  if (!start.ok()) return out;
  out.pathMm.push_back(start.p);
  JointAngles from = current;
  for (const JointAngles& to : out.targets) {
    for (int i = 1; i <= kLegSamples; ++i) {
      const double t = double(i) / kLegSamples;
      const JointAngles q{from.theta1 + (to.theta1 - from.theta1) * t,
                          from.theta2 + (to.theta2 - from.theta2) * t};
      const FkResult fk = forward(profile.geometry, q, profile.assembly);
      if (fk.ok()) out.pathMm.push_back(fk.p);
    }
    from = to;
  }
  return out;
}

}  // namespace

JogPlan planCartesianJog(const MachineProfile& profile, const JointAngles& current, Vec2 deltaMm,
                         double speedMmPerS) {
  const double length = deltaMm.norm();
  if (!(length > 0.0)) {
    JogPlan refused;
    refused.reason = "zero-length jog";
    return refused;
  }
  return adapt(profile, current,
               jog::planCartesianJog(profile, current, deltaMm, length, speedMmPerS, kJogChordToleranceMm));
}

JogPlan planMotorJog(const MachineProfile& profile, const JointAngles& current, int motorIndex,
                     double deltaRad, double speedRadPerS) {
  return adapt(profile, current,
               jog::planMotorJog(profile, current, motorIndex, degFromRad(deltaRad),
                                 degFromRad(std::abs(speedRadPerS)) * 60.0));
}

JogPlan planGoTo(const MachineProfile& profile, const JointAngles& current, Vec2 targetMm) {
  return adapt(profile, current, jog::planGoTo(profile, current, targetMm));
}

}  // namespace fivebar::widgets
