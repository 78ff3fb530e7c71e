// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/kinematics/batch.hpp"
#include "core/kinematics/units.hpp"
#include "core/kinematics/move_samples.hpp"

namespace fivebar {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Points closer than this (mm) are one point: duplicates add nothing but zero-length moves.
constexpr double kDuplicatePointMm = 1e-9;
// FK samples along a joint-linear move: one per this much motor rotation, at least kMinSamples.
constexpr double kSampleStepRad = 1.0 * kPi / 180.0;
constexpr int kMinSamples = 8;
constexpr int kMaxSamples = 512;
// Share of the deviation budget a split piece is aimed at, and the share below which one longer
// piece is tried.
constexpr double kSplitTarget = 0.985;
constexpr double kSplitGrowBelow = 0.9;

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

std::optional<JointAngles> unwrappedIk(const Geometry& g, WorkingMode mode, const Vec2& p,
                                       const JointAngles& near) {
  const IkResult ik = inverse(g, p, mode);
  if (!ik.ok()) return std::nullopt;
  return JointAngles{unwrapNear(ik.angles.theta1, near.theta1),
                     unwrapNear(ik.angles.theta2, near.theta2)};
}

// The angles as the G-code carries them: `decimals` decimals of a degree (decimals < 0: as they are).
JointAngles roundedAngles(const JointAngles& q, int decimals) {
  if (decimals < 0) return q;
  const double unitsPerDeg = std::pow(10.0, decimals);
  auto round = [&](double rad) { return radFromDeg(std::nearbyint(degFromRad(rad) * unitsPerDeg) / unitsPerDeg); };
  return {round(q.theta1), round(q.theta2)};
}

void withoutDuplicates(std::span<const Vec2> stroke, std::vector<Vec2>& pts) {
  pts.clear();
  pts.reserve(stroke.size());
  for (const Vec2& p : stroke)
    if (pts.empty() || (p - pts.back()).norm() > kDuplicatePointMm) pts.push_back(p);
}

// Inverse kinematics of every point (batch kernels), unwrapped along the stroke; sets the
// failure on `out`.
bool solveAll(const Geometry& g, WorkingMode mode, const std::vector<Vec2>& pts,
              const JointAngles& reference, std::vector<JointAngles>& qs, SegmentedStroke& out,
              int angleDecimals = -1) {
  const std::size_t n = pts.size();
  thread_local std::vector<double> buf;  // scratch
  thread_local std::vector<std::uint8_t> ok;
  buf.resize(4 * n);
  ok.resize(n);
  double *x = buf.data(), *y = x + n, *t1 = y + n, *t2 = t1 + n;
  for (std::size_t k = 0; k < n; ++k) x[k] = pts[k].x(), y[k] = pts[k].y();
  BatchOptions single;
  single.maxThreads = 1;
  inverseBatch(g, mode, x, y, n, t1, t2, ok.data(), single);
  qs.clear();
  qs.reserve(n);
  JointAngles prev = reference;
  for (std::size_t k = 0; k < n; ++k) {
    if (!ok[k]) {
      out.status = SegmentStatus::OutOfReach;
      out.failedAt = pts[k];
      return false;
    }
    const JointAngles q{unwrapNear(t1[k], prev.theta1), unwrapNear(t2[k], prev.theta2)};
    qs.push_back(roundedAngles(q, angleDecimals));
    prev = q;
  }
  return true;
}

struct MoveEval {
  double deviationMm = kInfinity;
  double peakSpeedMmPerUnit = 0.0;
  double bowMm = 0.0;  // largest distance of a sample from the line through the move's ends
  int bowSide = 0;     // side of that sample: +1 left of the move's direction, -1 right
};

// Deviation of the joint-linear move qa -> qb from `chain` (see jointMoveDeviation), and the
// largest XY speed among its samples.
MoveEval evaluateMove(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                      const MotorTrig& trigA, const JointAngles& qb, std::span<const Vec2> chain) {
  const double span = std::max(std::abs(qb.theta1 - qa.theta1), std::abs(qb.theta2 - qa.theta2));
  const int n = std::clamp(kMinSamples + static_cast<int>(std::ceil(span / kSampleStepRad)),
                           kMinSamples, kMaxSamples);
  thread_local std::vector<Vec2> curve;
  curve.resize(static_cast<size_t>(n) + 1);
  MoveEval out;
  if (!sampleJointMove(g, assembly, qa, trigA, qb, n, curve.data())) return out;
  // The curve between two samples lies within its sagitta (|second difference| / 8) of their
  // chord; allow for it (with margin) on both directed distances.
  double sagitta2 = 0.0, step2 = (curve[1] - curve[0]).squaredNorm();
  for (size_t k = 1; k + 1 < curve.size(); ++k) {
    sagitta2 = std::max(sagitta2, (curve[k - 1] - 2.0 * curve[k] + curve[k + 1]).squaredNorm());
    step2 = std::max(step2, (curve[k + 1] - curve[k]).squaredNorm());
  }
  const double allowance = 1.25 * std::sqrt(sagitta2) / 8.0;
  const double curveToChain = directedDistance(curve, chain);
  const double chainToCurve =
      chain.size() > 2 ? directedDistance(chain.subspan(1, chain.size() - 2), curve) : 0.0;
  out.deviationMm = std::max(curveToChain, chainToCurve) + allowance;
  out.peakSpeedMmPerUnit = std::sqrt(step2) * n;
  const Vec2 chord = curve.back() - curve.front();
  const double chordLength = chord.norm();
  if (chordLength > 0.0)
    for (const Vec2& c : curve) {
      const double side = cross(chord, c - curve.front()) / chordLength;
      if (std::abs(side) > out.bowMm) {
        out.bowMm = std::abs(side);
        out.bowSide = side > 0.0 ? 1 : -1;
      }
    }
  out.bowMm += allowance;
  return out;
}

// The greedy adaptive segmenter's state: the current waypoint lies on polyline segment i.
// Merges are found in the plane first (the farthest vertex whose skipped vertices stay within the
// budget of the chord), then confirmed by FK samples: two sampled moves per waypoint in the usual
// case. Straight segments too long for one move are split (splitSegment).
class Segmenter {
 public:
  Segmenter(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
            const std::vector<Vec2>& pts, const std::vector<JointAngles>& qs,
            const SegmentationOptions& options, SegmentedStroke& out)
      : g_(g), mode_(mode), assembly_(assembly), pts_(pts), qs_(qs), opt_(options), out_(out) {
    cur_ = pts[0];
    qcur_ = qs[0];
    thread_local std::vector<MotorTrig> trig;
    trig.resize(pts.size());
    if (options.angleDecimalsDeg < 0) {
      motorTrigOfPoints(g, mode, pts.data(), pts.size(), trig.data());
    } else {  // of the rounded angles, which are no longer exactly the points'
      for (std::size_t j = 0; j < pts.size(); ++j) trig[j] = MotorTrig::of(qs[j]);
    }
    trig_ = trig.data();
    trigCur_ = trig_[0];
  }

