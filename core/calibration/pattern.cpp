// SPDX-License-Identifier: GPL-3.0-or-later
// makeCalibrationPattern: candidate points over the safe area, backlash rows at fixed asymmetric
// places, grid marks by farthest-point sampling (edge first); planCalibrationPattern: the one
// planner plus the checked approach moves. Design: docs/calibration-pattern.md.
#include "core/calibration/pattern.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/calibration/pattern_checks.hpp"
#include "core/calibration/stroke_digits.hpp"
#include "core/kinematics/singularity.hpp"
#include "core/planning/feeds.hpp"
#include "core/planning/safety.hpp"
#include "core/planning/time_estimate.hpp"
#include "core/planning/time_optimal.hpp"
#include "core/workspace/workspace.hpp"

namespace fivebar {
namespace {

using pattern_detail::discIsSafe;
using pattern_detail::safePose;

constexpr double kCandidateStepMm = 3.0;     // spacing of the candidate mark centres
constexpr double kAngleRoundingDeg = 0.01;   // mark poses are round numbers of degrees
constexpr int kRingPoints = 36;              // polyline points of a ring
constexpr double kPoseRoundTripRad = 1e-9;   // IK(FK(q)) must give q back (same branch)
constexpr int kMaxMarks = 99;                // two-digit numbers
constexpr double kMaxJumpRad = kPi - 0.2;    // largest motor change between drawn items
// Where the backlash rows go, as fractions of the candidates' bounding box: chosen so that no
// mirror image or half turn of the pattern maps a row onto another row (the scan relies on it).
constexpr std::array<std::array<double, 2>, 4> kRowAnchors1{{{0.22, 0.30}, {0.62, 0.72}, {0.40, 0.88}, {0.85, 0.15}}};
constexpr std::array<std::array<double, 2>, 4> kRowAnchors2{{{0.78, 0.52}, {0.38, 0.22}, {0.12, 0.70}, {0.55, 0.45}}};

double roundedRad(double angleRad) {
  return radFromDeg(std::round(degFromRad(angleRad) / kAngleRoundingDeg) * kAngleRoundingDeg);
}

double sign(Approach a) { return a == Approach::Plus ? 1.0 : -1.0; }

// The excursion pose before a dot: approachRad against each motor's approach direction.
JointAngles excursionOf(const JointAngles& q, Approach a1, Approach a2, double approachRad) {
  return {q.theta1 - sign(a1) * approachRad, q.theta2 - sign(a2) * approachRad};
}

class Builder {
 public:
  Builder(const MachineProfile& p, const PatternOptions& o) : p_(p), o_(o), mode_(p.defaultMode) {}

  PatternResult run() {
    PatternResult out;
    if (!(o_.ringRadiusMm > 0.0) || !(o_.minSpacingMm > 2.0 * o_.ringRadiusMm) ||
        !(o_.approachRad > 0.0) || o_.gridMarks < kMinPatternMarks ||
        o_.gridMarks + 3 * o_.backlashRowsPerMotor * 2 > kMaxMarks || o_.backlashRowsPerMotor < 0 ||
        o_.backlashRowsPerMotor > static_cast<int>(kRowAnchors1.size())) {
      out.error = FB_TR("CalibrationPattern", "pattern options out of range");
      return out;
    }
    CalibrationPattern pat;
    pat.mode = mode_;
    pat.ringRadiusMm = o_.ringRadiusMm;
    if (o_.accuracyLines) pat.accuracy = placeAccuracyPattern(p_);
    accuracy_ = pat.accuracy;
    candidates(pat.accuracy);
    if (cands_.empty()) {
      out.error = std::move(Message(FB_TR("CalibrationPattern", "no point of the working area (mode %1) has room for a mark"))
                                .arg(std::string(toString(mode_))));
      return out;
    }
    std::vector<PatternMark> rows;
    for (int motor : {1, 2})
      for (int r = 0; r < o_.backlashRowsPerMotor; ++r) {
        const auto& a = motor == 1 ? kRowAnchors1[r] : kRowAnchors2[r];
        addRow(motor, Vec2(lo_.x() + a[0] * (hi_.x() - lo_.x()), lo_.y() + a[1] * (hi_.y() - lo_.y())), rows);
      }
    std::vector<PatternMark> grid = farthestPoints();
    if (static_cast<int>(grid.size()) < kMinPatternMarks) {
      out.error = std::move(Message(FB_TR("CalibrationPattern",
                                          "only %1 marks fit %2 mm apart in the working area; at least %3 are needed"))
                                .arg(grid.size())
                                .arg(o_.minSpacingMm, 1)
                                .arg(kMinPatternMarks));
      return out;
    }
    number(grid);
    int id = 0;
    for (PatternMark& m : grid) m.id = ++id;
    int group = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
      rows[i].id = ++id;
      if (rows[i].rowIndex == 0) ++group;
      rows[i].group = group;
    }
    pat.marks = std::move(grid);
    pat.marks.insert(pat.marks.end(), rows.begin(), rows.end());
    if (!strokes(pat, out.error)) return out;
    out.pattern = std::move(pat);
    return out;
  }

