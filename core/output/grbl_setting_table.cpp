// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/grbl_setting_table.hpp"

#include <algorithm>

#include "core/support/message.hpp"

namespace fivebar {

const std::vector<GrblSettingInfo>& grblSettingTable() {
  // GRBL 1.1h's settings (grbl/doc/markdown/settings.md), with X = motor 1 and Y = motor 2.
  static const std::vector<GrblSettingInfo> table = {
      {0, FB_TR_NOOP("GrblSetting", "Step pulse time"), "µs"},
      {1, FB_TR_NOOP("GrblSetting", "Step idle delay (255: motors always on)"), "ms"},
      {2, FB_TR_NOOP("GrblSetting", "Step pulse invert (bit mask)"), ""},
      {3, FB_TR_NOOP("GrblSetting", "Direction invert (bit mask)"), ""},
      {4, FB_TR_NOOP("GrblSetting", "Invert step enable pin (on/off)"), ""},
      {5, FB_TR_NOOP("GrblSetting", "Invert limit pins (on/off)"), ""},
      {6, FB_TR_NOOP("GrblSetting", "Invert probe pin (on/off)"), ""},
      {10, FB_TR_NOOP("GrblSetting", "Status report options (bit mask)"), ""},
      {11, FB_TR_NOOP("GrblSetting", "Junction deviation"), "deg"},
      {12, FB_TR_NOOP("GrblSetting", "Arc tolerance"), "deg"},
      {13, FB_TR_NOOP("GrblSetting", "Report in inches (on/off)"), ""},
      {20, FB_TR_NOOP("GrblSetting", "Soft limits (on/off)"), ""},
      {21, FB_TR_NOOP("GrblSetting", "Hard limits (on/off)"), ""},
      {22, FB_TR_NOOP("GrblSetting", "Homing cycle (on/off)"), ""},
      {23, FB_TR_NOOP("GrblSetting", "Homing direction invert (bit mask)"), ""},
      {24, FB_TR_NOOP("GrblSetting", "Homing locate feed rate"), "deg/min"},
      {25, FB_TR_NOOP("GrblSetting", "Homing search seek rate"), "deg/min"},
      {26, FB_TR_NOOP("GrblSetting", "Homing switch debounce delay"), "ms"},
      {27, FB_TR_NOOP("GrblSetting", "Homing switch pull-off distance"), "deg"},
      {30, FB_TR_NOOP("GrblSetting", "Maximum spindle speed (largest S value)"), "S"},
      {31, FB_TR_NOOP("GrblSetting", "Minimum spindle speed (smallest S value)"), "S"},
      {32, FB_TR_NOOP("GrblSetting", "Laser mode (on/off)"), ""},
      {100, FB_TR_NOOP("GrblSetting", "Motor 1 (X) steps per degree"), "steps/deg"},
      {101, FB_TR_NOOP("GrblSetting", "Motor 2 (Y) steps per degree"), "steps/deg"},
      {102, FB_TR_NOOP("GrblSetting", "Z steps per mm"), "steps/mm"},
      {110, FB_TR_NOOP("GrblSetting", "Motor 1 (X) maximum rate"), "deg/min"},
      {111, FB_TR_NOOP("GrblSetting", "Motor 2 (Y) maximum rate"), "deg/min"},
      {112, FB_TR_NOOP("GrblSetting", "Z maximum rate"), "mm/min"},
      {120, FB_TR_NOOP("GrblSetting", "Motor 1 (X) acceleration"), "deg/s^2"},
      {121, FB_TR_NOOP("GrblSetting", "Motor 2 (Y) acceleration"), "deg/s^2"},
      {122, FB_TR_NOOP("GrblSetting", "Z acceleration"), "mm/s^2"},
      {130, FB_TR_NOOP("GrblSetting", "Motor 1 (X) maximum travel"), "deg"},
      {131, FB_TR_NOOP("GrblSetting", "Motor 2 (Y) maximum travel"), "deg"},
      {132, FB_TR_NOOP("GrblSetting", "Z maximum travel"), "mm"},
  };
  return table;
}

const GrblSettingInfo* grblSettingInfo(int id) {
  const auto& t = grblSettingTable();
  const auto it = std::lower_bound(t.begin(), t.end(), id, [](const GrblSettingInfo& s, int v) { return s.id < v; });
  return it != t.end() && it->id == id ? &*it : nullptr;
}

}  // namespace fivebar