  void run() {
    while (i_ + 1 < pts_.size()) {
      // Inside a long segment already being split: the last piece's length predicts the next
      // one, so skip testing the whole remainder (which would cost O(pieces^2) samples).
      if ((pts_[i_ + 1] - cur_).norm() > 2.0 * hintMm_) {
        if (!splitSegment()) return;
        continue;
      }
      if (!merge() && !splitSegment()) return;
    }
  }

 private:
  const MotorTrig& trigAt(size_t j) const { return trig_[j]; }
  MotorTrig trigOf(const Vec2& p, const JointAngles& q) const {
    if (opt_.angleDecimalsDeg >= 0) return MotorTrig::of(q);
    MotorTrig t;
    motorTrigOfPoints(g_, mode_, &p, 1, &t);
    return t;
  }

  MoveEval evalTo(size_t j) {
    chain_.assign(1, cur_);
    chain_.insert(chain_.end(), pts_.begin() + static_cast<std::ptrdiff_t>(i_ + 1),
                  pts_.begin() + static_cast<std::ptrdiff_t>(j + 1));
    return evaluateMove(g_, assembly_, qcur_, trigCur_, qs_[j], chain_);
  }

  // Largest distance of the vertices skipped by a move to vertex j from its chord (mm).
  double chordDeviation(size_t j) const {
    double worst = 0.0;
    for (size_t k = i_ + 1; k < j; ++k)
      worst = std::max(worst, pointSegmentDistance(pts_[k], cur_, pts_[j]));
    return worst;
  }

  // The farthest vertex whose skipped vertices stay within the budget of the chord: gallop, then
  // bisect (the chord deviation grows with the span in practice; a wrong guess only costs
  // FK-sampled tests below, never accuracy).
  size_t planarReach() const {
    const size_t last = pts_.size() - 1;
    size_t lo = i_ + 1, hi = last + 1, step = 1;
    while (lo < last) {
      const size_t cand = std::min(last, lo + step);
      if (chordDeviation(cand) > opt_.deviationBudgetMm) { hi = cand; break; }
      lo = cand;
      step *= 2;
    }
    while (hi <= last && hi - lo > 1) {
      const size_t mid = lo + (hi - lo) / 2;
      if (chordDeviation(mid) <= opt_.deviationBudgetMm) lo = mid; else hi = mid;
    }
    return lo;
  }

