// SPDX-License-Identifier: GPL-3.0-or-later
// The board procedure. Contract: board_procedure.hpp.
#include "board_procedure.hpp"

#include <iostream>

#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "machine_arg.hpp"
#include "machine_cli.hpp"

namespace fivebar::cli {

Procedure::Procedure(MachineLink& link, std::string command, double timeoutS, Decide decide, Verify verify)
    : link_(link), command_(std::move(command)), timeoutS_(timeoutS), sync_(link.protocol(), timeoutS),
      decide_(std::move(decide)), verify_(std::move(verify)) {
  link_.protocol().addListener(this);
}

Procedure::~Procedure() { link_.protocol().removeListener(this); }

bool Procedure::step(double nowS) {
  if (done_) return true;
  if (phase_ == Phase::Sending) {
    if (nowS > deadlineS_) return fail("no answer within " + std::to_string(int(timeoutS_)) + " s");
    if (pending_ != 0) return false;
    if (next_ < lines_.size()) {
      const auto r = link_.protocol().enqueue(lines_[next_++]);
      if (!r.ok()) return fail("'" + lines_[next_ - 1] + "': " + grbl::describe(r.status));
      pending_ = r.id;
      return false;
    }
    phase_ = Phase::Verify;
    sync_.restart();
  }
  const auto st = sync_.step(nowS);
  if (st == grbl::PoseSync::State::Failed) return fail("cannot read the machine's pose: " + sync_.problem());
  if (st == grbl::PoseSync::State::Waiting) return false;
  const auto pose = motion::boardPoseOf(link_.protocol());
  if (!pose) return false;
  if (phase_ == Phase::Verify) return finish(verify_(*pose));
  if (link_.protocol().state() == grbl::MachineState::Alarm && !allowAlarm)
    return fail("the machine is in alarm: check it, then unlock with \"fivebar send --port " +
                link_.transport().name().toStdString() + " '$X'\" and run this again");
  const auto lines = decide_(*pose, link_);
  if (!lines) return finish(1);
  lines_ = *lines;
  phase_ = Phase::Sending;
  deadlineS_ = nowS + timeoutS_;
  return false;
}

void Procedure::onAck(const grbl::Ack& a) {
  if (a.id != pending_) return;
  pending_ = 0;
  if (!a.ok()) fail("'" + a.line + "' was refused: " + grbl::describeError(a.errorCode));
}

void Procedure::onAlarm(int code, const std::vector<std::uint64_t>&) {
  if (phase_ == Phase::Sending) fail(grbl::describeAlarm(code));
}

void Procedure::onDisconnected(const std::string& reason) { fail("connection lost: " + reason); }

bool Procedure::fail(const std::string& why) {
  if (!done_) std::cerr << "fivebar " << command_ << ": " << why << "\n";
  return finish(1);
}

bool Procedure::finish(int code) {
  if (!done_) exitCode_ = code;
  done_ = true;
  return true;
}

int runProcedure(const Options& o, const std::string& command, double timeoutS, Procedure::Decide decide,
                 Procedure::Verify verify, bool allowAlarm, bool wantSettings) {
  QtApp qt;
  const std::unique_ptr<Transport> transport = portTransport(o);
  Transport& port = *transport;
  MachineLink link(port, 0.0);
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar " << command << ": " << error.toStdString() << "\n";
    return 1;
  }
  Procedure proc(link, command, timeoutS, std::move(decide), std::move(verify));
  proc.allowAlarm = allowAlarm;
  proc.wantSettings(wantSettings);
  QObject::connect(&link, &MachineLink::ticked, [&](double now) {
    if (proc.step(now)) qt.app.quit();
  });
  link.start();
  qt.app.exec();
  port.close();
  return proc.exitCode();
}

}  // namespace fivebar::cli
