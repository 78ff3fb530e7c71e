// SPDX-License-Identifier: GPL-3.0-or-later
// Seeded randomness for tests: the seed is printed, and FIVEBAR_TEST_SEED overrides it.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

namespace fivebar::test {

// The seed of every random test: printed once by each test main(); FIVEBAR_TEST_SEED=<n> sets it.
inline std::uint64_t seed() {
  static const std::uint64_t s = [] {
    const char* env = std::getenv("FIVEBAR_TEST_SEED");
    return env ? std::stoull(env) : std::uint64_t{20261122};
  }();
  return s;
}
inline std::mt19937_64 rng() { return std::mt19937_64(seed()); }

}  // namespace fivebar::test
