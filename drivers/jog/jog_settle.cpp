// SPDX-License-Identifier: GPL-3.0-or-later
#include "drivers/jog/jog_settle.hpp"

namespace fivebar::jog {

void JogSettle::jogSent(const std::vector<std::uint64_t>& lineIds, const std::optional<JointAngles>& end) {
  jogLines_.insert(lineIds.begin(), lineIds.end());
  if (end) end_ = end;
  reportsLeft_ = kReportsToSettle;
}

void JogSettle::cancelled(const std::vector<std::uint64_t>& droppedIds) {
  for (std::uint64_t id : droppedIds) jogLines_.erase(id);
  cancelAfter_ = jogLines_;
  end_.reset();
  blocked_ = true;
  reportsLeft_ = kReportsToSettle;
}

void JogSettle::referenceSent(std::uint64_t id) {
  referenceLine_ = id;
  awaitWco_ = true;
  end_.reset();
  blocked_ = true;
  reportsLeft_ = kReportsToSettle;
}

JogSettle::AckAction JogSettle::answered(std::uint64_t id, bool ok) {
  if (referenceLine_ && *referenceLine_ == id) {
    referenceLine_.reset();
    if (!ok) awaitWco_ = false;  // refused: no new offset is coming
  }
  const bool jog = jogLines_.erase(id) > 0;
  // A refused jog line: the plan stops there, the machine stands where the reports say.
  if (jog && !ok) end_.reset();
  if (cancelAfter_.erase(id) > 0 && cancelAfter_.empty()) return AckAction::CancelAgain;
  return AckAction::None;
}

void JogSettle::reported(grbl::MachineState state, bool hasWco) {
  if (awaitWco_ && !referenceLine_ && hasWco) awaitWco_ = false;
  const bool quiet = state == grbl::MachineState::Idle && jogLines_.empty() && !awaitWco_;
  if (quiet && reportsLeft_ > 0 && --reportsLeft_ == 0) {
    end_.reset();
    blocked_ = false;
  }
}

void JogSettle::interrupted(const std::vector<std::uint64_t>& lostIds) {
  for (std::uint64_t id : lostIds) jogLines_.erase(id);
  cancelAfter_.clear();
  end_.reset();
  blocked_ = false;
  reportsLeft_ = 0;
  referenceLine_.reset();
  awaitWco_ = false;
}

void JogSettle::clear() { *this = JogSettle{}; }

}  // namespace fivebar::jog
