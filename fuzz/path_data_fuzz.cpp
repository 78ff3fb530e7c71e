// SPDX-License-Identifier: GPL-3.0-or-later
// SVG path data ("d"): parsing into absolute commands, arcs as cubics, and the split that keeps
// Qt SVG under its 32,767-element limit. Asserts: the parse starts with a moveto or says where
// it stopped; each split part is itself valid path data within the element budget, and
// the parts together hold the same drawing commands (a closepath of an earlier part may become
// a lineto, moves start each part).
#include <QString>

#include <cmath>
#include <cstdint>

#include "core/import/path_data.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar::svg;
  const QString d = QString::fromUtf8(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  const ParsedPath parsed = parsePathData(d);
  FUZZ_CHECK(parsed.errorOffset >= 0 && parsed.errorOffset <= d.size(), "error offset outside the text");
  if (parsed.commands.empty()) return 0;
  FUZZ_CHECK(parsed.commands.front().op == 'M', "the first command is not a moveto");
  for (const PathCommand& c : parsed.commands) {
    FUZZ_CHECK(c.op == 'M' || c.op == 'L' || c.op == 'C' || c.op == 'Q' || c.op == 'A' || c.op == 'Z',
               std::string("an unexpected op ") + c.op);
  }
  const std::vector<PathCommand> cubics = arcsAsCubics(parsed.commands);
  for (const PathCommand& c : cubics) FUZZ_CHECK(c.op != 'A', "an arc left after arcsAsCubics");
  if (parsed.commands.size() > 5000) return 0;  // the split's cost is not what is fuzzed
  constexpr int kBudget = 64;
  std::size_t drawn = 0;
  for (const PathCommand& c : parsed.commands) drawn += (c.op != 'M' && c.op != 'Z') ? 1 : 0;
  std::size_t drawnInParts = 0;
  for (const QString& part : splitPathData(parsed.commands, kBudget)) {
    const ParsedPath again = parsePathData(part);
    FUZZ_CHECK(!again.error, "a split part does not parse: " + part.left(200).toStdString());
    int elements = 0;
    for (const PathCommand& c : again.commands) {
      elements += qtElementEstimate(c);
      drawnInParts += (c.op != 'M' && c.op != 'Z') ? 1 : 0;
    }
    // A single command larger than the budget stays whole (an arc of up to 12 elements).
    FUZZ_CHECK(elements <= kBudget + 12, "a split part over the element budget");
  }
  FUZZ_CHECK(drawnInParts >= drawn, "the split lost drawing commands");
  return 0;
}
