// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed-point decimal text of doubles, as printf("%.*f") writes it but never "-0.000": the numbers
// of the G-code. writeFixedDecimal is the allocation-free fast path (exact rounding, ties to even
// on the exact value, as printf and std::to_chars round); fixedDecimal covers every value.
#pragma once

#include <cstddef>
#include <string>

namespace fivebar {

// Room writeFixedDecimal needs at its output: sign, 16 integer digits, '.', 9 decimals, and
// slack for its fixed-size copy.
inline constexpr std::size_t kFixedDecimalRoom = 32;

// The text of `value` with `decimals` decimals (any double, any decimals >= 0).
std::string fixedDecimal(double value, int decimals);

// The same text written at `out` (kFixedDecimalRoom bytes of room); returns its end, or nullptr
// when the fast path does not apply (more than 9 decimals, |value| too large, NaN, infinity):
// then use fixedDecimal.
char* writeFixedDecimal(double value, int decimals, char* out);

}  // namespace fivebar
