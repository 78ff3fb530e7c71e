// SPDX-License-Identifier: GPL-3.0-or-later
// The session layer without widgets: MachineSide over a StudioInputs that is no document,
// connected to the in-process simulated machine; the JogController's step moves the machine and
// the JogSettle tracking lets the next jog start from the reported pose.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <functional>

#include "tests/widgets/event_wait.hpp"

#include "core/kinematics/units.hpp"
#include "session/machine_side.hpp"

namespace fivebar {
namespace {

using test::waitUntil;

// The smallest StudioInputs: a profile, no drawing, no planned job.
class FixedInputs : public session::StudioInputs {
 public:
  explicit FixedInputs(MachineProfile profile) : profile_(std::move(profile)) {}
  const MachineProfile& profile() const override { return profile_; }
  QString drawingFileName() const override { return QStringLiteral("nothing.svg"); }
  const PlannedJob* plannedJob() const override { return nullptr; }

 private:
  MachineProfile profile_;
};

TEST(MachineSide, JogsTheSimulatedMachineWithoutAnyWidget) {
  FixedInputs inputs(*preset("maker-plotter"));
  session::MachineSide machine(inputs);
  session::MachineSession& s = machine.session();
  QString error;
  ASSERT_TRUE(machine.connectSimulated(6.0, &error)) << error.toStdString();
  const MachineProfile& p = inputs.profile();
  ASSERT_TRUE(waitUntil([&] {
    const auto q = s.motorAngles();
    return s.isConnected() && s.canJog() && q && std::abs(q->theta1 - p.homeAngles.theta1) < 1e-3;
  }, 10000)) << "connected and referenced at the home pose";
  EXPECT_FALSE(machine.run().canStart()) << "no planned job";
  EXPECT_EQ(machine.run().jobPath().section(QLatin1Char('/'), -1), QStringLiteral("nothing.gcode"));

  // A motor step of 4 deg: the jog's end is where the next jog starts until the reports settle.
  machine.jog().setStep(4.0);
  ASSERT_TRUE(machine.jog().jogStep(session::JogDirection::motorJog(1, -1)));
  ASSERT_TRUE(s.jogStart().has_value());
  EXPECT_NEAR(s.jogStart()->theta1, p.homeAngles.theta1 - radFromDeg(4.0), 1e-6);
  EXPECT_FALSE(s.jogSettled());
  ASSERT_TRUE(waitUntil([&] { return s.jogSettled() && s.state() == grbl::MachineState::Idle; }, 10000));
  EXPECT_NEAR(s.motorAngles()->theta1, p.homeAngles.theta1 - radFromDeg(4.0), radFromDeg(0.05));
  EXPECT_NEAR(s.motorAngles()->theta2, p.homeAngles.theta2, radFromDeg(0.05));
  EXPECT_TRUE(machine.stopRunForQuit()) << "no job runs";
  s.disconnectMachine();
  EXPECT_FALSE(s.isConnected());
}

}  // namespace
}  // namespace fivebar
