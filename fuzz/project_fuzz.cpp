// SPDX-License-Identifier: GPL-3.0-or-later
// Project files (.fivebar: versioned JSON with the drawing's SVG, placement, layers, mode,
// tolerance and profile). Asserts as for profiles: refusals name a field or the file; an
// accepted project survives a round trip.
#include <cstdint>
#include <string>

#include "core/project/project.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar;
  const std::string text(fuzz::asText(data, size));
  const ProjectLoad load = projectFromJson(text, "fuzz.fivebar");
  if (!load.project) {
    FUZZ_CHECK(!load.issues.empty(), "a refused project without an issue");
    for (const ValidationIssue& issue : load.issues)
      FUZZ_CHECK(!issue.field.empty() || fuzz::namesSource(issue.message.text(), "fuzz.fivebar"),
                 "an issue naming neither a field nor the file: " + issue.message.text());
    return 0;
  }
  const std::string written = projectToJson(*load.project);
  const ProjectLoad again = projectFromJson(written, "again.fivebar");
  FUZZ_CHECK(again.project.has_value(), "a written project that does not read back: " +
                                            (again.issues.empty() ? std::string() : again.issues.front().message.text()));
  FUZZ_CHECK(projectToJson(*again.project) == written, "the round trip changed the project");
  (void)planOptionsOf(*again.project);
  return 0;
}