 private:
  struct Candidate {
    Vec2 p;
    double minDist2 = std::numeric_limits<double>::infinity();
  };

  // A mark at `q` with this approach whose ring, number and approach are safe; nullopt if not.
  std::optional<PatternMark> markAt(const JointAngles& qIn, Approach a1, Approach a2) const {
    const JointAngles q{roundedRad(qIn.theta1), roundedRad(qIn.theta2)};
    const FkResult fk = forward(p_.geometry, q, p_.assembly);
    if (!fk.ok()) return std::nullopt;
    const std::optional<JointAngles> back = safePose(p_, mode_, fk.p);
    if (!back || std::abs(back->theta1 - q.theta1) > kPoseRoundTripRad ||
        std::abs(back->theta2 - q.theta2) > kPoseRoundTripRad)
      return std::nullopt;
    if (!discIsSafe(p_, mode_, fk.p, o_.clearanceMm)) return std::nullopt;
    if (!checkJointMove(p_, q, excursionOf(q, a1, a2, o_.approachRad)).ok()) return std::nullopt;
    PatternMark m;
    m.q = q;
    m.nominalMm = fk.p;
    m.approach1 = a1;
    m.approach2 = a2;
    return m;
  }

  void candidates(const std::optional<AccuracyPattern>& accuracy) {
    const Geometry& g = p_.geometry;
    const double longSide = 2.0 * std::max(g.a1 + g.b1, g.a2 + g.b2) + g.w;
    const GridSpec grid = gridCovering(g, std::max(8, static_cast<int>(longSide / kCandidateStepMm)));
    const WorkspaceMap map = computeMap(g, workspaceSettings(p_), mode_, grid, 1);
    lo_ = Vec2::Constant(std::numeric_limits<double>::infinity());
    hi_ = -lo_;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix) {
        if (!map.safe(grid.index(ix, iy))) continue;
        const Vec2 c(grid.xCenter(ix), grid.yCenter(iy));
        if (accuracy && nearLines(*accuracy, c)) continue;
        const std::optional<JointAngles> q = safePose(p_, mode_, c);
        if (!q || !markAt(*q, Approach::Plus, Approach::Plus)) continue;
        cands_.push_back({c});
        lo_ = lo_.cwiseMin(c);
        hi_ = hi_.cwiseMax(c);
      }
  }

  bool nearLines(const AccuracyPattern& a, const Vec2& c) const {
    const double keep = o_.clearanceMm + 2.0;
    for (const AccuracyLine& l : a.lines) {
      const Vec2 d = l.endMm - l.startMm;
      const double t = std::clamp((c - l.startMm).dot(d) / d.squaredNorm(), 0.0, 1.0);
      if ((l.startMm + t * d - c).norm() < keep) return true;
    }
    return false;
  }

  bool farFromChosen(const Vec2& p) const {
    for (const Vec2& c : chosen_)
      if ((c - p).norm() < o_.minSpacingMm) return false;
    return true;
  }

