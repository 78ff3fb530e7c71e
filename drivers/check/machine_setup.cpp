// SPDX-License-Identifier: GPL-3.0-or-later
#include "machine_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/output/gcode.hpp"
#include "drivers/protocol/grbl_codes.hpp"

namespace fivebar::setup {

Settings expectedSettings(const MachineProfile& profile) {
  Settings s;
  const std::string text = grblSettings(profile);
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const grbl::ParsedLine p = grbl::parseLine(text.substr(start, end - start));
    if (p.kind == grbl::LineKind::Setting) s[p.settingId] = p.settingValue;
    start = end + 1;
  }
  // $10=3: status reports carry MPos (GRBL's default, bit 0) and Bf: (bit 1), the planner and
  // receive-buffer room from which executed progress, the ETA and the resume point are exact.
  // (Without it progress is derived from the acknowledgements, see JobRunner.)
  s[10] = 3;
  return s;
}

std::vector<SettingDiff> compare(const Settings& board, const Settings& wanted) {
  std::vector<SettingDiff> out;
  for (const auto& [id, value] : wanted) {
    const auto it = board.find(id);
    if (it != board.end() && std::abs(it->second - value) <= 1e-4 * std::max(1.0, std::abs(value)))
      continue;
    out.push_back({id, it == board.end() ? std::nullopt : std::optional<double>(it->second), value});
  }
  return out;
}

namespace {
std::string settingLine(int id, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "$%d=%.4f", id, v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}
}  // namespace

std::vector<std::string> writeLines(const std::vector<SettingDiff>& diffs) {
  std::vector<std::string> lines;
  for (const SettingDiff& d : diffs) lines.push_back(settingLine(d.id, d.wanted));
  return lines;
}

std::string backupText(const Settings& board, const std::string& boardVersion) {
  std::string text = "; GRBL " + boardVersion + " settings backup (restore with fivebar send)\n";
  for (const auto& [id, v] : board) text += settingLine(id, v) + "\n";
  return text;
}

SettingsSync::SettingsSync(grbl::GrblProtocol& protocol) : protocol_(protocol) {
  protocol_.addListener(this);
}
SettingsSync::~SettingsSync() { protocol_.removeListener(this); }

void SettingsSync::read() {
  board_.clear();
  problem_.clear();
  state_ = SetupState::Reading;
  protocol_.enqueue("$I");  // [VER:...] names the firmware in the backup's header
  pending_ = {protocol_.enqueue("$$").id};
}

void SettingsSync::apply(const std::vector<SettingDiff>& diffs,
                         const std::function<std::string(const std::string&)>& saveBackup) {
  if (const std::string err = saveBackup(backupText(board_, protocol_.version())); !err.empty()) {
    fail("backup not saved, nothing written: " + err);
    return;
  }
  state_ = SetupState::Writing;
  pending_.clear();
  for (const std::string& line : writeLines(diffs)) pending_.push_back(protocol_.enqueue(line).id);
  if (pending_.empty()) state_ = SetupState::Done;
  if (changed) changed();
}

void SettingsSync::onLine(const grbl::ParsedLine& line) {
  if (state_ == SetupState::Reading && line.kind == grbl::LineKind::Setting)
    board_[line.settingId] = line.settingValue;
}

void SettingsSync::onAck(const grbl::Ack& ack) {
  const auto it = std::find(pending_.begin(), pending_.end(), ack.id);
  if (it == pending_.end()) return;
  pending_.erase(it);
  if (!ack.ok()) {
    fail("'" + ack.line + "' was refused: " + grbl::describeError(ack.errorCode));
    return;
  }
  if (pending_.empty()) {
    state_ = SetupState::Done;
    if (changed) changed();
  }
}

void SettingsSync::onReset(const std::string&, const std::vector<std::uint64_t>&,
                           const std::vector<std::uint64_t>&) {
  if (state_ == SetupState::Reading || state_ == SetupState::Writing)
    fail("the board reset during setup; read the settings again");
}

void SettingsSync::onDisconnected(const std::string& reason) {
  if (state_ == SetupState::Reading || state_ == SetupState::Writing) fail("connection lost: " + reason);
}

void SettingsSync::fail(const std::string& why) {
  for (std::uint64_t id : protocol_.dropQueued()) std::erase(pending_, id);
  pending_.clear();
  problem_ = why;
  state_ = SetupState::Failed;
  if (changed) changed();
}

}  // namespace fivebar::setup
