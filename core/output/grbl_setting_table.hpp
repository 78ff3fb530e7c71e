// SPDX-License-Identifier: GPL-3.0-or-later
// The one table of GRBL 1.1h's $ settings: what each means and its unit on this machine. On a
// five-bar the board's X and Y axes are the two motor angles (docs/machine-protocol.md), so
// GRBL's "mm" of X and Y are degrees here: $100/$101 are steps/deg, $110/$111 deg/min,
// $120/$121 deg/s^2, $130/$131 deg, and the junction deviation and arc tolerance ($11, $12)
// are in degrees too. Z (the pen on a Z-axis tool) keeps mm.
// Meanings are marked for translation (context "GrblSetting"): `fivebar setup` prints them in
// English, the studio's Machine settings view translates them. Units are symbols, not words.
#pragma once

#include <vector>

namespace fivebar {

struct GrblSettingInfo {
  int id = 0;                  // the N of $N
  const char* meaning = "";    // "Step pulse time" (English; translate with context "GrblSetting")
  const char* unit = "";       // "µs", "steps/deg", ...; "" for on/off switches and bit masks
};

// Every setting of GRBL 1.1h, in id order.
const std::vector<GrblSettingInfo>& grblSettingTable();
// The entry of `id`, or nullptr for a setting GRBL 1.1h does not have.
const GrblSettingInfo* grblSettingInfo(int id);

}  // namespace fivebar
