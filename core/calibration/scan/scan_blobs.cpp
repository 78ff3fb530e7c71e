// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/scan/scan_blobs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace fivebar::scan {
namespace {

// Ring acceptance: outer size within this share of the expected (plus the pen), squareness and
// hollowness (ink over bounding box) limits.
constexpr double kRingSizeShare = 0.15;
constexpr double kRingSquareness = 0.2;
constexpr double kRingMaxFill = 0.5;
// A dot: smaller than this share of the ring, its centre within this share of the ring's radius.
constexpr double kDotMaxShare = 1.0 / 3.0;
constexpr double kDotCentreShare = 0.5;
// Pixels around a dot's box included in its grey-weighted centre.
constexpr int kDotMarginPx = 2;
// Ink weight starts this share of the paper-ink contrast below the paper level (keeps the paper's
// noise out of the centre).
constexpr double kWeightFloorShare = 0.1;

struct Run {
  int y, x0, x1, label;
};

int findRoot(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) {
    parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    i = parent[static_cast<size_t>(i)];
  }
  return i;
}

}  // namespace

Levels levelsOf(const QImage& grey) {
  std::array<double, 256> hist{};
  for (int y = 0; y < grey.height(); ++y) {
    const uchar* row = grey.constScanLine(y);
    for (int x = 0; x < grey.width(); ++x) hist[row[x]] += 1.0;
  }
  const double total = std::accumulate(hist.begin(), hist.end(), 0.0);
  double sumAll = 0.0;
  for (int i = 0; i < 256; ++i) sumAll += i * hist[static_cast<size_t>(i)];
  Levels l;
  l.paper = l.ink = total > 0.0 ? sumAll / total : 255.0;  // one grey level: no contrast at all
  double wB = 0.0, sumB = 0.0, bestVar = -1.0;
  for (int t = 0; t < 255; ++t) {
    wB += hist[static_cast<size_t>(t)];
    sumB += t * hist[static_cast<size_t>(t)];
    const double wF = total - wB;
    if (wB <= 0.0 || wF <= 0.0) continue;
    const double mB = sumB / wB, mF = (sumAll - sumB) / wF;
    const double var = wB * wF * (mB - mF) * (mB - mF);
    if (var > bestVar) {
      bestVar = var;
      l.threshold = t;
      l.ink = mB;
      l.paper = mF;
    }
  }
  return l;
}

std::vector<Blob> darkBlobs(const QImage& grey, const Levels& levels) {
  std::vector<Run> runs;
  std::vector<int> parent;
  size_t prevBegin = 0, prevEnd = 0;
  for (int y = 0; y < grey.height(); ++y) {
    const uchar* row = grey.constScanLine(y);
    const size_t curBegin = runs.size();
    for (int x = 0; x < grey.width();) {
      if (row[x] > levels.threshold) { ++x; continue; }
      const int x0 = x;
      while (x < grey.width() && row[x] <= levels.threshold) ++x;
      const int label = static_cast<int>(parent.size());
      parent.push_back(label);
      runs.push_back({y, x0, x - 1, label});
    }
    // Join with the previous row's runs that touch (8-connected): both lists are sorted by x.
    size_t p = prevBegin;
    for (size_t c = curBegin; c < runs.size(); ++c) {
      while (p < prevEnd && runs[p].x1 < runs[c].x0 - 1) ++p;
      for (size_t q = p; q < prevEnd && runs[q].x0 <= runs[c].x1 + 1; ++q) {
        const int a = findRoot(parent, runs[q].label), b = findRoot(parent, runs[c].label);
        if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
      }
    }
    prevBegin = curBegin;
    prevEnd = runs.size();
  }
  std::vector<int> blobOf(parent.size(), -1);
  std::vector<Blob> blobs;
  std::vector<Vec2> sums;
  std::vector<std::array<double, 3>> moments;  // raw sums of x^2, x y, y^2 (pixel centres)
  for (const Run& r : runs) {
    const int root = findRoot(parent, r.label);
    int& b = blobOf[static_cast<size_t>(root)];
    if (b < 0) {
      b = static_cast<int>(blobs.size());
      blobs.push_back({0, r.x0, r.y, r.x1, r.y, Vec2::Zero()});
      sums.push_back(Vec2::Zero());
      moments.push_back({0.0, 0.0, 0.0});
    }
    Blob& blob = blobs[static_cast<size_t>(b)];
    const int n = r.x1 - r.x0 + 1;
    blob.area += n;
    blob.x0 = std::min(blob.x0, r.x0);
    blob.x1 = std::max(blob.x1, r.x1);
    blob.y0 = std::min(blob.y0, r.y);
    blob.y1 = std::max(blob.y1, r.y);
    const double sx = n * (0.5 * (r.x0 + r.x1) + 0.5), yc = r.y + 0.5;
    sums[static_cast<size_t>(b)] += Vec2(sx, n * yc);
    // Sum over the run of (k + 0.5)^2 = sum k^2 + sum k + n / 4.
    const auto sumSq = [](double m) { return m * (m + 1.0) * (2.0 * m + 1.0) / 6.0; };
    const double sk = 0.5 * n * (r.x0 + r.x1);
    auto& mo = moments[static_cast<size_t>(b)];
    mo[0] += sumSq(r.x1) - sumSq(r.x0 - 1.0) + sk + 0.25 * n;
    mo[1] += sx * yc;
    mo[2] += n * yc * yc;
  }
  for (size_t i = 0; i < blobs.size(); ++i) {
    Blob& blob = blobs[i];
    blob.centroidPx = sums[i] / blob.area;
    const double a = blob.area;
    blob.sxx = moments[i][0] - a * blob.centroidPx.x() * blob.centroidPx.x();
    blob.sxy = moments[i][1] - a * blob.centroidPx.x() * blob.centroidPx.y();
    blob.syy = moments[i][2] - a * blob.centroidPx.y() * blob.centroidPx.y();
  }
  return blobs;
}

