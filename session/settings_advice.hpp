// SPDX-License-Identifier: GPL-3.0-or-later
// What a difference between the board's GRBL $ settings and the profile's means for a maker:
// one sentence per differing setting, and whether it would stop (or spoil) a job, so the machine
// panel can warn on connect and Start can explain a mismatch before the machine moves.
// Pure (Qt strings only, translated in the context "fivebar::session::SettingsAdvice").
#pragma once

#include <QString>
#include <vector>

#include "drivers/check/machine_setup.hpp"

namespace fivebar::session {

struct SettingAdvice {
  int id = 0;
  QString text;           // "$20 soft limits: board 1, profile 0. ..."
  bool stopsJob = false;  // the job would stop with an alarm or move the arms wrongly
};

std::vector<SettingAdvice> adviseOnSettings(const std::vector<setup::SettingDiff>& diffs);
bool anyStopsJob(const std::vector<SettingAdvice>& advice);
// One paragraph for the machine panel's warning.
QString settingsWarningText(const std::vector<setup::SettingDiff>& diffs);
// The explanation Start shows (rich text, one bullet per difference).
QString settingsMismatchText(const std::vector<setup::SettingDiff>& diffs);

}  // namespace fivebar::session
