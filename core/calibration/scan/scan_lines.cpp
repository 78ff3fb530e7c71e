// SPDX-License-Identifier: GPL-3.0-or-later
// Accuracy lines in a scan: contract in scan_lines.hpp, method in docs/calibration.md.
#include "core/calibration/scan/scan_lines.hpp"

#include <Eigen/Cholesky>
#include <QImageReader>
#include <algorithm>
#include <cmath>

#include "core/calibration/scan/scan.hpp"
#include "core/calibration/scan/scan_blobs.hpp"

namespace fivebar {
namespace {

// A line candidate is between these shares of the nominal length.
constexpr double kMinLengthShare = 0.6;
constexpr double kMaxLengthShare = 1.4;
// Lines whose direction differs from the median by more than this are not of the pattern (rad).
constexpr double kParallelRad = 10.0 * kPi / 180.0;
// Pixels beyond the stroke's half width taken into the band around it (covers a blur of 2.5 px).
constexpr double kBandMarginPx = 8.0;
// Axial profile: bins (px) and the half width of the tent each pixel is spread with (px; a
// multiple of the bin, so that every pixel deposits the same total weight 1 / kBinPx). Pixels
// along an axis-aligned line lie 1 px apart: narrower bins without the tent would alias.
constexpr double kBinPx = 0.5;
constexpr double kTentPx = 1.0;

struct Sample {
  double t, n, v;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Where the blurred profile of a round cap falls to half its plateau, past the end of the pen's
// centre path (px): the cap's chord across the line, sqrt(1 - (s / R)^2) of the width for
// 0 <= s <= R, integrated across and blurred along the line by a Gaussian of sigma.
double capHalfPointPx(double radiusPx, double sigmaPx) {
  if (!(radiusPx > 0.0)) return 0.0;
  if (!(sigmaPx > 1e-3)) return radiusPx * std::sqrt(3.0) / 2.0;
  const double step = std::min(0.02, radiusPx / 50.0);
  const auto chord = [&](double s) {
    if (s <= 0.0) return 1.0;
    if (s >= radiusPx) return 0.0;
    return std::sqrt(1.0 - (s / radiusPx) * (s / radiusPx));
  };
  const auto blurred = [&](double s) {
    double sum = 0.0, wsum = 0.0;
    for (double u = -4.0 * sigmaPx; u <= 4.0 * sigmaPx; u += step) {
      const double w = std::exp(-0.5 * u * u / (sigmaPx * sigmaPx));
      sum += w * chord(s - u);
      wsum += w;
    }
    return sum / wsum;
  };
  double lo = -4.0 * sigmaPx, hi = radiusPx + 4.0 * sigmaPx;  // blurred(lo) > 1/2 > blurred(hi)
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (blurred(mid) > 0.5 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The first bin position (px, from `from` stepping by `dir`) where the profile reaches `level`,
// interpolated between bin centres; nullopt when it never does.
std::optional<double> crossing(const std::vector<double>& f, double t0, int from, int dir, double level) {
  for (int k = from; k >= 0 && k < static_cast<int>(f.size()); k += dir) {
    if (f[static_cast<size_t>(k)] < level) continue;
    if (k == from) return std::nullopt;  // starts inside the ink: the band is too short
    const double a = f[static_cast<size_t>(k - dir)], b = f[static_cast<size_t>(k)];
    const double u = (level - a) / (b - a);
    return t0 + (k - dir + dir * u + 0.5) * kBinPx;
  }
  return std::nullopt;
}

// One stroke measured around its blob (pixel frame, y down). nullopt when it has no clear ends.
std::optional<ScannedLine> measureLine(const QImage& grey, const scan::Blob& blob, const Vec2& u, double pxPerMm) {
  const Vec2 c = blob.centroidPx;
  const Vec2 nrm(-u.y(), u.x());
  const double varAlong = (u.x() * u.x() * blob.sxx + 2.0 * u.x() * u.y() * blob.sxy + u.y() * u.y() * blob.syy) / blob.area;
  const double halfLen = std::sqrt(3.0 * std::max(varAlong, 1.0));
  const double thick = blob.area / (2.0 * halfLen);
  const double bandHalf = 0.5 * thick + kBandMarginPx;
  const double tMax = halfLen + bandHalf + 4.0;
  // Pixels of the oriented band around the stroke.
  std::vector<Sample> samples;
  const double ex = std::abs(u.x()) * tMax + std::abs(nrm.x()) * bandHalf;
  const double ey = std::abs(u.y()) * tMax + std::abs(nrm.y()) * bandHalf;
  const int x0 = std::max(0, static_cast<int>(std::floor(c.x() - ex))), x1 = std::min(grey.width() - 1, static_cast<int>(std::ceil(c.x() + ex)));
  const int y0 = std::max(0, static_cast<int>(std::floor(c.y() - ey))), y1 = std::min(grey.height() - 1, static_cast<int>(std::ceil(c.y() + ey)));
  std::vector<double> rim;
  for (int y = y0; y <= y1; ++y) {
    const uchar* row = grey.constScanLine(y);
    for (int x = x0; x <= x1; ++x) {
      const Vec2 d = Vec2(x + 0.5, y + 0.5) - c;
      const double t = d.dot(u), n = d.dot(nrm);
      if (std::abs(t) > tMax || std::abs(n) > bandHalf) continue;
      samples.push_back({t, n, static_cast<double>(row[x])});
      if (std::abs(n) > bandHalf - 2.0 || std::abs(t) > tMax - 2.0) rim.push_back(row[x]);
    }
  }
  if (rim.empty()) return std::nullopt;
  const double paper = median(rim);  // the paper around this line
  for (Sample& s : samples) s.v = paper - s.v;
  // Across the middle half: ink per unit length I, centre n0, spread, peak darkness.
  const double mid = 0.5 * halfLen;
  double sumV = 0.0, sumVn = 0.0;
  for (const Sample& s : samples)
    if (std::abs(s.t) <= mid) sumV += s.v, sumVn += s.v * s.n;
  if (!(sumV > 0.0)) return std::nullopt;
  const double n0 = sumVn / sumV;
  const double inkPerPx = sumV / (2.0 * mid);
  double sumVnn = 0.0;
  std::vector<double> binSum(static_cast<size_t>(std::ceil(4.0 * bandHalf)) + 2, 0.0), binCount(binSum.size(), 0.0);
  for (const Sample& s : samples) {
    if (std::abs(s.t) > mid) continue;
    sumVnn += s.v * (s.n - n0) * (s.n - n0);
    const auto b = static_cast<size_t>(std::clamp((s.n + bandHalf) / kBinPx, 0.0, static_cast<double>(binSum.size() - 1)));
    binSum[b] += s.v;
    binCount[b] += 1.0;
  }
  double peak = 0.0;
  for (size_t b = 0; b < binSum.size(); ++b)
    if (binCount[b] >= 3.0) peak = std::max(peak, binSum[b] / binCount[b]);
  if (!(peak > 0.0)) return std::nullopt;
  const double variance = sumVnn / sumV;
  // Width w and blur sigma of a stripe of darkness k: I = k w, variance = w^2 / 12 + sigma^2,
  // peak = k erf(w / (2 sqrt(2) sigma)). Fixed point from k = peak.
  double k = peak, w = inkPerPx / k, sigma = 0.0;
  for (int it = 0; it < 20; ++it) {
    w = inkPerPx / k;
    sigma = std::sqrt(std::max(0.0, variance - w * w / 12.0));
    const double e = sigma > 1e-6 ? std::erf(w / (2.0 * std::sqrt(2.0) * sigma)) : 1.0;
    k = std::clamp(peak / std::max(e, 1e-3), peak, std::max(peak, paper));
  }
  w = inkPerPx / k;
  // Along: ink per unit length, smoothed by the tent (its variance kTentPx^2 / 6 adds to the
  // blur), in bins; its half-plateau points, less the cap's.
  const double tStart = -tMax;
  std::vector<double> f(static_cast<size_t>(std::ceil(2.0 * tMax / kBinPx)) + 1, 0.0);
  for (const Sample& s : samples) {
    const double x = (s.t - tStart) / kBinPx - 0.5;  // in bins, 0 = the first bin's centre
    const auto k0 = static_cast<long>(std::ceil(x - kTentPx / kBinPx));
    const auto k1 = static_cast<long>(std::floor(x + kTentPx / kBinPx));
    for (long bin = std::max(0L, k0); bin <= std::min(k1, static_cast<long>(f.size()) - 1); ++bin)
      f[static_cast<size_t>(bin)] +=
          s.v * std::max(0.0, 1.0 - std::abs(x - static_cast<double>(bin)) * kBinPx / kTentPx);
  }
  const auto a = crossing(f, tStart, 0, +1, 0.5 * inkPerPx);
  const auto b = crossing(f, tStart, static_cast<int>(f.size()) - 1, -1, 0.5 * inkPerPx);
  if (!a || !b || !(*b > *a)) return std::nullopt;
  const double cap = capHalfPointPx(0.5 * w, std::sqrt(sigma * sigma + kTentPx * kTentPx / 6.0));
  const double t0 = *a + cap, t1 = *b - cap;
  if (!(t1 > t0)) return std::nullopt;
  // The centre line: the ink's centre across, in windows kLineSampleMm long clear of the caps.
  const double step = kLineSampleMm * pxPerMm;
  const double clear = 0.5 * w + 2.0 * sigma + 1.0;
  const double nHalf = 0.5 * w + 3.0 * sigma + 1.0;
  const int windows = std::max(1, static_cast<int>(std::floor((t1 - t0 - 2.0 * clear) / step)));
  const double first = 0.5 * (t0 + t1) - 0.5 * windows * step;
  std::vector<double> wSum(static_cast<size_t>(windows), 0.0), wnSum(wSum.size(), 0.0);
  for (const Sample& s : samples) {
    if (std::abs(s.n - n0) > nHalf) continue;
    const double x = (s.t - first) / step;
    if (x < 0.0 || x >= windows) continue;
    const auto i = static_cast<size_t>(x);
    wSum[i] += s.v;
    wnSum[i] += s.v * s.n;
  }
  const auto toPaper = [&](const Vec2& px) { return Vec2(px.x() / pxPerMm, (grey.height() - px.y()) / pxPerMm); };
  ScannedLine line;
  // The ends' offsets across: a parabola n(t) fitted to the centre samples, extrapolated over
  // the caps (a drawn line bends smoothly; the samples stop short of the ends).
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  const double scale = std::max(1.0, 0.5 * (t1 - t0));
  for (int i = 0; i < windows; ++i) {
    if (!(wSum[static_cast<size_t>(i)] > 0.0)) continue;
    const double n = wnSum[static_cast<size_t>(i)] / wSum[static_cast<size_t>(i)];
    const double t = first + (i + 0.5) * step;
    line.centreMm.push_back(toPaper(c + t * u + n * nrm));
    const Eigen::Vector3d row(1.0, t / scale, (t / scale) * (t / scale));
    ata += row * row.transpose();
    atb += row * n;
  }
  double nStart = n0, nEnd = n0;
  if (line.centreMm.size() >= 3) {
    const Eigen::Vector3d coef = ata.ldlt().solve(atb);
    const auto at = [&](double t) { return coef[0] + coef[1] * (t / scale) + coef[2] * (t / scale) * (t / scale); };
    nStart = at(t0);
    nEnd = at(t1);
  }
  line.startMm = toPaper(c + t0 * u + nStart * nrm);
  line.endMm = toPaper(c + t1 * u + nEnd * nrm);
  line.penWidthMm = w / pxPerMm;
  return line;
}

}  // namespace

using scan::sourced;

std::vector<Vec2> ScannedLine::pointsMm() const {
  std::vector<Vec2> p{startMm};
  p.insert(p.end(), centreMm.begin(), centreMm.end());
  p.push_back(endMm);
  return p;
}

LineScanOutcome scanAccuracyLines(const QImage& image, double dpi, const std::string& source, int expectedLines,
                                  double nominalLengthMm) {
  LineScanOutcome out;
  scan::ReadyImage ready = scan::readyImage(image, dpi, source);
  if (ready.problem) {
    out.error = std::move(*ready.problem);
    return out;
  }
  const QImage& grey = ready.grey;
  const scan::Levels& levels = ready.levels;
  const double pxPerMm = dpi / kMmPerInch;
  const double nominalPx = nominalLengthMm * pxPerMm;
  const double maxPenPx = kScanMaxPenMm * pxPerMm + 4.0;  // a blurred pen
  struct Candidate {
    const scan::Blob* blob;
    Vec2 u;
    double angle;  // of u in [0, pi)
  };
  std::vector<Candidate> candidates;
  const std::vector<scan::Blob> blobs = scan::darkBlobs(grey, levels);
  for (const scan::Blob& b : blobs) {
    if (b.area < 10) continue;
    const double sxx = b.sxx / b.area, sxy = b.sxy / b.area, syy = b.syy / b.area;
    const double tr = 0.5 * (sxx + syy), det = sxx * syy - sxy * sxy;
    const double l1 = tr + std::sqrt(std::max(0.0, tr * tr - det));
    const double lengthPx = std::sqrt(12.0 * l1);
    if (lengthPx < kMinLengthShare * nominalPx || lengthPx > kMaxLengthShare * nominalPx + maxPenPx) continue;
    if (b.area / lengthPx > maxPenPx) continue;  // not a thin stroke
    const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
    candidates.push_back({&b, Vec2(std::cos(angle), std::sin(angle)), angle < 0.0 ? angle + kPi : angle});
  }
  // The pattern's lines are parallel: keep those along the median direction (angles mod pi).
  if (!candidates.empty()) {
    std::vector<double> angles;
    for (const Candidate& cd : candidates) angles.push_back(cd.angle);
    const double ref = candidates.front().angle;
    for (double& a : angles) a = ref + std::remainder(a - ref, kPi);
    const double med = median(angles);
    std::erase_if(candidates, [&](const Candidate& cd) { return std::abs(std::remainder(cd.angle - med, kPi)) > kParallelRad; });
  }
  if (static_cast<int>(candidates.size()) != expectedLines) {
    out.error = sourced(source, std::move(Message(FB_TR("CalibrationScan",
                                                         "found %1 parallel lines of about %2 mm at %3 dpi, expected %4 "
                                                         "(is the dpi right, and the whole pattern on the scan?)"))
                                              .arg(candidates.size())
                                              .arg(nominalLengthMm, 0)
                                              .arg(dpi, 0)
                                              .arg(expectedLines)));
    return out;
  }
  // One direction for every line: along +x of the paper (y up), or +y for vertical lines; the
  // normal 90 deg counter-clockwise from it in the paper frame.
  Vec2 u = candidates.front().u;  // pixel frame (y down)
  const Vec2 uPaper(u.x(), -u.y());
  if (uPaper.x() < -1e-9 || (std::abs(uPaper.x()) <= 1e-9 && uPaper.y() < 0.0)) u = -u;
  const Vec2 nPaper(u.y(), u.x());  // (-uPaper.y, uPaper.x) with uPaper = (u.x, -u.y)
  out.directionDeg = std::atan2(-u.y(), u.x()) * 180.0 / kPi;
  std::vector<std::pair<double, ScannedLine>> found;
  for (const Candidate& cd : candidates) {
    const Vec2 along = cd.u.dot(u) >= 0.0 ? cd.u : Vec2(-cd.u);
    auto line = measureLine(grey, *cd.blob, along, pxPerMm);
    if (!line) {
      const Vec2 at(cd.blob->centroidPx.x() / pxPerMm, (grey.height() - cd.blob->centroidPx.y()) / pxPerMm);
      out.error = sourced(source, std::move(Message(FB_TR("CalibrationScan",
                                                           "the line near (%1, %2) mm has no clear ends"))
                                                .arg(at.x(), 1)
                                                .arg(at.y(), 1)));
      return out;
    }
    const Vec2 mid = 0.5 * (line->startMm + line->endMm);
    found.push_back({mid.dot(nPaper), std::move(*line)});
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::vector<Vec2>> points;
  for (auto& [offset, line] : found) {
    points.push_back(line.pointsMm());
    out.lines.push_back(std::move(line));
  }
  out.figures = accuracyFigures(points, nominalLengthMm);
  return out;
}

LineScanOutcome scanAccuracyLinesFile(const std::string& path, double dpi, int expectedLines, double nominalLengthMm) {
  QImageReader reader(QString::fromStdString(path));
  reader.setAutoTransform(false);
  reader.setAllocationLimit(1024);  // MB, as for the marks
  const QImage image = reader.read();
  if (image.isNull()) {
    LineScanOutcome out;
    out.error = sourced(path, std::move(Message(FB_TR("CalibrationScan", "cannot read the image (%1)"))
                                            .arg(reader.errorString().toStdString())));
    return out;
  }
  return scanAccuracyLines(image, dpi, path, expectedLines, nominalLengthMm);
}

}  // namespace fivebar
