// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/calibration/mark_match.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fivebar {
namespace {

// Base pairs of nominal marks tried (the longest pairs between distinct marks).
constexpr int kBasePairs = 6;
// Relative and absolute slack when comparing a found pair's length with a base pair's.
constexpr double kPairSlackShare = 0.03;
constexpr double kPairSlackMm = 4.0;
// A second placement this close to the best in matched marks makes the match ambiguous.
constexpr int kAmbiguityMarks = 2;

struct Hypothesis {
  RigidFit paperFromMachine;  // maps nominal (machine) points onto the paper
  std::vector<int> assign;
  int matched = 0;
  double sum2 = 0.0;
};

// Assigns each nominal mark to its nearest found mark within tolerance, one found mark per
// nominal (the nearer nominal wins a conflict).
void assign(const std::vector<Vec2>& found, const std::vector<Vec2>& nominal, double tol, Hypothesis& h) {
  h.assign.assign(nominal.size(), -1);
  std::vector<double> bestOfFound(found.size(), std::numeric_limits<double>::infinity());
  std::vector<int> ownerOfFound(found.size(), -1);
  for (size_t i = 0; i < nominal.size(); ++i) {
    const Vec2 p = h.paperFromMachine.map(nominal[i]);
    int best = -1;
    double bestD = tol * tol;
    for (size_t k = 0; k < found.size(); ++k) {
      const double d = (found[k] - p).squaredNorm();
      if (d < bestD) { bestD = d; best = static_cast<int>(k); }
    }
    if (best < 0) continue;
    if (bestD < bestOfFound[static_cast<size_t>(best)]) {
      if (ownerOfFound[static_cast<size_t>(best)] >= 0) h.assign[static_cast<size_t>(ownerOfFound[static_cast<size_t>(best)])] = -1;
      bestOfFound[static_cast<size_t>(best)] = bestD;
      ownerOfFound[static_cast<size_t>(best)] = static_cast<int>(i);
      h.assign[i] = best;
    }
  }
  h.matched = 0;
  h.sum2 = 0.0;
  for (size_t i = 0; i < nominal.size(); ++i)
    if (h.assign[i] >= 0) {
      ++h.matched;
      h.sum2 += (found[static_cast<size_t>(h.assign[i])] - h.paperFromMachine.map(nominal[i])).squaredNorm();
    }
}

bool better(const Hypothesis& a, const Hypothesis& b) {
  return a.matched != b.matched ? a.matched > b.matched : a.sum2 < b.sum2;
}

// Least-squares refinement: the rigid fit of the assigned pairs, then a new assignment.
void refine(const std::vector<Vec2>& found, const std::vector<Vec2>& nominal, double tol, bool mirrored,
            Hypothesis& h) {
  for (int iter = 0; iter < 3; ++iter) {
    std::vector<Vec2> from, to;
    for (size_t i = 0; i < nominal.size(); ++i)
      if (h.assign[i] >= 0) {
        from.push_back(nominal[i]);
        to.push_back(found[static_cast<size_t>(h.assign[i])]);
      }
    const std::optional<RigidFit> f = fitRigid(from, to, mirrored);
    if (!f) return;
    h.paperFromMachine = *f;
    assign(found, nominal, tol, h);
  }
}

}  // namespace

