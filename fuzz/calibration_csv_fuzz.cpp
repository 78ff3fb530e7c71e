// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration's files: MARKS.csv, MEASURED.csv, the measurement files of either form
// (marks or ruler distances) and the mark poses. The first byte chooses the reader, so that the
// fuzzer learns each format's header. Asserts: an error names the file and a line ("FILE:N:");
// what is read back is finite.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/calibration/marks_csv.hpp"
#include "core/calibration/measurements.hpp"
#include "fuzz_check.hpp"

namespace {
void checkError(const fivebar::Message& error) {
  if (error.empty()) return;
  const std::string text = error.text();
  FUZZ_CHECK(fivebar::fuzz::namesSource(text, "fuzz.csv"), text);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fivebar;
  if (size == 0) return 0;
  const std::string text(fuzz::asText(data + 1, size - 1));
  switch (data[0] % 4) {
    case 0: {
      const MarksLoad load = parseMarksCsv(text, "fuzz.csv");
      checkError(load.error);
      for (const MarkRecord& m : load.marks) FUZZ_CHECK(std::isfinite(m.ringRadiusMm), "ring radius not finite");
      break;
    }
    case 1: {
      const MeasuredLoad load = parseMeasuredCsv(text, "fuzz.csv");
      checkError(load.error);
      for (const MeasuredMark& m : load.marks)
        FUZZ_CHECK(std::isfinite(m.theta1Deg) && std::isfinite(m.theta2Deg) && m.measuredMm.allFinite(),
                   "a measured mark not finite");
      break;
    }
    case 2: checkError(calibration::readMeasurements(text, "fuzz.csv").error); break;
    default: checkError(calibration::readMarkPoses(text, "fuzz.csv").error); break;
  }
  return 0;
}
