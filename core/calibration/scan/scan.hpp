// SPDX-License-Identifier: GPL-3.0-or-later
// `fivebar calibrate scan`: the calibration pattern's marks found in a scanned sheet (PNG/JPEG at
// a known dpi) and numbered by matching the pattern. The paper frame of the result: mm from the
// image's lower left corner, x right, y up (the sheet may lie turned or mirrored in it).
// Algorithm and the choice of Qt's QImage: docs/calibration-pattern.md "Scan".
#pragma once

#include <QImage>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/marks_csv.hpp"
#include "core/calibration/scan/scan_blobs.hpp"
#include "core/support/message.hpp"

namespace fivebar {

inline constexpr double kMmPerInch = 25.4;
// Widest pen line the ring test allows for (mm).
inline constexpr double kScanMaxPenMm = 1.5;

struct ScanOutcome {
  std::vector<MeasuredMark> measured;  // every matched mark, ordered by id
  std::vector<int> missingIds;         // pattern marks not found
  int foundMarks = 0;                  // rings with a dot found in the image
  bool mirrored = false;               // the sheet lies mirrored in the image
  double rotationDeg = 0.0;            // of the sheet in the image
  double rmsMm = 0.0;                  // rigid-placement residual against the nominal marks
  Message error;                       // names the file and what is wrong; empty when ok (translatable)
  bool ok() const { return error.empty(); }
};

ScanOutcome scanImage(const QImage& image, double dpi, const std::vector<MarkRecord>& marks,
                      const std::string& source);

namespace scan {
// "SOURCE: what is wrong", the form of every scan problem.
Message sourced(const std::string& source, Message m);
// A scan ready to be read (marks or accuracy lines): the image in 8-bit grey with its paper and
// ink levels, or the problem, named with `source`, when the dpi is not a positive number, the
// image is empty or it has almost no contrast.
struct ReadyImage {
  QImage grey;
  Levels levels;
  std::optional<Message> problem;
};
ReadyImage readyImage(const QImage& image, double dpi, const std::string& source);
}  // namespace scan
// Reads the image (any format Qt reads: PNG, JPEG, ...) then scanImage.
ScanOutcome scanFile(const std::string& path, double dpi, const std::vector<MarkRecord>& marks);

}  // namespace fivebar
