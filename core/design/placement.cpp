// SPDX-License-Identifier: GPL-3.0-or-later
// Placement: a scan of rectangle centres over the reachable region's bounding box, then a local
// NLopt search (Subplex, derivative-free: the worst case over samples is not smooth) from the
// best few, on successively finer samplings.
#include "core/design/placement.hpp"

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>

namespace fivebar::design {
namespace {

// Centres tried per axis by the scan.
constexpr int kScanPerAxis = 24;
// Scan candidates refined locally.
constexpr int kRefined = 3;
// Local search budget per candidate and its stopping tolerance on the centre (mm).
constexpr int kLocalEvaluations = 400;
constexpr double kCentreToleranceMm = 1e-3;

struct Candidate {
  double cx = 0.0, cy = 0.0, score = 0.0;
};

struct LocalProblem {
  const Geometry* g;
  WorkingMode mode;
  double w, h;
  const DesignRules* rules;
  Objective objective;
  MixWeights weights;
  Sampling sampling;
};

double localScore(unsigned n, const double* x, double* grad, void* data) {
  (void)n;
  (void)grad;
  const auto& p = *static_cast<const LocalProblem*>(data);
  return penalisedScore(p.objective,
                        evaluateDesign(*p.g, p.mode, centredRect(x[0], x[1], p.w, p.h), *p.rules,
                                       p.sampling),
                        p.weights);
}

Placement placeOriented(const Geometry& g, WorkingMode mode, double w, double h,
                        const DesignRules& rules, const PlacementOptions& options) {
  const double reach1 = g.a1 + g.b1, reach2 = g.a2 + g.b2;
  const double xLo = std::max(-0.5 * g.w - reach1, 0.5 * g.w - reach2) + 0.5 * w;
  const double xHi = std::min(-0.5 * g.w + reach1, 0.5 * g.w + reach2) - 0.5 * w;
  const double yLo = rules.minRectangleYMm + 0.5 * h;
  const double yHi = std::max(yLo, std::min(reach1, reach2) - 0.5 * h);
  const double coarse = std::max(w, h) / 8.0;
  LocalProblem problem{&g, mode, w, h, &rules, options.objective, options.weights, Sampling{coarse}};
  std::vector<Candidate> scan;
  for (int j = 0; j < kScanPerAxis; ++j)
    for (int i = 0; i < kScanPerAxis; ++i) {
      const double cx = xHi > xLo ? xLo + (xHi - xLo) * (i + 0.5) / kScanPerAxis : 0.5 * (xLo + xHi);
      const double cy = yLo + (yHi - yLo) * (j + 0.5) / kScanPerAxis;
      const double x[2] = {cx, cy};
      scan.push_back({cx, cy, localScore(2, x, nullptr, &problem)});
    }
  std::stable_sort(scan.begin(), scan.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  scan.resize(std::min<std::size_t>(scan.size(), kRefined));
  Placement best;
  bool have = false;
  const double span = std::max({w, h, 1.0});
  for (const Candidate& c : scan) {
    std::vector<double> x{c.cx, c.cy};
    for (double spacing : {coarse, std::max(w, h) / 24.0, options.finalSampling.spacingMm * 2.0}) {
      problem.sampling = Sampling{spacing};
      nlopt::opt opt(nlopt::LN_SBPLX, 2);
      opt.set_min_objective(localScore, &problem);
      opt.set_lower_bounds({std::min(xLo, xHi) - span, yLo});
      opt.set_upper_bounds({std::max(xLo, xHi) + span, yHi + span});
      opt.set_initial_step({0.05 * span, 0.05 * span});
      opt.set_xtol_abs(kCentreToleranceMm);
      opt.set_maxeval(kLocalEvaluations);
      double f = 0.0;
      try {
        opt.optimize(x, f);
      } catch (const std::exception&) {
        // A failed local step keeps the best point NLopt reported in x.
      }
    }
    Placement p;
    p.rect = centredRect(x[0], x[1], w, h);
    p.evaluation = evaluateDesign(g, mode, p.rect, rules, options.finalSampling);
    p.score = penalisedScore(options.objective, p.evaluation, options.weights);
    if (!have || p.score < best.score) {
      best = p;
      have = true;
    }
  }
  return best;
}

}  // namespace

Placement bestPlacement(const Geometry& g, WorkingMode mode, double widthMm, double heightMm,
                        const DesignRules& rules, const PlacementOptions& options) {
  Placement best = placeOriented(g, mode, widthMm, heightMm, rules, options);
  if (options.allowRotation && widthMm != heightMm) {
    Placement turned = placeOriented(g, mode, heightMm, widthMm, rules, options);
    turned.rotated = true;
    if (turned.score < best.score) best = turned;
  }
  return best;
}

}  // namespace fivebar::design