MarkMatch matchMarks(const std::vector<Vec2>& found, const std::vector<Vec2>& nominal,
                     const MatchOptions& options) {
  MarkMatch out;
  out.foundOfMark.assign(nominal.size(), -1);
  if (nominal.size() < 3) {
    out.error = FB_TR("CalibrationScan", "the pattern has fewer than 3 marks");
    return out;
  }
  if (found.size() < 3) {
    out.error = std::move(Message(FB_TR("CalibrationScan", "found %1 marks, the pattern has %2")).arg(found.size()).arg(nominal.size()));
    return out;
  }
  // Base pairs: the longest nominal pairs, each mark used once.
  struct Pair { size_t i, j; double d; };
  std::vector<Pair> pairs;
  for (size_t i = 0; i < nominal.size(); ++i)
    for (size_t j = i + 1; j < nominal.size(); ++j) pairs.push_back({i, j, (nominal[j] - nominal[i]).norm()});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d > b.d; });
  std::vector<Pair> bases;
  std::vector<bool> used(nominal.size(), false);
  for (const Pair& p : pairs) {
    if (static_cast<int>(bases.size()) >= kBasePairs) break;
    if (used[p.i] || used[p.j]) continue;
    used[p.i] = used[p.j] = true;
    bases.push_back(p);
  }
  // Best hypothesis per handedness; and the best whose placement differs from the overall best.
  std::vector<Hypothesis> all;
  for (bool mirrored : {false, true}) {
    const Eigen::Matrix2d flip = mirrored ? Eigen::Vector2d(1.0, -1.0).asDiagonal().toDenseMatrix()
                                          : Eigen::Matrix2d::Identity();
    for (const Pair& b : bases) {
      const Vec2 nd = flip * (nominal[b.j] - nominal[b.i]);
      for (size_t a = 0; a < found.size(); ++a)
        for (size_t c = 0; c < found.size(); ++c) {
          if (a == c) continue;
          const Vec2 fd = found[c] - found[a];
          if (std::abs(fd.norm() - b.d) > kPairSlackMm + kPairSlackShare * b.d) continue;
          Hypothesis h;
          const double angle = std::atan2(cross(nd, fd), nd.dot(fd));
          h.paperFromMachine.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix() * flip;
          h.paperFromMachine.mirrored = mirrored;
          h.paperFromMachine.translation =
              0.5 * (found[a] + found[c]) - h.paperFromMachine.rotation * (0.5 * (nominal[b.i] + nominal[b.j]));
          assign(found, nominal, options.assignToleranceMm, h);
          all.push_back(std::move(h));
        }
    }
  }
  if (all.empty()) {
    out.error = FB_TR("CalibrationScan", "no two found marks are as far apart as the pattern's marks (is the dpi right?)");
    return out;
  }
  std::sort(all.begin(), all.end(), better);
  // Refine the best few distinct placements (rotation differs by more than 5 deg or handedness,
  // or the centre moved by more than the tolerance).
  std::vector<Hypothesis> distinct;
  for (Hypothesis& h : all) {
    if (distinct.size() >= 4) break;
    bool same = false;
    for (const Hypothesis& d : distinct) {
      const Eigen::Matrix2d dr = d.paperFromMachine.rotation.transpose() * h.paperFromMachine.rotation;
      same = same || (d.paperFromMachine.mirrored == h.paperFromMachine.mirrored &&
                      std::abs(std::atan2(dr(1, 0), dr(0, 0))) < radFromDeg(5.0) &&
                      (d.paperFromMachine.translation - h.paperFromMachine.translation).norm() <
                          options.assignToleranceMm * 4.0);
    }
    if (same) continue;
    refine(found, nominal, options.assignToleranceMm, h.paperFromMachine.mirrored, h);
    distinct.push_back(h);
  }
  std::sort(distinct.begin(), distinct.end(), better);
  const Hypothesis& best = distinct.front();
  const int needed = static_cast<int>(std::ceil(options.minFoundShare * static_cast<double>(nominal.size())));
  if (best.matched < needed) {
    out.error = std::move(Message(FB_TR("CalibrationScan",
                                        "only %1 of the pattern's %2 marks match the found ones (%3 found): "
                                        "not this pattern, or the dpi is wrong"))
                              .arg(best.matched)
                              .arg(nominal.size())
                              .arg(found.size()));
    return out;
  }
  if (distinct.size() > 1 && distinct[1].matched >= best.matched - kAmbiguityMarks &&
      distinct[1].assign != best.assign) {
    out.error = std::move(Message(FB_TR("CalibrationScan", "ambiguous: two placements of the sheet match %1 and %2 marks"))
                              .arg(best.matched)
                              .arg(distinct[1].matched));
    return out;
  }
  out.foundOfMark = best.assign;
  out.matched = best.matched;
  // The placement returned maps paper to machine.
  std::vector<Vec2> paper, machine;
  for (size_t i = 0; i < nominal.size(); ++i)
    if (best.assign[i] >= 0) {
      paper.push_back(found[static_cast<size_t>(best.assign[i])]);
      machine.push_back(nominal[i]);
    }
  out.machineFromPaper = *fitRigid(paper, machine, best.paperFromMachine.mirrored);
  return out;
}

}  // namespace fivebar
