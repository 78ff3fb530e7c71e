// SPDX-License-Identifier: GPL-3.0-or-later
// The progress file a resume reads (JOB.gcode.progress). Asserts: a refusal says why, naming the
// file; an accepted record survives a round trip.
#include <cstdint>
#include <string>

#include "drivers/stream/job_progress.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar::stream;
  const std::string text(fivebar::fuzz::asText(data, size));
  std::string error;
  const auto progress = progressFromJson(text, "fuzz.progress", &error);
  if (!progress) {
    FUZZ_CHECK(fivebar::fuzz::namesSource(error, "fuzz.progress"), error);
    return 0;
  }
  const std::string written = toJson(*progress);
  std::string again;
  const auto back = progressFromJson(written, "again.progress", &again);
  FUZZ_CHECK(back.has_value(), "a written progress record that does not read back: " + again);
  FUZZ_CHECK(toJson(*back) == written, "the round trip changed the progress record");
  return 0;
}
