// SPDX-License-Identifier: GPL-3.0-or-later
#include "pose_sync.hpp"

#include <cstdio>

namespace fivebar::grbl {

PoseSync::State PoseSync::step(double nowS) {
  if (!started_) {
    started_ = true;
    askedParameters_ = false;
    askedSettings_ = false;
    deadlineS_ = nowS + timeoutS_;
    reportsAtStart_ = protocol_.statusReportsSeen();
    lastPollS_ = -1e300;
    problem_.clear();
  }
  const auto timeText = [this] {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", timeoutS_);
    return std::string(buf);
  };
  const bool fresh = protocol_.statusReportsSeen() > reportsAtStart_;
  const MachineState st = protocol_.state();
  const bool still = st == MachineState::Idle || st == MachineState::Alarm || st == MachineState::Sleep ||
                     st == MachineState::Door || st == MachineState::Check;
  if (fresh && still && !protocol_.parametersPending()) {
    const bool storedKnown = !wantStored_ || (protocol_.parameter("G28") && protocol_.parameter("G30"));
    // Settings: known, or the "$$" asked for was answered (a board without $20 has none to check).
    const bool settingsKnown = freshSettings_ ? askedSettings_ && protocol_.idleLink()
                               : !wantSettings_ || protocol_.boardSettings().count(20) > 0 ||
                                     (askedSettings_ && protocol_.idleLink());
    if (protocol_.workPositionDeg() && storedKnown && settingsKnown) return State::Ready;
    if (!settingsKnown && !askedSettings_ && protocol_.idleLink()) {
      askedSettings_ = true;
      protocol_.requestSettings();
    }
    if (!askedParameters_ && protocol_.idleLink()) {
      askedParameters_ = true;
      if (protocol_.requestParameters() != 0) reportsAtStart_ = protocol_.statusReportsSeen();
    }
  }
  if (nowS > deadlineS_) {
    problem_ = !fresh ? "no status report within " + timeText() +
                            ": is it a GRBL 1.1 board at this baud rate?"
               : !still ? "the machine did not come to rest within " + timeText() +
                              " (state " + std::string(toString(st)) + ")"
                        : "the board did not report its work offset (WCO: or $#)" +
                              std::string(wantStored_ ? " or its stored G28/G30 positions" : "") +
                              std::string(wantSettings_ || freshSettings_ ? " or its settings ($$)" : "") +
                              " within " + timeText();
    return State::Failed;
  }
  if (nowS - lastPollS_ >= kPollS) {
    lastPollS_ = nowS;
    protocol_.sendRealtime(realtime::kStatus);
  }
  return State::Waiting;
}

}  // namespace fivebar::grbl
