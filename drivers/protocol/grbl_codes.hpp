// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL 1.1 error and alarm codes as data: each code with a short name, a plain explanation of
// what happened and what to do. The tables are the single source for every message the
// drivers, the CLI and the studio show about a rejected line or an alarm.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace fivebar::grbl {

struct CodeInfo {
  int code = 0;
  std::string_view name;     // short, e.g. "Soft limit"
  std::string_view meaning;  // what happened, one sentence
  std::string_view action;   // what to do, one sentence
};

// All GRBL 1.1 error codes (1-17, 20-38; 18 and 19 are unused by GRBL) and alarm codes (1-9).
std::span<const CodeInfo> errorCodes();
std::span<const CodeInfo> alarmCodes();

// Lookup; nullptr for a code GRBL 1.1 does not define.
const CodeInfo* findError(int code);
const CodeInfo* findAlarm(int code);

// "error:9 (G-code lock): G-code commands are locked out while in alarm or jog state. Unlock
// with '$X' or home with '$H' first." Unknown codes still give a readable sentence.
std::string describeError(int code);
std::string describeAlarm(int code);

}  // namespace fivebar::grbl
