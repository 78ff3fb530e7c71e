// SPDX-License-Identifier: GPL-3.0-or-later
// GRBL 1.1h feed and rapid overrides: the real-time bytes (0x90-0x97) and what the firmware does
// with them (protocol.c protocol_exec_rt_system, "Execute overrides"). Pure values, no I/O.
//  - feed override: 100 % at reset, +-10 % (0x91 / 0x92), +-1 % (0x93 / 0x94), reset to 100 %
//    (0x90); clamped to 10..200 % (config.h MIN/MAX_FEED_RATE_OVERRIDE). It scales G1/G2/G3
//    moves, never G0, jogs ($J=), homing or probing.
//  - rapid override: 100 / 50 / 25 % (0x95 / 0x96 / 0x97); it scales G0 only.
//  - the overridden rate of a block is capped at its rapid rate, the highest speed the axes'
//    $110/$111/$112 allow along it (planner.c plan_compute_profile_nominal_speed): a feed
//    override of 200 % never drives a motor past its maximum rate, and accelerations stay at
//    $120-$122, so an override cannot take the machine beyond its motor limits.
//  - M2 / M30 put both back to 100 % (RESTORE_OVERRIDES_AFTER_PROGRAM_END), as does a reset.
// The board reports them in the Ov: field of a status report (feed, rapid, spindle %): on the
// report after a change, else on every 10th (idle) / 20th (busy) report.
#pragma once

#include <cstdint>
#include <optional>

namespace fivebar::grbl {

inline constexpr int kDefaultOverridePct = 100;
inline constexpr int kFeedOverrideMinPct = 10;   // config.h MIN_FEED_RATE_OVERRIDE
inline constexpr int kFeedOverrideMaxPct = 200;  // config.h MAX_FEED_RATE_OVERRIDE
inline constexpr int kFeedOverrideCoarsePct = 10;
inline constexpr int kFeedOverrideFinePct = 1;
inline constexpr int kRapidOverrideMediumPct = 50;  // config.h RAPID_OVERRIDE_MEDIUM
inline constexpr int kRapidOverrideLowPct = 25;     // config.h RAPID_OVERRIDE_LOW

enum class OverrideCommand {
  FeedReset,     // 0x90: feed 100 %
  FeedPlus10,    // 0x91
  FeedMinus10,   // 0x92
  FeedPlus1,     // 0x93
  FeedMinus1,    // 0x94
  RapidFull,     // 0x95: rapid 100 %
  RapidHalf,     // 0x96: rapid 50 %
  RapidQuarter,  // 0x97: rapid 25 %
};

// The real-time byte GRBL 1.1h takes for the command.
char overrideByte(OverrideCommand command);
// The command of a real-time byte 0x90-0x97; nullopt for any other byte.
std::optional<OverrideCommand> overrideCommandOf(char byte);

// Feed and rapid override as a board holds them (percent).
struct MotionOverrides {
  int feedPct = kDefaultOverridePct;
  int rapidPct = kDefaultOverridePct;
  bool operator==(const MotionOverrides&) const = default;
};

// The override commands that arrived since the firmware last ran its real-time check: GRBL
// keeps one flag per command (sys_rt_exec_motion_override), so the same byte twice before the
// check counts once; applyTo() executes the flags in protocol.c's order (reset, coarse +, coarse
// -, fine +, fine -, then the clamp; rapid reset, medium, low).
class OverrideFlags {
 public:
  void add(OverrideCommand command) { bits_ |= std::uint8_t(1u << unsigned(command)); }
  bool empty() const { return bits_ == 0; }
  void clear() { bits_ = 0; }
  MotionOverrides applyTo(MotionOverrides current) const;

 private:
  bool has(OverrideCommand c) const { return (bits_ >> unsigned(c)) & 1u; }
  std::uint8_t bits_ = 0;
};

}  // namespace fivebar::grbl
