// SPDX-License-Identifier: GPL-3.0-or-later
// Fixed-point decimal text of doubles for G-code, exact and fast. Contract: fixed_decimal.hpp.
#include "core/output/fixed_decimal.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace fivebar {
namespace {

constexpr int kFastMaxDecimals = 9;
constexpr double kPow10[kFastMaxDecimals + 1] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr std::uint64_t kPow10Int[kFastMaxDecimals + 1] = {
    1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};
constexpr double kTwoPow52 = 4503599627370496.0;  // below it, doubles have a fractional bit

// round(magnitude * 10^decimals) to an integer, ties to even, computed on the EXACT product (what
// printf and std::to_chars round). With p = fl(m * s) < 2^52, floor(p) and f = p - floor(p) are
// exact; the rounding error e = m * s - p (exact by fma, s being an exact power of ten) has
// |e| <= ulp(p) / 2. For p >= 1/2, f and 1/2 lie on p's ulp grid, so the sign of f - 1/2 decides
// unless f == 1/2, where e decides, and e == 0 is a true tie (to even); for p < 1/2, p + e < 1/2.
// Returns false when the fast path does not apply (too large, not finite).
bool roundScaled(double magnitude, int decimals, std::uint64_t& rounded) {
  const double scale = kPow10[decimals];
  const double p = magnitude * scale;
  if (!(p < kTwoPow52)) return false;  // also NaN and infinity
  rounded = static_cast<std::uint64_t>(p);  // floor: p >= 0
  const double aboveHalf = (p - static_cast<double>(rounded)) - 0.5;
  rounded += aboveHalf > 0.0 ? 1 : 0;  // no branch: up or down is a coin toss
  if (aboveHalf == 0.0) {  // rare: the sign of the product's rounding error decides
    const double e = std::fma(magnitude, scale, -p);
    if (e > 0.0 || (e == 0.0 && (rounded & 1U) != 0)) ++rounded;
  }
  return true;
}

// "00" .. "99": two digits per step.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Writes the digits of v backwards so that they end at q; returns their start. At least one
// digit; exactly `Count` digits (leading zeros) when Count > 0.
template <int Count>
char* digitsBackward(char* q, std::uint64_t v) {
  auto pair = [&](std::uint64_t two) {
    q -= 2;
    std::memcpy(q, kDigitPairs + 2 * two, 2);
  };
  if constexpr (Count > 0) {
    for (int i = 0; i + 1 < Count; i += 2) {
      pair(v % 100);
      v /= 100;
    }
    if constexpr (Count % 2 == 1) *--q = static_cast<char>('0' + v);
  } else {
    for (; v >= 100; v /= 100) pair(v % 100);
    if (v >= 10) pair(v);
    else *--q = static_cast<char>('0' + v);
  }
  return q;
}

// Writes n = round(|value| * 10^Decimals) as "[-]int.frac" at `out` (kFixedDecimalRoom bytes of room);
// returns the end. Decimals is a template argument so that the divisions are multiplications;
// the integer and fraction digits are two independent chains.
template <int Decimals>
char* writeScaled(std::uint64_t n, bool negative, char* out) {
  constexpr std::uint64_t kScale = kPow10Int[Decimals];
  char digits[2 * kFixedDecimalRoom];  // written backwards to end at digits + kFixedDecimalRoom
  char* const end = digits + kFixedDecimalRoom;
  char* q = end;
  if constexpr (Decimals > 0) {
    q = digitsBackward<Decimals>(q, n % kScale);
    *--q = '.';
  }
  q = digitsBackward<0>(q, n / kScale);
  if (negative && n != 0) *--q = '-';  // "-0.000" is written "0.000"
  std::memcpy(out, q, kFixedDecimalRoom);     // fixed size: two vector moves; bytes past `end` unused
  return out + (end - q);
}

}  // namespace

// std::to_chars gives printf's digits without locale; only "-0.000" is changed.
std::string fixedDecimal(double value, int decimals) {
  char buf[64];
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  std::string s;
  if (r.ec == std::errc{}) {
    s.assign(buf, r.ptr);
  } else {  // too long for the buffer (|value| near 1e60 or more): let snprintf size it
    s.resize(static_cast<size_t>(std::snprintf(nullptr, 0, "%.*f", decimals, value)) + 1);
    s.resize(static_cast<size_t>(std::snprintf(s.data(), s.size(), "%.*f", decimals, value)));
  }
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

// The fast path of fixedDecimal: nullptr when decimals are outside 0..9, |value| * 10^decimals
// >= 2^52 or value is not finite.
char* writeFixedDecimal(double value, int decimals, char* out) {
  std::uint64_t n = 0;
  if (decimals < 0 || decimals > kFastMaxDecimals || !roundScaled(std::abs(value), decimals, n))
    return nullptr;
  const bool negative = std::signbit(value);
  switch (decimals) {
    case 0: return writeScaled<0>(n, negative, out);
    case 1: return writeScaled<1>(n, negative, out);
    case 2: return writeScaled<2>(n, negative, out);
    case 3: return writeScaled<3>(n, negative, out);
    case 4: return writeScaled<4>(n, negative, out);
    case 5: return writeScaled<5>(n, negative, out);
    case 6: return writeScaled<6>(n, negative, out);
    case 7: return writeScaled<7>(n, negative, out);
    case 8: return writeScaled<8>(n, negative, out);
    default: return writeScaled<9>(n, negative, out);
  }
}

}  // namespace fivebar
