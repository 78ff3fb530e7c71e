// SPDX-License-Identifier: GPL-3.0-or-later
// A short session with a GRBL board for the machine commands that move or declare (reference,
// home, frame): read the board's pose (status report at rest, $# for the work offset, $$ when
// its settings are wanted), let the command decide what to send, send it line by line (each
// answered before the next), wait for rest, read the pose again and let the command verify.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "drivers/check/motion_check.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/protocol/pose_sync.hpp"
#include "options.hpp"

namespace fivebar::cli {

class Procedure : public grbl::ProtocolListener {
 public:
  // decide(pose): lines to send (empty: done) or nullopt after reporting a refusal.
  using Decide =
      std::function<std::optional<std::vector<std::string>>(const motion::BoardPose&, MachineLink&)>;
  using Verify = std::function<int(const motion::BoardPose&)>;  // exit code
  Procedure(MachineLink& link, std::string command, double timeoutS, Decide decide, Verify verify);
  ~Procedure() override;

  // True when done; exitCode() then says how it went.
  bool step(double nowS);
  int exitCode() const { return exitCode_; }
  bool allowAlarm = false;  // decide even while the board is in alarm ($H is the way out)
  // Read the board's $$ before deciding (its soft limits for the motion check, the settings to
  // compare): protocol().boardSettings() holds them in decide.
  void wantSettings(bool on) { sync_.wantSettings(on); sync_.wantFreshSettings(on); }

  void onAck(const grbl::Ack& a) override;
  void onAlarm(int code, const std::vector<std::uint64_t>&) override;
  void onDisconnected(const std::string& reason) override;

 private:
  enum class Phase { Read, Sending, Verify };
  bool fail(const std::string& why);
  bool finish(int code);

  MachineLink& link_;
  std::string command_;
  double timeoutS_;
  grbl::PoseSync sync_;
  Decide decide_;
  Verify verify_;
  Phase phase_ = Phase::Read;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  std::uint64_t pending_ = 0;
  double deadlineS_ = 0.0;
  bool done_ = false;
  int exitCode_ = 1;
};

// Opens --port (--baud), runs the procedure on the Qt event loop, returns its exit code.
int runProcedure(const Options& o, const std::string& command, double timeoutS, Procedure::Decide decide,
                 Procedure::Verify verify, bool allowAlarm = false, bool wantSettings = false);

}  // namespace fivebar::cli