  bool mayExtend(size_t lo, const MoveEval& e) const {
    const double now = (pts_[lo] - cur_).squaredNorm(), next = (pts_[lo + 1] - cur_).squaredNorm();
    const double bow = now > 0.0 ? e.bowMm * std::max(1.0, next / now) : kInfinity;
    return chordDeviation(lo + 1) <= opt_.deviationBudgetMm + 1.5 * bow;
  }

  // Moves to the farthest vertex one joint-linear move can reach within the budget; false when
  // not even vertex i+1 can be reached.
  bool merge() {
    const size_t last = pts_.size() - 1;
    size_t lo = planarReach();
    MoveEval e = evalTo(lo);
    if (e.deviationMm <= opt_.deviationBudgetMm) {
      // The curve may bend towards a farther chain: extend while the sampled test agrees, unless
      // the next chain is farther from its chord than the curve can bow (which grows with the
      // square of the chord).
      while (lo < last && mayExtend(lo, e)) {
        const MoveEval next = evalTo(lo + 1);
        if (next.deviationMm > opt_.deviationBudgetMm) break;
        ++lo;
        e = next;
      }
    } else {
      size_t hi = lo;
      lo = i_ + 1;
      e = lo == hi ? e : evalTo(lo);
      if (e.deviationMm > opt_.deviationBudgetMm) return false;
      while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        const MoveEval m = evalTo(mid);
        if (m.deviationMm <= opt_.deviationBudgetMm) { lo = mid; e = m; } else { hi = mid; }
      }
    }
    double length = (pts_[i_ + 1] - cur_).norm();
    for (size_t k = i_ + 1; k < lo; ++k) length += (pts_[k + 1] - pts_[k]).norm();
    push(qs_[lo], trigAt(lo), pts_[lo], e, length);
    i_ = lo;
    hintMm_ = kInfinity;
    return true;
  }

  // Even the next vertex is too far: the longest prefix of this straight segment that fits.
  // The deviation of a short joint-linear move from its chord grows with the square of its
  // length, so each try predicts the piece that uses kSplitTarget of the budget: about one
  // sampled test per piece once the first piece of a segment is found.
  bool splitSegment() {
    const Vec2 a = cur_, b = pts_[i_ + 1];
    const double length = (b - a).norm();
    const double budget = opt_.deviationBudgetMm;
    // Waypoints inside the segment go off the line against the side the last piece bowed to
    // (SegmentationOptions::waypointOffsetShare); the first piece of a segment shows the side.
    const Vec2 normal = length > 0.0 ? Vec2(Vec2(-(b - a).y(), (b - a).x()) / length) : Vec2(Vec2::Zero());
    double offsetMm = std::isfinite(hintMm_) ? -bowSide_ * opt_.waypointOffsetShare * budget : 0.0;
    double t = std::isfinite(hintMm_) ? std::min(1.0, hintMm_ / length) : 1.0;
    JointAngles q;
    Vec2 target;
    auto tryAt = [&](double u, JointAngles& qOut, Vec2& targetOut) {
      targetOut = a + u * (b - a) + (u < 1.0 ? offsetMm : 0.0) * normal;
      const auto qx = unwrappedIk(g_, mode_, targetOut, qcur_);
      if (!qx) return MoveEval{};
      qOut = roundedAngles(*qx, opt_.angleDecimalsDeg);
      const Vec2 piece[2] = {a, a + u * (b - a)};  // measured against the line itself
      return evaluateMove(g_, assembly_, qcur_, trigCur_, qOut, piece);
    };
    // Length factor towards kSplitTarget of the budget: the deviation of a short move grows with
    // the square of its length; with offset waypoints its bow does, aimed at the budget plus the
    // offset (the curve then spans -offset .. budget around the line).
    const auto towardsTarget = [&](const MoveEval& e, double lo, double hi) {
      if (offsetMm == 0.0 || !std::isfinite(e.deviationMm)) return growth(e.deviationMm, lo, hi);
      if (!(e.bowMm > 0.0)) return hi;
      const double aim = kSplitTarget * budget + std::abs(offsetMm);
      return std::clamp(std::sqrt(aim / e.bowMm), lo, hi) *
             (e.deviationMm > budget ? std::min(1.0, std::sqrt(budget / e.deviationMm)) : 1.0);
    };
    MoveEval e = tryAt(t, q, target);
    while (!(e.deviationMm <= budget)) {
      t *= std::min(0.9, towardsTarget(e, 0.25, 0.9));
      if (offsetMm != 0.0 && t * length < 0.25 * hintMm_) {  // the offset does not pay here
        offsetMm = 0.0;
        t = std::min(1.0, hintMm_ / length);
      }
      if (t * length < opt_.minPieceMm) {
        out_.status = SegmentStatus::CannotFollow;
        out_.failedAt = a;
        return false;
      }
      e = tryAt(t, q, target);
    }
    if (t < 1.0 && e.deviationMm < kSplitGrowBelow * budget) {  // clearly short: one longer try
      JointAngles q2;
      Vec2 target2;
      const double t2 = std::min(1.0, t * towardsTarget(e, 1.0, 2.0));
      const MoveEval e2 = tryAt(t2, q2, target2);
      if (e2.deviationMm <= budget) t = t2, e = e2, q = q2, target = target2;
    }
    if (t >= 1.0) {  // the rest of the segment fits: the waypoint is vertex i+1 itself
      push(q, trigOf(b, q), b, e, length);
      ++i_;
      hintMm_ = kInfinity;
      bowSide_ = 0;
      return true;
    }
    push(q, trigOf(target, q), target, e, t * length);
    cur_ = a + t * (b - a);  // the stroke goes on from the point on the line
    // The next piece is predicted to use kSplitTarget of the budget too.
    hintMm_ = t * length * towardsTarget(e, 0.5, 1.5);
    bowSide_ = e.bowSide;
    return true;
  }

