// Seeded randomness for tests: the seed is printed, and FIVEBAR_TEST_SEED overrides it.
#pragma once

#include <cstdint>
#include <random>

namespace fivebar::test {

std::uint64_t seed();  // printed once at start; set with FIVEBAR_TEST_SEED=<n>
inline std::mt19937_64 rng() { return std::mt19937_64(seed()); }

}  // namespace fivebar::test
