// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/accuracy_pattern.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/calibration/pattern_checks.hpp"
#include "core/planning/segmentation.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

// Spacing of the checked points along and around the lines.
constexpr double kCheckStepMm = 2.0;
// Grid of candidate centres searched for the placement.
constexpr double kCandidateStepMm = 2.5;

bool fits(const MachineProfile& profile, const AccuracyPattern& a, double clearanceMm) {
  for (const AccuracyLine& l : a.lines) {
    // The planner must be able to follow the line with joint-linear moves.
    const std::vector<Vec2> line{l.startMm, l.endMm};
    if (!segmentStroke(profile.geometry, profile.defaultMode, profile.assembly, line, profile.homeAngles, {}).ok())
      return false;
    const double length = (l.endMm - l.startMm).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(length / kCheckStepMm)));
    for (int k = 0; k <= n; ++k) {
      const Vec2 p = l.startMm + (l.endMm - l.startMm) * (static_cast<double>(k) / n);
      if (!pattern_detail::discIsSafe(profile, profile.defaultMode, p, clearanceMm, 8)) return false;
    }
  }
  return true;
}

}  // namespace

AccuracyPattern accuracyPatternAt(const Vec2& centerMm, const Vec2& direction) {
  const Vec2 u = direction.normalized();
  const Vec2 v(-u.y(), u.x());
  AccuracyPattern a;
  for (int i = 0; i < kAccuracyLineCount; ++i) {
    const double offset = (i - 0.5 * (kAccuracyLineCount - 1)) * kAccuracyLineSpacingMm;
    const Vec2 mid = centerMm + offset * v;
    a.lines.push_back({mid - 0.5 * kAccuracyLineLengthMm * u, mid + 0.5 * kAccuracyLineLengthMm * u});
  }
  return a;
}

std::optional<AccuracyPattern> placeAccuracyPattern(const MachineProfile& profile,
                                                    double clearanceMm) {
  // Centre of the safe area: the largest safe rectangle's centre (workspace analysis).
  const WorkspaceSettings s = workspaceSettings(profile);
  const GridSpec grid = gridCovering(profile.geometry, 120);
  const WorkspaceMap map = computeMap(profile.geometry, s, profile.defaultMode, grid, 1);
  const std::optional<Rect> rect = largestSafeRectangle(map, profile.geometry, s);
  if (!rect) return std::nullopt;
  const Vec2 center(0.5 * (rect->xMin + rect->xMax), 0.5 * (rect->yMin + rect->yMax));
  // Candidates on a spiral of growing distance from the centre: nearest first.
  struct Candidate {
    Vec2 c;
    double d;
  };
  std::vector<Candidate> candidates;
  const double reach = std::max(rect->width(), rect->height());
  const int n = static_cast<int>(std::ceil(reach / kCandidateStepMm));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const Vec2 c = center + kCandidateStepMm * Vec2(i, j);
      candidates.push_back({c, (c - center).norm()});
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.d < b.d; });
  for (const Candidate& c : candidates)
    for (const Vec2& dir : {Vec2(1.0, 0.0), Vec2(0.0, 1.0)}) {
      AccuracyPattern a = accuracyPatternAt(c.c, dir);
      if (fits(profile, a, clearanceMm)) return a;
    }
  return std::nullopt;
}

std::optional<AccuracyFigures> accuracyFigures(const std::vector<std::vector<Vec2>>& measuredLines,
                                               double nominalLengthMm) {
  AccuracyFigures f;
  double sumStraight2 = 0.0, sumLength2 = 0.0;
  for (const std::vector<Vec2>& pts : measuredLines) {
    if (pts.size() < 2 || (pts.back() - pts.front()).norm() <= 0.0) return std::nullopt;
    Vec2 mean = Vec2::Zero();
    for (const Vec2& p : pts) mean += p;
    mean /= static_cast<double>(pts.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Vec2& p : pts) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    Vec2 u = eig.eigenvectors().col(1);  // largest eigenvalue: the line's direction
    if (u.dot(pts.back() - pts.front()) < 0.0) u = -u;
    const Vec2 normal(-u.y(), u.x());
    LineAccuracy l;
    for (const Vec2& p : pts) l.straightnessMm = std::max(l.straightnessMm, std::abs(normal.dot(p - mean)));
    l.lengthMm = u.dot(pts.back() - pts.front());
    l.lengthErrorMm = l.lengthMm - nominalLengthMm;
    f.maxStraightnessMm = std::max(f.maxStraightnessMm, l.straightnessMm);
    f.maxAbsLengthErrorMm = std::max(f.maxAbsLengthErrorMm, std::abs(l.lengthErrorMm));
    sumStraight2 += l.straightnessMm * l.straightnessMm;
    sumLength2 += l.lengthErrorMm * l.lengthErrorMm;
    f.lines.push_back(l);
  }
  if (f.lines.empty()) return std::nullopt;
  const double n = static_cast<double>(f.lines.size());
  f.rmsStraightnessMm = std::sqrt(sumStraight2 / n);
  f.rmsLengthErrorMm = std::sqrt(sumLength2 / n);
  return f;
}

}  // namespace fivebar
