// SPDX-License-Identifier: GPL-3.0-or-later
// What every harness asserts beyond "no crash": a property of the parser's answer that could
// fail. FUZZ_CHECK prints the broken property and aborts, which libFuzzer (and the replay
// driver) report as a finding with the input that caused it (docs/reliability.md).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#define FUZZ_CHECK(cond, what)                                                     \
  do {                                                                             \
    if (!(cond)) {                                                                 \
      std::fprintf(stderr, "fuzz check failed: %s (%s:%d): %s\n", #cond, __FILE__, \
                   __LINE__, std::string(what).c_str());                           \
      std::abort();                                                                \
    }                                                                              \
  } while (0)

namespace fivebar::fuzz {

inline std::string_view asText(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A refusal names the file: the message starts with (or contains) the source name.
inline bool namesSource(const std::string& message, std::string_view source) {
  return message.find(source) != std::string::npos;
}

}  // namespace fivebar::fuzz
