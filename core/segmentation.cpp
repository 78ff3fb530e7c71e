#include "segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "move_samples.hpp"

namespace fivebar {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Points closer than this (mm) are one point: duplicates add nothing but zero-length moves.
constexpr double kDuplicatePointMm = 1e-9;
// FK samples along a joint-linear move: one per this much motor rotation, at least kMinSamples.
constexpr double kSampleStepRad = 0.5 * kPi / 180.0;
constexpr int kMinSamples = 4;
constexpr int kMaxSamples = 512;
// Bisection steps that refine a partial piece after halving found one that fits.
constexpr int kRefineSteps = 3;

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Max over `from` of the distance to the polyline `to`. The segment pointer only moves forward
// (both follow the same direction); a stalled pointer can only overestimate, never under.
double directedDistance(std::span<const Vec2> from, std::span<const Vec2> to) {
  double worst = 0.0;
  if (to.size() == 1) {
    for (const Vec2& p : from) worst = std::max(worst, (p - to[0]).norm());
    return worst;
  }
  const size_t segments = to.size() - 1;
  size_t s = 0;
  for (const Vec2& p : from) {
    double d = pointSegmentDistance(p, to[s], to[s + 1]);
    while (s + 1 < segments) {
      const double next = pointSegmentDistance(p, to[s + 1], to[s + 2]);
      if (next > d) break;
      d = next;
      ++s;
    }
    worst = std::max(worst, d);
  }
  return worst;
}

JointAngles lerp(const JointAngles& a, const JointAngles& b, double u) {
  return {a.theta1 + u * (b.theta1 - a.theta1), a.theta2 + u * (b.theta2 - a.theta2)};
}

std::optional<JointAngles> unwrappedIk(const Geometry& g, WorkingMode mode, const Vec2& p,
                                       const JointAngles& near) {
  const IkResult ik = inverse(g, p, mode);
  if (!ik.ok()) return std::nullopt;
  return JointAngles{unwrapNear(ik.angles.theta1, near.theta1),
                     unwrapNear(ik.angles.theta2, near.theta2)};
}

std::vector<Vec2> withoutDuplicates(std::span<const Vec2> stroke) {
  std::vector<Vec2> pts;
  pts.reserve(stroke.size());
  for (const Vec2& p : stroke)
    if (pts.empty() || (p - pts.back()).norm() > kDuplicatePointMm) pts.push_back(p);
  return pts;
}

// Inverse kinematics of every point, unwrapped along the stroke; sets the failure on `out`.
bool solveAll(const Geometry& g, WorkingMode mode, const std::vector<Vec2>& pts,
              const JointAngles& reference, std::vector<JointAngles>& qs, SegmentedStroke& out) {
  qs.reserve(pts.size());
  JointAngles prev = reference;
  for (const Vec2& p : pts) {
    const auto q = unwrappedIk(g, mode, p, prev);
    if (!q) {
      out.status = SegmentStatus::OutOfReach;
      out.failedAt = p;
      return false;
    }
    qs.push_back(*q);
    prev = *q;
  }
  return true;
}

// The greedy adaptive segmenter's state: the current waypoint lies on polyline segment i.
class Segmenter {
 public:
  Segmenter(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
            const std::vector<Vec2>& pts, const std::vector<JointAngles>& qs,
            const SegmentationOptions& options, SegmentedStroke& out)
      : g_(g), mode_(mode), assembly_(assembly), pts_(pts), qs_(qs), opt_(options), out_(out) {
    cur_ = pts[0];
    qcur_ = qs[0];
  }

  void run() {
    while (i_ + 1 < pts_.size()) {
      // Inside a long segment already being split: the last piece's length predicts the next
      // one, so skip testing the whole remainder (which would cost O(pieces^2) samples).
      if ((pts_[i_ + 1] - cur_).norm() > 2.0 * hintMm_) {
        if (!splitSegment()) return;
        continue;
      }
      const double first = deviationTo(i_ + 1);
      const bool advanced = first <= opt_.deviationBudgetMm ? mergeFrom(first) : splitSegment();
      if (!advanced) return;
    }
  }