  // A row of three marks along motor `motor` near `anchor`: the middle one approached with that
  // motor reversed. Skipped (no row) when no candidate near the anchor can hold it.
  void addRow(int motor, const Vec2& anchor, std::vector<PatternMark>& rows) {
    std::vector<const Candidate*> byDistance;
    for (const Candidate& c : cands_) byDistance.push_back(&c);
    std::sort(byDistance.begin(), byDistance.end(), [&](const Candidate* a, const Candidate* b) {
      return (a->p - anchor).squaredNorm() < (b->p - anchor).squaredNorm();
    });
    for (const Candidate* c : byDistance) {
      const std::optional<JointAngles> q0 = safePose(p_, mode_, c->p);
      if (!q0) continue;
      const auto J = cartesianJacobian(p_.geometry, makePose(p_.geometry, *q0, c->p));
      if (!J) continue;
      const double lever = J->col(motor - 1).norm();  // mm per rad of this motor
      const double step = o_.minSpacingMm / lever;
      std::array<std::optional<PatternMark>, 3> row;
      bool ok = true;
      for (int i = 0; i < 3 && ok; ++i) {
        JointAngles q = *q0;
        (motor == 1 ? q.theta1 : q.theta2) += i * step;
        const Approach reversed = i == 1 ? Approach::Minus : Approach::Plus;
        row[i] = markAt(q, motor == 1 ? reversed : Approach::Plus, motor == 2 ? reversed : Approach::Plus);
        ok = row[i] && farFromChosen(row[i]->nominalMm) && !(accuracy_ && nearLines(*accuracy_, row[i]->nominalMm));
        if (ok && i > 0) ok = (row[i]->nominalMm - row[i - 1]->nominalMm).norm() >= o_.minSpacingMm * 0.99;
      }
      if (!ok) continue;
      for (int i = 0; i < 3; ++i) {
        row[i]->kind = MarkKind::Backlash;
        row[i]->motor = motor;
        row[i]->rowIndex = i;
        chosen_.push_back(row[i]->nominalMm);
        rows.push_back(*row[i]);
      }
      return;
    }
  }

  // Farthest-point sampling over the candidates, away from the marks already chosen: the first
  // picks lie on the edge of the area, later ones fill it.
  std::vector<PatternMark> farthestPoints() {
    Vec2 centroid = Vec2::Zero();
    for (const Candidate& c : cands_) centroid += c.p;
    centroid /= static_cast<double>(cands_.size());
    for (Candidate& c : cands_)
      for (const Vec2& x : chosen_) c.minDist2 = std::min(c.minDist2, (c.p - x).squaredNorm());
    std::vector<PatternMark> out;
    while (static_cast<int>(out.size()) < o_.gridMarks) {
      const Candidate* best = nullptr;
      double bestKey = -1.0;
      for (const Candidate& c : cands_) {
        // Without a chosen mark yet: the candidate farthest from the centroid.
        const double key = std::isinf(c.minDist2) ? (c.p - centroid).squaredNorm() : c.minDist2;
        if (key > bestKey) { bestKey = key; best = &c; }
      }
      if (!best || (!std::isinf(best->minDist2) && best->minDist2 < o_.minSpacingMm * o_.minSpacingMm)) break;
      const Vec2 pick = best->p;
      const std::optional<JointAngles> q = safePose(p_, mode_, pick);
      if (auto m = q ? markAt(*q, Approach::Plus, Approach::Plus) : std::nullopt) {
        out.push_back(*m);
        chosen_.push_back(m->nominalMm);
        for (Candidate& c : cands_) c.minDist2 = std::min(c.minDist2, (c.p - m->nominalMm).squaredNorm());
      } else {
        const_cast<Candidate*>(best)->minDist2 = 0.0;  // cannot hold a mark after rounding
      }
    }
    return out;
  }

  // Reading order: bands of minSpacing from the top, left to right in each band.
  void number(std::vector<PatternMark>& marks) const {
    std::stable_sort(marks.begin(), marks.end(), [&](const PatternMark& a, const PatternMark& b) {
      const double ba = std::floor((hi_.y() - a.nominalMm.y()) / o_.minSpacingMm);
      const double bb = std::floor((hi_.y() - b.nominalMm.y()) / o_.minSpacingMm);
      if (ba != bb) return ba < bb;
      return a.nominalMm.x() < b.nominalMm.x();
    });
  }