  // Length factor that brings a piece of deviation `deviationMm` to kSplitTarget of the budget
  // (deviation ~ length^2), clamped to [lo, hi].
  double growth(double deviationMm, double lo, double hi) const {
    if (!std::isfinite(deviationMm) || deviationMm <= 0.0) return deviationMm <= 0.0 ? hi : lo;
    return std::clamp(std::sqrt(kSplitTarget * opt_.deviationBudgetMm / deviationMm), lo, hi);
  }

  void push(const JointAngles& q, const MotorTrig& trig, const Vec2& p, const MoveEval& e,
            double length) {
    out_.waypoints.push_back({q, p, e.deviationMm, length, e.peakSpeedMmPerUnit});
    out_.maxDeviationMm = std::max(out_.maxDeviationMm, e.deviationMm);
    cur_ = p;
    qcur_ = q;
    trigCur_ = trig;
  }

  const Geometry& g_;
  WorkingMode mode_;
  AssemblyMode assembly_;
  const std::vector<Vec2>& pts_;
  const std::vector<JointAngles>& qs_;
  const SegmentationOptions& opt_;
  SegmentedStroke& out_;
  const MotorTrig* trig_ = nullptr;  // cosines and sines of qs_ (thread-local storage)
  size_t i_ = 0;
  Vec2 cur_;
  JointAngles qcur_;
  MotorTrig trigCur_;
  std::vector<Vec2> chain_;
  double hintMm_ = kInfinity;  // length of the last split piece (mm), infinite after a vertex
  int bowSide_ = 0;            // side the last split piece bowed to (MoveEval::bowSide)
};

}  // namespace

double jointMoveDeviation(const Geometry& g, AssemblyMode assembly, const JointAngles& qa,
                          const JointAngles& qb, std::span<const Vec2> chain) {
  return evaluateMove(g, assembly, qa, MotorTrig::of(qa), qb, chain).deviationMm;
}

SegmentedStroke segmentStroke(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                              std::span<const Vec2> stroke, const JointAngles& reference,
                              const SegmentationOptions& options) {
  SegmentedStroke out;
  thread_local std::vector<Vec2> pts;  // scratch, reused by every stroke of the thread
  thread_local std::vector<JointAngles> qs;
  withoutDuplicates(stroke, pts);
  if (pts.empty()) return out;
  if (!solveAll(g, mode, pts, reference, qs, out, options.angleDecimalsDeg)) return out;
  out.waypoints.reserve(pts.size());
  out.waypoints.push_back({qs[0], pts[0], 0.0, 0.0});
  if (options.angleDecimalsDeg >= 0) {  // where the rounded angles put the pen down (a dot: all)
    const FkResult fk = forward(g, qs[0], assembly);
    out.maxDeviationMm = fk.ok() ? (fk.p - pts[0]).norm() : kInfinity;
  }
  Segmenter(g, mode, assembly, pts, qs, options, out).run();
  return out;
}

SegmentedStroke segmentFixedLength(const Geometry& g, WorkingMode mode, AssemblyMode assembly,
                                   std::span<const Vec2> stroke, const JointAngles& reference,
                                   double stepMm) {
  SegmentedStroke out;
  std::vector<Vec2> pts;
  std::vector<JointAngles> qs;
  withoutDuplicates(stroke, pts);
  if (pts.empty()) return out;
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
