// SPDX-License-Identifier: GPL-3.0-or-later
// PoseSync: learns where the board really is before any position is used (F1 of the machine
// link issue). Polls status until a report arrives; waits for the machine to stand still
// (Idle or Alarm); when the reports carry MPos without a known work offset, asks "$#" (GRBL
// sends WCO: only on some reports) and uses the active G5x + G92 offset it lists; asks "$#" also
// when the stored G28/G30 positions are wanted. Pure logic
// driven by step(nowS) on the protocol's clock.
#pragma once

#include <cstdint>
#include <string>

#include "grbl_protocol.hpp"

namespace fivebar::grbl {

class PoseSync {
 public:
  enum class State { Waiting, Ready, Failed };
  static constexpr double kPollS = 0.25;

  PoseSync(GrblProtocol& protocol, double timeoutS) : protocol_(protocol), timeoutS_(timeoutS) {}
  // Forget what is known (after a $ command, a reset): the next step() reads the pose again.
  void restart() { started_ = false; }
  // Also needs the stored G28/G30 positions (a G28/G30 line is to be checked): asks "$#" even
  // when the work offset came with a status report.
  void wantStoredPositions(bool on) { wantStored_ = on; }
  // Also needs the board's settings ($20 soft limits, $130/$131 travel: the motion check's board
  // part): asks "$$" once when the protocol has not seen them yet.
  void wantSettings(bool on) { wantSettings_ = on; }
  // Asks "$$" anew once after each (re)start even when the protocol has seen them: the settings
  // compared before a job are the board's as they are now.
  void wantFreshSettings(bool on) { freshSettings_ = on; }
  State step(double nowS);
  const std::string& problem() const { return problem_; }

 private:
  GrblProtocol& protocol_;
  double timeoutS_;
  bool started_ = false;
  bool askedParameters_ = false;
  bool wantStored_ = false;
  bool wantSettings_ = false;
  bool askedSettings_ = false;
  bool freshSettings_ = false;
  double deadlineS_ = 0.0;
  double lastPollS_ = -1e300;
  std::uint64_t reportsAtStart_ = 0;
  std::string problem_;
};

}  // namespace fivebar::grbl
