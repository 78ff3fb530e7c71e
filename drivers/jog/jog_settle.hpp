// SPDX-License-Identifier: GPL-3.0-or-later
// JogSettle: when may the host trust the reported position again after a jog, a jog cancel or
// a new reference pose? GRBL acknowledges a $J= line when it enters the planner, not when the
// motion ends, and a jog cancel (0x85) empties the planner but not the serial buffer, so the
// host tracks:
//  - the jog lines sent and not yet answered;
//  - the end of the jog that may still be running (where the next jog starts from);
//  - after a cancel, the lines that were already in the board's buffer: once the last of them is
//    answered it has entered the planner, and a second cancel must stop it;
//  - after a reference command (G10 L20), that the position is known again only from a report
//    carrying the new work offset (WCO);
//  - "settled": kReportsToSettle quiet status reports (Idle, no jog line in flight, no WCO awaited)
//    after the last of these events. Two, because at most one '?' is outstanding: the second report
//    was certainly requested after the last jog answer.
// Pure: line ids and report facts in, queries and one action out. No Qt, no I/O.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "drivers/protocol/grbl_parser.hpp"

namespace fivebar::jog {

class JogSettle {
 public:
  static constexpr int kReportsToSettle = 2;

  // What the host must do after an answer.
  enum class AckAction { None, CancelAgain };

  // A jog (or go-to) plan was queued: the ids of its lines and the joint target it ends at
  // (commanded angles, rad; nullopt when its lines carry no motion).
  void jogSent(const std::vector<std::uint64_t>& lineIds, const std::optional<JointAngles>& end);
  // A jog cancel (0x85) was sent after the host dropped droppedIds from its own queue (never sent).
  // Where the machine stops is known only from later reports: jogs are blocked until settled.
  void cancelled(const std::vector<std::uint64_t>& droppedIds);
  // A reference command (G10 L20) was queued as line `id`.
  void referenceSent(std::uint64_t id);
  // The board answered line `id` (ok or error).
  AckAction answered(std::uint64_t id, bool ok);
  // A status report arrived: its state and whether it carried a work offset (WCO).
  void reported(grbl::MachineState state, bool hasWco);
  // An alarm or a reset: these lines will never be answered, and nothing is moving any more.
  void interrupted(const std::vector<std::uint64_t>& lostIds);
  // The link closed: forget everything.
  void clear();

  // The end of the jog that may still be running (the next jog starts there); nullopt once settled.
  const std::optional<JointAngles>& pendingEnd() const { return end_; }
  // No jog of ours may still be moving (its end confirmed by quiet status reports).
  bool settled() const { return !end_ && !blocked_; }
  // After a cancel or a new reference: no jog may be sent until settled.
  bool blocked() const { return blocked_; }
  bool isJogLine(std::uint64_t id) const { return jogLines_.count(id) > 0; }
  std::size_t jogLinesInFlight() const { return jogLines_.size(); }

 private:
  std::set<std::uint64_t> jogLines_;     // jog / go-to lines not yet answered
  std::set<std::uint64_t> cancelAfter_;  // lines in the board's buffer at the last cancel
  std::optional<JointAngles> end_;
  int reportsLeft_ = 0;  // quiet reports still needed before end_ is forgotten
  bool blocked_ = false;
  std::optional<std::uint64_t> referenceLine_;  // G10 L20 not yet answered
  bool awaitWco_ = false;                       // answered; waiting for a report with the WCO
};

}  // namespace fivebar::jog
