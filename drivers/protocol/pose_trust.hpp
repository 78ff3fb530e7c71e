// SPDX-License-Identifier: GPL-3.0-or-later
// PoseTrust: whether the host KNOWS where the arms are, never assumed (issue 23).
//
// GRBL counts steps from power-up and keeps the work offset (G54) in its EEPROM, so a board that
// has just powered up reports MPos 0,0 and, through the kept offset, exactly the pose it had
// at the last reference: the report alone cannot tell a powered-up board from a referenced one.
// The host therefore remembers, per board (its port name), where it last saw the machine stand
// still (BoardRecord, saved in the state directory at every change). The pose is known only
// when
//  - the board answers, at rest, with the machine position and work offset of that record, and
//    the record says the machine stood still there (not "moving": the host lost sight of it
//    while it moved), or
//  - the maker set the reference pose (G10 L20 read back), homed ($H answered ok) or confirmed
//    the reported pose, in this session,
// and it stays known while the host watches the board. It becomes unknown at a reset in motion
// (ALARM:3), at a banner after which the board reports another machine position than the last
// one seen (a power cut, a reset button), and when the link goes away.
// Pure logic over the protocol's events; the record file is the only I/O.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>

#include "grbl_protocol.hpp"

namespace fivebar::grbl {

// Why the pose is not known.
enum class PoseDoubt {
  None,            // known
  NotYetRead,      // no status report at rest yet
  NotReferenced,   // the host has no record of this board: never referenced or homed from here
  PositionChanged, // the board reports another machine position than where it last stood (power cut, reset)
  ResetInMotion,   // reset while moving (ALARM:3), hard limit (ALARM:1): steps may be lost
  HomingFailed,    // a homing cycle moved and did not finish (ALARM:6-9)
  RunInterrupted,  // the host lost sight of the board while it moved (stopped, killed, cable)
  Disconnected,    // the link went away
};
const char* toString(PoseDoubt d);  // "power cut or reset", ... (English, for logs)

// Where the host last saw a board, kept across runs (one entry per port name).
struct BoardRecord {
  enum class Standing { AtRest, Moving, Lost };
  Standing standing = Standing::Lost;
  std::array<double, 2> machineDeg{0.0, 0.0};  // MPos X, Y
  std::array<double, 2> wcoDeg{0.0, 0.0};      // work offset X, Y
  PoseDoubt lostBecause = PoseDoubt::None;     // with Standing::Lost
};

// The state directory: $FIVEBAR_STATE_DIR, else $XDG_STATE_HOME/fivebar, else
// ~/.local/state/fivebar. The records are in boards.json there.
std::string boardRecordPath();
std::optional<BoardRecord> loadBoardRecord(const std::string& boardKey);
// Saves atomically; "" or an error sentence naming the file.
std::string saveBoardRecord(const std::string& boardKey, const BoardRecord& record);

class PoseTrust : public ProtocolListener {
 public:
  // Positions agree when within this (GRBL reports 3 decimals; half a step of 35.6 steps/deg is 0.014).
  static constexpr double kSamePositionDeg = 0.002;

  // boardKey: the port name the record is kept under; "" keeps no record (the in-process
  // simulated machine: a new board every time).
  PoseTrust(GrblProtocol& protocol, std::string boardKey);
  ~PoseTrust() override;
  PoseTrust(const PoseTrust&) = delete;
  PoseTrust& operator=(const PoseTrust&) = delete;

  bool known() const { return doubt_ == PoseDoubt::None; }
  PoseDoubt doubt() const { return doubt_; }
  // The maker declared the pose (reference set and read back, homing done, or the reported pose
  // confirmed): known from the next report at rest on.
  void confirmed();
  // The host is about to send a motion: the record says "moving" until the board rests again.
  void aboutToMove();
  // A warning when the record could not be saved (the state directory is not writable), else "".
  const std::string& saveProblem() const { return saveProblem_; }

  std::function<void()> changed;  // doubt() changed

  void onAck(const Ack& ack) override;  // "$H" answered ok: homed, the pose is known
  void onStatus(const StatusReport& report) override;
  void onAlarm(int code, const std::vector<std::uint64_t>& lostIds) override;
  void onReset(const std::string& version, const std::vector<std::uint64_t>& lostIds,
               const std::vector<std::uint64_t>& dropped) override;
  void onDisconnected(const std::string& reason) override;

 private:
  void setDoubt(PoseDoubt d);
  void record(BoardRecord::Standing standing);
  bool atRestNow(const StatusReport& report) const;

  GrblProtocol& protocol_;
  std::string key_;
  std::optional<BoardRecord> saved_;  // as read at the start, then as last written
  PoseDoubt doubt_ = PoseDoubt::NotYetRead;
  bool assessed_ = false;        // the first report at rest was compared with the record
  bool confirmPending_ = false;  // confirmed(): trust the next report at rest
  bool afterReset_ = false;      // a banner came: compare the next report with lastRest_
  std::optional<std::array<double, 2>> lastMachineDeg_;  // from the last report
  bool lastMoving_ = false;
  std::string saveProblem_;
};

}  // namespace fivebar::grbl
