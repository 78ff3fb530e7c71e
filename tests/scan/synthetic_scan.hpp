// SPDX-License-Identifier: GPL-3.0-or-later
// Synthetic scans of a calibration pattern for the scan tests and benchmark: the pattern's
// strokes painted by QPainter (antialiased, round pen) on a white page at a given dpi, the sheet
// turned, shifted and optionally mirrored, marks optionally displaced (an imperfect machine), then
// a Gaussian blur and seeded Gaussian noise. Knows where each dot really is (paper frame: mm from
// the image's lower left corner, y up), so a scan can be checked to the micrometre.
#pragma once

#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "core/calibration/pattern.hpp"

namespace fivebar::test {

struct SheetOptions {
  double dpi = 300.0;
  double rotationDeg = 0.0;
  bool mirrored = false;
  double marginMm = 12.0;
  double penMm = 0.4;
  double dotMm = 0.7;
  double blurSigmaPx = 0.0;
  double noiseSigma = 0.0;        // grey levels
  std::uint64_t seed = 1;
  std::map<int, Vec2> displacementMm;  // per mark id: drawn this far from nominal (machine frame)
  double pageWidthMm = 0.0;      // 0: just large enough for the turned pattern
  double pageHeightMm = 0.0;
};

struct Sheet {
  QImage image;                      // Format_Grayscale8
  std::map<int, Vec2> truePaperMm;   // where each dot's centre is
};

inline void gaussianBlur(QImage& img, double sigma) {
  if (!(sigma > 0.0)) return;
  const int r = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<double> k(static_cast<size_t>(2 * r + 1));
  double sum = 0.0;
  for (int i = -r; i <= r; ++i) sum += k[static_cast<size_t>(i + r)] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& v : k) v /= sum;
  const int w = img.width(), h = img.height();
  std::vector<float> tmp(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) {
    const uchar* row = img.constScanLine(y);
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int i = -r; i <= r; ++i) s += k[static_cast<size_t>(i + r)] * row[std::clamp(x + i, 0, w - 1)];
      tmp[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] = static_cast<float>(s);
    }
  }
  for (int y = 0; y < h; ++y) {
    uchar* row = img.scanLine(y);
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int i = -r; i <= r; ++i)
        s += k[static_cast<size_t>(i + r)] * tmp[static_cast<size_t>(std::clamp(y + i, 0, h - 1)) * static_cast<size_t>(w) + static_cast<size_t>(x)];
      row[x] = static_cast<uchar>(std::clamp(std::lround(s), 0L, 255L));
    }
  }
}

inline void addNoise(QImage& img, double sigma, std::uint64_t seed) {
  if (!(sigma > 0.0)) return;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, sigma);
  for (int y = 0; y < img.height(); ++y) {
    uchar* row = img.scanLine(y);
    for (int x = 0; x < img.width(); ++x) row[x] = static_cast<uchar>(std::clamp(std::lround(row[x] + n(rng)), 0L, 255L));
  }
}

inline Sheet renderSheet(const CalibrationPattern& pattern, const SheetOptions& o) {
  // Drawn positions (machine frame): every stroke of a mark moves with its displacement. A mark's
  // strokes (ring, number, dot) are those after the previous dot IN PLOTTING ORDER up to its own
  // dot, and near it: the marks are listed by id, not in plotting order, and the accuracy lines
  // (an item of the same tour) belong to no mark.
  std::vector<Vec2> strokeShift(pattern.strokes.size(), Vec2::Zero());
  std::vector<size_t> byDot(pattern.marks.size());
  for (size_t i = 0; i < byDot.size(); ++i) byDot[i] = i;
  std::sort(byDot.begin(), byDot.end(),
            [&](size_t a, size_t b) { return pattern.dotStroke[a] < pattern.dotStroke[b]; });
  const double markRadiusMm = 15.0;  // ring and number lie within this of the dot
  int previousDot = -1;
  for (const size_t i : byDot) {
    const int dot = pattern.dotStroke[i];
    const int first = previousDot + 1;
    previousDot = dot;
    const auto it = o.displacementMm.find(pattern.marks[i].id);
    if (it == o.displacementMm.end()) continue;
    for (int s = first; s <= dot; ++s) {
      const auto& pts = pattern.strokes[static_cast<size_t>(s)].points;
      const bool near = std::all_of(pts.begin(), pts.end(), [&](const Vec2& p) {
        return (p - pattern.marks[i].nominalMm).norm() <= markRadiusMm;
      });
      if (near) strokeShift[static_cast<size_t>(s)] = it->second;
    }
  }
  const double a = o.rotationDeg * kPi / 180.0;
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(a).toRotationMatrix() *
                            (o.mirrored ? Eigen::Vector2d(1, -1).asDiagonal().toDenseMatrix() : Eigen::Matrix2d::Identity());
  Vec2 lo = Vec2::Constant(1e18), hi = -lo;
  for (const Stroke& s : pattern.strokes)
    for (const Vec2& p : s.points) {
      lo = lo.cwiseMin(R * p);
      hi = hi.cwiseMax(R * p);
    }
  const double wMm = o.pageWidthMm > 0 ? o.pageWidthMm : hi.x() - lo.x() + 2 * o.marginMm;
  const double hMm = o.pageHeightMm > 0 ? o.pageHeightMm : hi.y() - lo.y() + 2 * o.marginMm;
  const Vec2 shift = Vec2(0.5 * wMm, 0.5 * hMm) - 0.5 * (lo + hi);  // centred on the page
  const double pxPerMm = o.dpi / 25.4;
  Sheet sheet;
  sheet.image = QImage(static_cast<int>(std::ceil(wMm * pxPerMm)), static_cast<int>(std::ceil(hMm * pxPerMm)),
                       QImage::Format_Grayscale8);
  sheet.image.fill(255);
  const double H = sheet.image.height();
  auto toPx = [&](const Vec2& machine) {
    const Vec2 paper = R * machine + shift;
    return QPointF(paper.x() * pxPerMm, H - paper.y() * pxPerMm);
  };
  {
    QPainter painter(&sheet.image);
    painter.setRenderHint(QPainter::Antialiasing);
    QPen pen(QColor(20, 20, 20));
    pen.setWidthF(o.penMm * pxPerMm);
    pen.setCapStyle(Qt::RoundCap);
    pen.setJoinStyle(Qt::RoundJoin);
    painter.setPen(pen);
    for (size_t k = 0; k < pattern.strokes.size(); ++k) {
      const Stroke& s = pattern.strokes[k];
      if (s.points.size() < 2) continue;
      QPainterPath path(toPx(s.points[0] + strokeShift[k]));
      for (size_t i = 1; i < s.points.size(); ++i) path.lineTo(toPx(s.points[i] + strokeShift[k]));
      painter.drawPath(path);
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(20, 20, 20));
    const double r = 0.5 * o.dotMm * pxPerMm;
    for (size_t i = 0; i < pattern.marks.size(); ++i) {
      const Vec2 m = pattern.marks[i].nominalMm + strokeShift[static_cast<size_t>(pattern.dotStroke[i])];
      painter.drawEllipse(toPx(m), r, r);
      sheet.truePaperMm[pattern.marks[i].id] = R * m + shift;
    }
  }
  gaussianBlur(sheet.image, o.blurSigmaPx);
  addNoise(sheet.image, o.noiseSigma, o.seed);
  return sheet;
}

}  // namespace fivebar::test
