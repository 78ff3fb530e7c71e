// SPDX-License-Identifier: GPL-3.0-or-later
// The image half of the scan: dark connected components of a greyscale image (run-length
// labelling, so an A4 page at 600 dpi needs memory for its ink only), and the marks among them:
// a ring of the pattern's size with a small dot at its centre. Pixel frame: x right, y down,
// pixel (i, j) covers [i, i + 1) x [j, j + 1).
#pragma once

#include <QImage>
#include <vector>

#include "core/kinematics/geometry.hpp"

namespace fivebar::scan {

struct Blob {
  int area = 0;                          // pixels
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;    // bounding box, inclusive
  Vec2 centroidPx = Vec2::Zero();        // of the pixels (centres at +0.5)
  double sxx = 0.0, sxy = 0.0, syy = 0.0;  // central second moments of the pixels (sums, px^2)
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};

// Grey levels of the paper and the ink (Otsu's threshold splits the histogram; the means of the
// two classes), from an 8-bit greyscale image.
struct Levels {
  int threshold = 128;  // a pixel is ink when <= threshold
  double paper = 255.0;
  double ink = 0.0;
};
Levels levelsOf(const QImage& grey);

// Dark components (8-connected) of `grey` at `levels.threshold`.
std::vector<Blob> darkBlobs(const QImage& grey, const Levels& levels);

// A found mark: its dot's centre (grey-weighted, pixels) and the ring around it.
struct FoundMark {
  Vec2 dotPx = Vec2::Zero();
  Vec2 ringCentrePx = Vec2::Zero();
  double ringDiameterPx = 0.0;
};
// Rings whose outer size is ringDiameterPx (within the pen's width and 15 %) with a dot (a blob
// smaller than a third of the ring) near their centre.
std::vector<FoundMark> findMarks(const QImage& grey, const Levels& levels, const std::vector<Blob>& blobs,
                                 double ringDiameterPx, double maxPenPx);

// Median outer size (px) of the ring-like blobs (round, hollow) of at least minSizePx, or 0: the
// hint when no mark of the expected size is found (a wrong dpi).
double typicalRingSizePx(const std::vector<Blob>& blobs, double minSizePx);

}  // namespace fivebar::scan
