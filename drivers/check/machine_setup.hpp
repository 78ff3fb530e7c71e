// SPDX-License-Identifier: GPL-3.0-or-later
// Machine setup: read the board's $$ settings, compare them with what the profile expects
// (core/gcode.hpp grblSettings: steps/deg $100/$101, rates $110/$111, accelerations
// $120/$121, soft limits $20/$130/$131, junction deviation $11, ...), back up the board's
// values to a file, then write the differences one at a time (GrblProtocol sends $N=V lines
// exclusively: each waits for the previous ok, never inside a counted stream).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/machine/profile.hpp"
#include "drivers/protocol/grbl_protocol.hpp"

namespace fivebar::setup {

using Settings = std::map<int, double>;

// The settings the profile expects, parsed from core's grblSettings(profile).
Settings expectedSettings(const MachineProfile& profile);

struct SettingDiff {
  int id = 0;
  std::optional<double> board;  // nullopt: the board did not report it
  double wanted = 0.0;
};
// Settings whose board value differs from the wanted one by more than a relative 1e-4 (or is
// missing), in id order.
std::vector<SettingDiff> compare(const Settings& board, const Settings& wanted);
std::vector<std::string> writeLines(const std::vector<SettingDiff>& diffs);  // "$100=35.5556"
// The board's values as a restorable file: one "$N=V" per line, with a header comment.
std::string backupText(const Settings& board, const std::string& boardVersion);

enum class SetupState { Idle, Reading, Writing, Done, Failed };

// Reads $$ and (optionally) writes differences. Drive it with the protocol's events.
class SettingsSync : public grbl::ProtocolListener {
 public:
  explicit SettingsSync(grbl::GrblProtocol& protocol);
  ~SettingsSync() override;
  void read();  // sends "$$"; collects until its ok
  // Saves the backup (the callback returns an error message or "") and then writes the lines
  // one at a time. Fails without writing anything when the backup cannot be saved.
  void apply(const std::vector<SettingDiff>& diffs,
             const std::function<std::string(const std::string& backup)>& saveBackup);

  SetupState state() const { return state_; }
  const Settings& board() const { return board_; }
  const std::string& problem() const { return problem_; }
  std::function<void()> changed;

  void onLine(const grbl::ParsedLine& line) override;
  void onAck(const grbl::Ack& ack) override;
  void onReset(const std::string&, const std::vector<std::uint64_t>&,
               const std::vector<std::uint64_t>&) override;
  void onDisconnected(const std::string& reason) override;

 private:
  void fail(const std::string& why);
  grbl::GrblProtocol& protocol_;
  SetupState state_ = SetupState::Idle;
  Settings board_;
  std::vector<std::uint64_t> pending_;
  std::string problem_;
};

}  // namespace fivebar::setup