 private:
  double deviationTo(size_t j) {
    chain_.assign(1, cur_);
    chain_.insert(chain_.end(), pts_.begin() + static_cast<std::ptrdiff_t>(i_ + 1),
                  pts_.begin() + static_cast<std::ptrdiff_t>(j + 1));
    return jointMoveDeviation(g_, assembly_, qcur_, qs_[j], chain_);
  }

  // Vertex i+1 is reachable in one move: gallop then bisect for the farthest vertex that is.
  bool mergeFrom(double firstDeviation) {
    const size_t last = pts_.size() - 1;
    size_t lo = i_ + 1, hi = last + 1, step = 1;
    double loDev = firstDeviation;
    // The previous merge's span predicts this one: try it first, then gallop or bisect.
    if (lastSpan_ > 1 && i_ + lastSpan_ <= last) {
      const double d = deviationTo(i_ + lastSpan_);
      if (d <= opt_.deviationBudgetMm) {
        lo = i_ + lastSpan_;
        loDev = d;
        step = lastSpan_;
      } else {
        hi = i_ + lastSpan_;
      }
    }
    while (hi > last && lo < last) {
      const size_t cand = std::min(last, lo + step);
      const double d = deviationTo(cand);
      if (d > opt_.deviationBudgetMm) { hi = cand; break; }
      lo = cand;
      loDev = d;
      step *= 2;
    }
    while (hi <= last && hi - lo > 1) {
      const size_t mid = lo + (hi - lo) / 2;
      const double d = deviationTo(mid);
      if (d <= opt_.deviationBudgetMm) { lo = mid; loDev = d; } else { hi = mid; }
    }
    double length = (pts_[i_ + 1] - cur_).norm();
    for (size_t k = i_ + 1; k < lo; ++k) length += (pts_[k + 1] - pts_[k]).norm();
    push(qs_[lo], pts_[lo], loDev, length);
    lastSpan_ = lo - i_;
    i_ = lo;
    hintMm_ = kInfinity;
    return true;
  }

  // Even the next vertex is too far: the longest prefix of this straight segment that fits
  // (within 1/8 of the bracket), starting from the previous piece's length when there is one.
  bool splitSegment() {
    const Vec2 a = cur_, b = pts_[i_ + 1];
    const double length = (b - a).norm();
    double t = std::isfinite(hintMm_) ? std::min(1.0, 2.0 * hintMm_ / length) : 1.0;
    double good = 0.0, goodDev = 0.0, hi = t;
    JointAngles goodQ;
    auto tryAt = [&](double u, JointAngles& q) {
      const Vec2 x = a + u * (b - a);
      const auto qx = unwrappedIk(g_, mode_, x, qcur_);
      if (!qx) return kInfinity;
      q = *qx;
      const Vec2 piece[2] = {a, x};
      return jointMoveDeviation(g_, assembly_, qcur_, q, piece);
    };
    if (std::isfinite(hintMm_)) {  // try the predicted piece first
      JointAngles q;
      t *= 0.5;
      const double d = tryAt(t, q);
      if (d <= opt_.deviationBudgetMm) { good = t; goodDev = d; goodQ = q; }
    }
    while (good == 0.0) {
      hi = t;
      t *= 0.5;
      if (t * length < opt_.minPieceMm) {
        out_.status = SegmentStatus::CannotFollow;
        out_.failedAt = a;
        return false;
      }
      JointAngles q;
      const double d = tryAt(t, q);
      if (d <= opt_.deviationBudgetMm) { good = t; goodDev = d; goodQ = q; }
    }
    double lo = good;
    for (int k = 0; k < kRefineSteps && hi > lo; ++k) {
      const double mid = 0.5 * (lo + hi);
      JointAngles q;
      const double d = tryAt(mid, q);
      if (d <= opt_.deviationBudgetMm) { lo = mid; goodDev = d; goodQ = q; } else { hi = mid; }
    }
    push(goodQ, a + lo * (b - a), goodDev, lo * length);
    hintMm_ = lo * length;
    return true;
  }

  void push(const JointAngles& q, const Vec2& p, double deviation, double length) {
    out_.waypoints.push_back({q, p, deviation, length});
    out_.maxDeviationMm = std::max(out_.maxDeviationMm, deviation);
    cur_ = p;
    qcur_ = q;
  }

