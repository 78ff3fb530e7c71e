// SPDX-License-Identifier: GPL-3.0-or-later
// What a board sends: every received line through the response parser (parseLine, which also
// parses status reports), and the status body alone. Asserts: the raw text is kept; a status
// line parses as a status exactly when its body does; codes and overrides are what GRBL can send.
#include <cmath>
#include <cstdint>
#include <string>

#include "drivers/protocol/grbl_parser.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar::grbl;
  std::string_view rest = fivebar::fuzz::asText(data, size);
  while (!rest.empty()) {
    const std::size_t end = rest.find_first_of("\r\n");
    const std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
    const ParsedLine parsed = parseLine(line);
    FUZZ_CHECK(parsed.raw.size() <= line.size(), "raw text longer than the line");
    if (parsed.kind == LineKind::Status) {
      const auto& s = parsed.status;
      if (s.mpos) FUZZ_CHECK(std::isfinite(s.mpos->x()) && std::isfinite(s.mpos->y()), "MPos not finite");
      if (s.wpos) FUZZ_CHECK(std::isfinite(s.wpos->x()) && std::isfinite(s.wpos->y()), "WPos not finite");
      if (s.overrides)
        for (int v : *s.overrides) FUZZ_CHECK(v >= 0, "a negative override");
    }
    if (line.size() >= 2 && line.front() == '<' && line.back() == '>') {
      const bool body = parseStatus(line.substr(1, line.size() - 2)).has_value();
      FUZZ_CHECK(body == (parsed.kind == LineKind::Status), "status line and body disagree");
    }
  }
  (void)parseStatus(fivebar::fuzz::asText(data, size));
  (void)parseAxes(fivebar::fuzz::asText(data, size));
  return 0;
}
