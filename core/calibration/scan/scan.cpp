// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/scan/scan.hpp"

#include <QImageReader>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/calibration/mark_match.hpp"
#include "core/calibration/scan/scan_blobs.hpp"
#include "core/output/fixed_decimal.hpp"

namespace fivebar {
namespace {

// The paper and the ink must differ by at least this many grey levels to find anything.
constexpr double kMinContrast = 40.0;

}  // namespace

namespace scan {

Message sourced(const std::string& source, Message m) {
  return std::move(Message(FB_TR("CalibrationScan", "%1: %2")).arg(source).arg(std::move(m)));
}

ReadyImage readyImage(const QImage& image, double dpi, const std::string& source) {
  ReadyImage out;
  if (!(dpi > 0.0) || !std::isfinite(dpi)) {
    out.problem = sourced(source, FB_TR("CalibrationScan", "the dpi must be a positive number"));
    return out;
  }
  if (image.isNull() || image.width() < 2 || image.height() < 2) {
    out.problem = sourced(source, FB_TR("CalibrationScan", "the image is empty"));
    return out;
  }
  out.grey = image.convertToFormat(QImage::Format_Grayscale8);
  out.levels = levelsOf(out.grey);
  const Levels& levels = out.levels;
  if (levels.paper - levels.ink < kMinContrast)
    out.problem = sourced(source, FB_TR("CalibrationScan", "no ink found (the image has almost no contrast)"));
  return out;
}

}  // namespace scan

using scan::sourced;

ScanOutcome scanImage(const QImage& image, double dpi, const std::vector<MarkRecord>& marks,
                      const std::string& source) {
  ScanOutcome out;
  if (marks.empty()) {
    out.error = sourced(source, FB_TR("CalibrationScan", "the pattern has no marks"));
    return out;
  }
  scan::ReadyImage ready = scan::readyImage(image, dpi, source);
  if (ready.problem) {
    out.error = std::move(*ready.problem);
    return out;
  }
  const QImage& grey = ready.grey;
  const scan::Levels& levels = ready.levels;
  const double pxPerMm = dpi / kMmPerInch;
  const double ringMm = 2.0 * marks.front().ringRadiusMm;
  const std::vector<scan::Blob> blobs = scan::darkBlobs(grey, levels);
  const std::vector<scan::FoundMark> found =
      scan::findMarks(grey, levels, blobs, ringMm * pxPerMm, kScanMaxPenMm * pxPerMm);
  out.foundMarks = static_cast<int>(found.size());
  if (found.empty()) {
    std::ostringstream dpiText;
    dpiText << dpi;
    const double typical = scan::typicalRingSizePx(blobs, 8.0);
    Message m = typical > 0.0
                    ? std::move(Message(FB_TR("CalibrationScan",
                                              "no marks found at %1 dpi: the pattern's rings are %2 mm across "
                                              "(%3 px); the ring-like shapes in the image are about %4 px: is it "
                                              "scanned at about %5 dpi?"))
                                    .arg(dpiText.str())
                                    .arg(ringMm, 1)
                                    .arg(ringMm * pxPerMm, 0)
                                    .arg(typical, 0)
                                    .arg(typical / ringMm * kMmPerInch, 0))
                    : std::move(Message(FB_TR("CalibrationScan",
                                              "no marks found at %1 dpi: the pattern's rings are %2 mm across (%3 px)"))
                                    .arg(dpiText.str())
                                    .arg(ringMm, 1)
                                    .arg(ringMm * pxPerMm, 0));
    out.error = sourced(source, std::move(m));
    return out;
  }
  // Pixel centres to paper mm, y up from the lower left corner.
  const double heightPx = grey.height();
  std::vector<Vec2> foundMm;
  for (const scan::FoundMark& f : found)
    foundMm.push_back(Vec2(f.dotPx.x() / pxPerMm, (heightPx - f.dotPx.y()) / pxPerMm));
  std::vector<Vec2> nominal;
  for (const MarkRecord& m : marks) nominal.push_back(m.mark.nominalMm);
  const MarkMatch match = matchMarks(foundMm, nominal);
  if (!match.ok()) {
    out.error = sourced(source, match.error);
    return out;
  }
  for (size_t i = 0; i < marks.size(); ++i) {
    const PatternMark& m = marks[i].mark;
    const int f = match.foundOfMark[i];
    if (f < 0) {
      out.missingIds.push_back(m.id);
      continue;
    }
    out.measured.push_back({m.id, degFromRad(m.q.theta1), degFromRad(m.q.theta2), foundMm[static_cast<size_t>(f)]});
  }
  std::sort(out.measured.begin(), out.measured.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  out.mirrored = match.machineFromPaper.mirrored;
  const Eigen::Matrix2d& R = match.machineFromPaper.rotation;
  out.rotationDeg = degFromRad(std::atan2(R(1, 0), R(0, 0)));
  out.rmsMm = match.machineFromPaper.rmsMm;
  return out;
}

ScanOutcome scanFile(const std::string& path, double dpi, const std::vector<MarkRecord>& marks) {
  QImageReader reader(QString::fromStdString(path));
  reader.setAutoTransform(false);
  reader.setAllocationLimit(1024);  // MB: an A3 page at 1200 dpi fits
  const QImage image = reader.read();
  if (image.isNull()) {
    ScanOutcome out;
    out.error = sourced(path, std::move(Message(FB_TR("CalibrationScan", "cannot read the image (%1)"))
                                            .arg(reader.errorString().toStdString())));
    return out;
  }
  return scanImage(image, dpi, marks, path);
}

}  // namespace fivebar