  // Drawing order: the planner draws each stroke at the turn of its motor angles nearest the
  // pose it comes from, so consecutive items must be less than half a turn apart in each motor
  // (else a far mark would be drawn a turn off, beyond a joint limit). A nearest-neighbour tour in
  // joint space (largest motor change) from the home pose, improved by 2-opt, keeps jumps short.
  std::vector<int> drawingOrder(const std::vector<JointAngles>& poses) const {
    auto jump = [](const JointAngles& a, const JointAngles& b) {
      return std::max(std::abs(a.theta1 - b.theta1), std::abs(a.theta2 - b.theta2));
    };
    const size_t n = poses.size();
    std::vector<int> order;
    std::vector<bool> used(n, false);
    JointAngles at = p_.homeAngles;
    for (size_t k = 0; k < n; ++k) {
      int best = -1;
      for (size_t i = 0; i < n; ++i)
        if (!used[i] && (best < 0 || jump(at, poses[i]) < jump(at, poses[static_cast<size_t>(best)])))
          best = static_cast<int>(i);
      used[static_cast<size_t>(best)] = true;
      order.push_back(best);
      at = poses[static_cast<size_t>(best)];
    }
    auto poseAt = [&](size_t k) { return k == 0 || k > n ? p_.homeAngles : poses[static_cast<size_t>(order[k - 1])]; };
    // 2-opt on the open tour from home; the cost of a jump grows with its fourth power, so that
    // the longest jumps shrink first.
    auto cost = [&](size_t a, size_t b) {
      if (b > n) return 0.0;  // the way back home is a checked travel, not a stroke
      const double j = jump(poseAt(a), poseAt(b));
      return j * j * j * j;
    };
    for (bool improved = true; improved;) {
      improved = false;
      for (size_t i = 1; i < n; ++i)
        for (size_t j = i + 1; j <= n; ++j) {
          const double before = cost(i - 1, i) + cost(j, j + 1);
          const double after = cost(i - 1, j) + cost(i, j + 1);
          if (after < before - 1e-9) {
            std::reverse(order.begin() + static_cast<long>(i - 1), order.begin() + static_cast<long>(j));
            improved = true;
          }
        }
    }
    return order;
  }

  bool strokes(CalibrationPattern& pat, Message& error) const {
    int path = 0;
    auto add = [&](std::vector<Vec2> pts) {
      Stroke s;
      s.points = std::move(pts);
      s.layerIndex = 0;
      s.pathIndex = path++;
      pat.strokes.push_back(std::move(s));
    };
    // Items: the marks, then the accuracy pattern as one item (at its centre's pose).
    std::vector<JointAngles> poses;
    for (const PatternMark& m : pat.marks) poses.push_back(m.q);
    if (pat.accuracy) {
      const Vec2 c = 0.5 * (pat.accuracy->lines.front().startMm + pat.accuracy->lines.back().endMm);
      poses.push_back(safePose(p_, mode_, c).value_or(p_.homeAngles));
    }
    const std::vector<int> order = drawingOrder(poses);
    JointAngles at = p_.homeAngles;
    for (int item : order) {
      const JointAngles& q = poses[static_cast<size_t>(item)];
      if (std::max(std::abs(q.theta1 - at.theta1), std::abs(q.theta2 - at.theta2)) >= kMaxJumpRad) {
        error = FB_TR("CalibrationPattern", "no drawing order keeps every move between marks under half a turn of a motor");
        return false;
      }
      at = q;
    }
    pat.dotStroke.assign(pat.marks.size(), -1);
    for (int item : order) {
      if (static_cast<size_t>(item) == pat.marks.size()) {
        bool forward = true;  // alternate directions: short travels
        for (const AccuracyLine& l : pat.accuracy->lines) {
          add(forward ? std::vector<Vec2>{l.startMm, l.endMm} : std::vector<Vec2>{l.endMm, l.startMm});
          forward = !forward;
        }
        continue;
      }
      const PatternMark& m = pat.marks[static_cast<size_t>(item)];
      std::vector<Vec2> ring;
      for (int k = 0; k <= kRingPoints; ++k) {
        const double a = 2.0 * kPi * (k % kRingPoints) / kRingPoints;
        ring.push_back(m.nominalMm + o_.ringRadiusMm * Vec2(std::cos(a), std::sin(a)));
      }
      add(std::move(ring));
      const Vec2 origin = m.nominalMm + Vec2(o_.ringRadiusMm + 1.0, -0.5 * o_.digitHeightMm);
      for (std::vector<Vec2>& d : digitStrokes(std::to_string(m.id), origin, o_.digitHeightMm))
        add(std::move(d));
      pat.dotStroke[static_cast<size_t>(item)] = static_cast<int>(pat.strokes.size());
      add({m.nominalMm});
    }
    return true;
  }

