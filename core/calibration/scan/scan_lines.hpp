// SPDX-License-Identifier: GPL-3.0-or-later
// Hoang's accuracy lines (accuracy_pattern.hpp) measured in a scanned sheet (PNG/JPEG at a known
// dpi), as the marks are by scan.hpp: each line's ends and centre line found in the image with
// Qt's QImage, then its length and straightness by accuracyFigures. Paper frame of the result: mm
// from the image's lower left corner, x right, y up (the sheet may lie turned or mirrored).
// Method: docs/calibration.md "Accuracy lines from a scan".
#pragma once

#include <QImage>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/accuracy_pattern.hpp"
#include "core/support/message.hpp"

namespace fivebar {

struct ScannedLine {
  Vec2 startMm = Vec2::Zero();   // ends of the pen's centre path (the round caps taken off)
  Vec2 endMm = Vec2::Zero();
  std::vector<Vec2> centreMm;    // the stroke's centre, about every kLineSampleMm between its ends
  double penWidthMm = 0.0;       // the stroke's width as found
  // start, the centre samples, end: the input of accuracyFigures.
  std::vector<Vec2> pointsMm() const;
};

struct LineScanOutcome {
  std::vector<ScannedLine> lines;           // across the sheet (see scanAccuracyLines)
  std::optional<AccuracyFigures> figures;   // of `lines` against the nominal length
  double directionDeg = 0.0;                // of the lines in the image, (-90, 90], y up
  Message error;                            // names the file and what is wrong; empty when ok
  bool ok() const { return error.empty(); }
};

// Centre samples of a line are this far apart (mm).
inline constexpr double kLineSampleMm = 1.0;

// The `expectedLines` strokes of about `nominalLengthMm` (between 0.6 and 1.4 times, thinner than
// kScanMaxPenMm) found in the image, numbered across the sheet: by their offset along the lines'
// common normal, the normal pointing up the image (left for vertical lines). Other ink (marks,
// numbers) is ignored. Every line is oriented the same way (start to end along the direction).
LineScanOutcome scanAccuracyLines(const QImage& image, double dpi, const std::string& source,
                                  int expectedLines = kAccuracyLineCount,
                                  double nominalLengthMm = kAccuracyLineLengthMm);
// Reads the image (any format Qt reads) then scanAccuracyLines.
LineScanOutcome scanAccuracyLinesFile(const std::string& path, double dpi,
                                      int expectedLines = kAccuracyLineCount,
                                      double nominalLengthMm = kAccuracyLineLengthMm);

}  // namespace fivebar