  const Geometry& g_;
  WorkingMode mode_;
  AssemblyMode assembly_;
  const std::vector<Vec2>& pts_;
  const std::vector<JointAngles>& qs_;
  const SegmentationOptions& opt_;
  SegmentedStroke& out_;
  size_t i_ = 0;
  Vec2 cur_;
  JointAngles qcur_;
  std::vector<Vec2> chain_;
  double hintMm_ = kInfinity;  // length of the last split piece (mm), infinite after a vertex
  size_t lastSpan_ = 0;        // input segments the last merged move covered
};

}  // namespace

double jointMoveDeviation(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                          const JointAngles& qb, std::span<const Vec2> chain) {
  const double span = std::max(std::abs(qb.theta1 - qa.theta1), std::abs(qb.theta2 - qa.theta2));
  const int n = std::clamp(kMinSamples + static_cast<int>(std::ceil(span / kSampleStepRad)),
                           kMinSamples, kMaxSamples);
  thread_local std::vector<Vec2> curve;
  curve.resize(static_cast<size_t>(n) + 1);
  if (!sampleJointMove(g, assembly, qa, qb, n, curve.data())) return kInfinity;
  // The curve between two samples lies within its sagitta (|second difference| / 8) of their
  // chord; allow for it (with margin) on both directed distances.
  double sagitta = 0.0;
  for (size_t k = 1; k + 1 < curve.size(); ++k)
    sagitta = std::max(sagitta, (curve[k - 1] - 2.0 * curve[k] + curve[k + 1]).norm());
  const double allowance = 1.25 * sagitta / 8.0;
  const double curveToChain = directedDistance(curve, chain);
  const double chainToCurve =
      chain.size() > 2 ? directedDistance(chain.subspan(1, chain.size() - 2), curve) : 0.0;
  return std::max(curveToChain, chainToCurve) + allowance;
}

SegmentedStroke segmentStroke(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                              std::span<const Vec2> stroke, const JointAngles& reference,
                              const SegmentationOptions& options) {
  SegmentedStroke out;
  const std::vector<Vec2> pts = withoutDuplicates(stroke);
  if (pts.empty()) return out;
  std::vector<JointAngles> qs;
  if (!solveAll(g, mode, pts, reference, qs, out)) return out;
  out.waypoints.push_back({qs[0], pts[0], 0.0, 0.0});
  Segmenter(g, mode, assembly, pts, qs, options, out).run();
  return out;
}

SegmentedStroke segmentFixedLength(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                                   std::span<const Vec2> stroke, const JointAngles& reference,
                                   double stepMm) {
  SegmentedStroke out;
  const std::vector<Vec2> pts = withoutDuplicates(stroke);
  if (pts.empty()) return out;
  std::vector<JointAngles> qs;
  if (!solveAll(g, mode, pts, reference, qs, out)) return out;
  out.waypoints.push_back({qs[0], pts[0], 0.0, 0.0});
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 a = pts[i], b = pts[i + 1];
    const double length = (b - a).norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / stepMm)));
    for (int k = 1; k <= pieces; ++k) {
      const Vec2 prevP = out.waypoints.back().p;
      const JointAngles prevQ = out.waypoints.back().q;
      const Vec2 x = k == pieces ? b : Vec2(a + (static_cast<double>(k) / pieces) * (b - a));
      const auto q = k == pieces ? std::optional<JointAngles>(JointAngles{
                                       unwrapNear(qs[i + 1].theta1, prevQ.theta1),
                                       unwrapNear(qs[i + 1].theta2, prevQ.theta2)})
                                 : unwrappedIk(g, mode, x, prevQ);
      if (!q) {
        out.status = SegmentStatus::OutOfReach;
        out.failedAt = x;
        return out;
      }
      const Vec2 piece[2] = {prevP, x};
      const double d = jointMoveDeviation(g, assembly, prevQ, *q, piece);
      out.waypoints.push_back({*q, x, d, length / pieces});
      out.maxDeviationMm = std::max(out.maxDeviationMm, d);
    }
  }
  return out;
}

}  // namespace fivebar