  const MachineProfile& p_;
  const PatternOptions& o_;
  WorkingMode mode_;
  std::vector<Candidate> cands_;
  std::vector<Vec2> chosen_;
  std::optional<AccuracyPattern> accuracy_;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
};

double approachFeedDuration(const MachineProfile& p, double dTheta1, double dTheta2, double lengthMm) {
  const FeedLimits limits = feedLimitsOf(p);
  double d = lengthMm / std::max(p.travelSpeedMmPerS, 1e-9);
  d = std::max(d, std::abs(dTheta1) / limits.maxSpeedRadPerS1);
  d = std::max(d, std::abs(dTheta2) / limits.maxSpeedRadPerS2);
  return std::max(d, limits.minSegmentDurationS);
}

}  // namespace

PatternResult makeCalibrationPattern(const MachineProfile& profile, const PatternOptions& options) {
  MachineProfile raw = profile;  // the raw machine, as planCalibrationPattern draws it
  raw.calibration.reset();
  return Builder(raw, options).run();
}

PlanResult planCalibrationPattern(const CalibrationPattern& pattern, const MachineProfile& calibrated,
                                  double approachRad) {
  Layer layer;
  layer.id = layer.name = "calibration pattern";
  const std::vector<Layer> layers{layer};
  PlanOptions options;
  options.optimise = false;  // marks in id order; each dot after its ring and number
  options.mode = pattern.mode;
  // The raw machine: no calibration applied (no backlash compensation, commanded = kinematic),
  // so the G-code angles are the marks' angles and the rows really reverse.
  MachineProfile profile = calibrated;
  profile.calibration.reset();
  PlanResult r = planStrokes(pattern.strokes, layers, profile, pattern.mode, options);
  if (!r.ok()) return r;
  std::vector<int> markOfStroke(pattern.strokes.size(), -1);
  for (size_t i = 0; i < pattern.dotStroke.size(); ++i) markOfStroke[static_cast<size_t>(pattern.dotStroke[i])] = static_cast<int>(i);
  PlannedJob& job = r.job;
  std::vector<JobMove> moves;
  moves.reserve(job.moves.size() + 2 * pattern.marks.size());
  std::vector<int> newIndex(job.moves.size() + 1, 0);
  for (size_t j = 0; j < job.moves.size(); ++j) {
    const JobMove& m = job.moves[j];
    const int mark = m.kind == JobMoveKind::PenDown && m.strokeIndex >= 0 ? markOfStroke[static_cast<size_t>(m.strokeIndex)] : -1;
    if (mark >= 0) {
      const PatternMark& pm = pattern.marks[static_cast<size_t>(mark)];
      const JointAngles q = m.target;
      const JointAngles e = excursionOf(q, pm.approach1, pm.approach2, approachRad);
      const MoveCheck check = checkJointMove(profile, q, e);
      if (!check.ok()) {
        r.status = PlanStatus::Infeasible;
        Message where = std::move(Message(FB_TR("CalibrationPattern", "approach of mark %1")).arg(pm.id));
        r.message = std::move(Message(FB_TR("CalibrationPattern", "%1: %2")).arg(where).arg(describeMove(check)));
        r.report.feasible = false;
        r.report.problems.push_back({where, check.where, describeMove(check), {}});
        return r;
      }
      const FkResult fe = forward(profile.geometry, e, profile.assembly);
      const double length = (fe.p - m.targetXY).norm();
      const double duration = approachFeedDuration(profile, e.theta1 - q.theta1, e.theta2 - q.theta2, length);
      const double jointFeed = std::hypot(e.theta1 - q.theta1, e.theta2 - q.theta2) / duration;
      for (const auto& [target, xy] : {std::pair{e, fe.p}, std::pair{q, m.targetXY}}) {
        JobMove t = m;
        t.kind = JobMoveKind::Travel;
        t.target = target;
        t.targetXY = xy;
        t.feedMmPerS = length / duration;
        t.jointFeedRadPerS = jointFeed;
        t.dwellS = 0.0;
        t.toolValue = 0.0;
        t.feedLimited = false;
        moves.push_back(t);
        job.summary.travelMm += length;
        job.summary.travelMoves += 1;
      }
      job.summary.minTypeIIMarginRad = std::min(job.summary.minTypeIIMarginRad, check.minTypeIIMarginRad);
    }
    newIndex[j] = static_cast<int>(moves.size());
    moves.push_back(m);
  }
  newIndex[job.moves.size()] = static_cast<int>(moves.size());
  for (PlannedStroke& s : job.strokes) s.firstMove = newIndex[static_cast<size_t>(s.firstMove)];
  job.moves = std::move(moves);
  fillJobTimes(job, profile);
  const std::vector<double> layerSpeeds{0.0};
  job.summary.timeOptimalS = timeOptimalJob(job, profile, layerSpeeds).totalS();
  r.report.estimatedTimeS = job.summary.estimatedTimeS;
  r.report.timeOptimalS = job.summary.timeOptimalS;
  r.report.travelMm = job.summary.travelMm;
  r.report.minSingularityMarginDeg = degFromRad(job.summary.minTypeIIMarginRad);
  return r;
}

