// SPDX-License-Identifier: GPL-3.0-or-later
#include "overrides.hpp"

#include <algorithm>

namespace fivebar::grbl {

char overrideByte(OverrideCommand command) { return char(0x90 + int(command)); }

std::optional<OverrideCommand> overrideCommandOf(char byte) {
  const int u = static_cast<unsigned char>(byte);
  if (u < 0x90 || u > 0x97) return std::nullopt;
  return OverrideCommand(u - 0x90);
}

MotionOverrides OverrideFlags::applyTo(MotionOverrides current) const {
  using C = OverrideCommand;
  // protocol.c works on a uint8_t: 10 - 10 = 0 is clamped back to 10 (no wrap below 0 is
  // reachable from 10..200 with at most one step of each kind).
  int feed = current.feedPct;
  if (has(C::FeedReset)) feed = kDefaultOverridePct;
  if (has(C::FeedPlus10)) feed += kFeedOverrideCoarsePct;
  if (has(C::FeedMinus10)) feed -= kFeedOverrideCoarsePct;
  if (has(C::FeedPlus1)) feed += kFeedOverrideFinePct;
  if (has(C::FeedMinus1)) feed -= kFeedOverrideFinePct;
  feed = std::clamp(feed, kFeedOverrideMinPct, kFeedOverrideMaxPct);
  int rapid = current.rapidPct;
  if (has(C::RapidFull)) rapid = kDefaultOverridePct;
  if (has(C::RapidHalf)) rapid = kRapidOverrideMediumPct;
  if (has(C::RapidQuarter)) rapid = kRapidOverrideLowPct;
  return {feed, rapid};
}

}  // namespace fivebar::grbl