namespace {

bool ringLike(const Blob& b, double minSize, double maxSize) {
  const double w = b.width(), h = b.height();
  if (w < minSize || h < minSize || w > maxSize || h > maxSize) return false;
  if (std::abs(w - h) > kRingSquareness * std::max(w, h)) return false;
  return b.area < kRingMaxFill * w * h;
}

// Grey-weighted centre of a dot: ink weight of every pixel in its box and a small margin.
Vec2 weightedCentre(const QImage& grey, const Levels& levels, const Blob& dot) {
  const double floor = levels.paper - kWeightFloorShare * (levels.paper - levels.ink);
  const int x0 = std::max(0, dot.x0 - kDotMarginPx), x1 = std::min(grey.width() - 1, dot.x1 + kDotMarginPx);
  const int y0 = std::max(0, dot.y0 - kDotMarginPx), y1 = std::min(grey.height() - 1, dot.y1 + kDotMarginPx);
  double sw = 0.0;
  Vec2 s = Vec2::Zero();
  for (int y = y0; y <= y1; ++y) {
    const uchar* row = grey.constScanLine(y);
    for (int x = x0; x <= x1; ++x) {
      const double w = std::max(0.0, floor - row[x]);
      sw += w;
      s += w * Vec2(x + 0.5, y + 0.5);
    }
  }
  return sw > 0.0 ? Vec2(s / sw) : dot.centroidPx;
}

}  // namespace

std::vector<FoundMark> findMarks(const QImage& grey, const Levels& levels, const std::vector<Blob>& blobs,
                                 double ringDiameterPx, double maxPenPx) {
  const double minSize = (1.0 - kRingSizeShare) * ringDiameterPx;
  const double maxSize = (1.0 + kRingSizeShare) * ringDiameterPx + maxPenPx;
  std::vector<FoundMark> out;
  for (const Blob& ring : blobs) {
    if (!ringLike(ring, minSize, maxSize)) continue;
    const double size = 0.5 * (ring.width() + ring.height());
    const Vec2 centre(0.5 * (ring.x0 + ring.x1 + 1), 0.5 * (ring.y0 + ring.y1 + 1));
    const Blob* dot = nullptr;
    for (const Blob& b : blobs) {
      if (&b == &ring || std::max(b.width(), b.height()) > kDotMaxShare * size) continue;
      if ((b.centroidPx - centre).norm() > kDotCentreShare * 0.5 * size) continue;
      if (!dot || b.area > dot->area) dot = &b;
    }
    if (!dot) continue;
    out.push_back({weightedCentre(grey, levels, *dot), centre, size});
  }
  return out;
}

double typicalRingSizePx(const std::vector<Blob>& blobs, double minSizePx) {
  std::vector<double> sizes;
  for (const Blob& b : blobs)
    if (ringLike(b, minSizePx, 1e9)) sizes.push_back(0.5 * (b.width() + b.height()));
  if (sizes.empty()) return 0.0;
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

}  // namespace fivebar::scan