PlanResult planVerificationPattern(const CalibrationPattern& pattern, const MachineProfile& profile) {
  Layer layer;
  layer.id = layer.name = "calibration pattern";
  PlanOptions options;
  options.optimise = false;  // the pattern's own order
  options.mode = pattern.mode;
  options.toleranceMm = kVerificationToleranceMm;
  return planStrokes(pattern.strokes, {layer}, profile, pattern.mode, options);
}

std::string patternSvg(const CalibrationPattern& pattern, double penWidthMm) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Stroke& s : pattern.strokes)
    for (const Vec2& p : s.points) {
      x0 = std::min(x0, p.x()); x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y()); y1 = std::max(y1, p.y());
    }
  const double m = 5.0;
  std::ostringstream out;
  out.precision(4);
  out << std::fixed;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << (x1 - x0 + 2 * m) << "mm\" height=\""
      << (y1 - y0 + 2 * m) << "mm\" viewBox=\"" << (x0 - m) << ' ' << (-y1 - m) << ' '
      << (x1 - x0 + 2 * m) << ' ' << (y1 - y0 + 2 * m) << "\">\n";
  out << "<!-- FiveBar Studio calibration pattern, machine frame in mm (y up: drawn with y negated) -->\n";
  out << "<g fill=\"none\" stroke=\"black\" stroke-width=\"" << penWidthMm
      << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (const Stroke& s : pattern.strokes) {
    if (s.points.size() == 1) {
      out << "<circle cx=\"" << s.points[0].x() << "\" cy=\"" << -s.points[0].y() << "\" r=\""
          << 0.5 * penWidthMm * 1.5 << "\" fill=\"black\" stroke=\"none\"/>\n";
      continue;
    }
    out << "<polyline points=\"";
    for (const Vec2& p : s.points) out << p.x() << ',' << -p.y() << ' ';
    out << "\"/>\n";
  }
  out << "</g>\n</svg>\n";
  return out.str();
}

std::optional<CalibrationPattern> accuracyOnlyPattern(const MachineProfile& profile) {
  const auto lines = placeAccuracyPattern(profile);
  if (!lines) return std::nullopt;
  CalibrationPattern pattern;
  pattern.accuracy = lines;
  pattern.mode = profile.defaultMode;
  for (const AccuracyLine& line : lines->lines) {
    Stroke s;
    s.points = {line.startMm, line.endMm};
    pattern.strokes.push_back(s);
  }
  return pattern;
}

}  // namespace fivebar
