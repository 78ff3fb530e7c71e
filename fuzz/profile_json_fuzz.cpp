// SPDX-License-Identifier: GPL-3.0-or-later
// Machine profile JSON (`--machine FILE`, the studio's profile files, the profile inside a
// project). Asserts: a refusal has issues naming a field or the file; an accepted profile passes
// validation and survives a round trip (written, read again: the same JSON).
#include <cstdint>
#include <string>

#include "core/machine/profile.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar;
  const std::string text(fuzz::asText(data, size));
  const ProfileLoad load = profileFromJson(text, "fuzz.json");
  if (!load.profile) {
    FUZZ_CHECK(!load.issues.empty(), "a refused profile without an issue");
    for (const ValidationIssue& issue : load.issues)
      FUZZ_CHECK(!issue.field.empty() || fuzz::namesSource(issue.message.text(), "fuzz.json"),
                 "an issue naming neither a field nor the file: " + issue.message.text());
    return 0;
  }
  FUZZ_CHECK(validate(*load.profile).empty(), "an accepted profile that does not validate");
  const std::string written = toJson(*load.profile);
  const ProfileLoad again = profileFromJson(written, "again.json");
  FUZZ_CHECK(again.profile.has_value(), "a written profile that does not read back: " +
                                            (again.issues.empty() ? std::string() : again.issues.front().message.text()));
  FUZZ_CHECK(toJson(*again.profile) == written, "the round trip changed the profile");
  return 0;
}
