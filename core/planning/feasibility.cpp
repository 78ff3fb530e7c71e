// SPDX-License-Identifier: GPL-3.0-or-later
// Job preflight and working-mode selection. Contract: feasibility.hpp.
#include "core/planning/feasibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/support/parallel.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/planning/placement.hpp"

namespace fivebar {
namespace {

// Points the quick fix search looks at (a stride sample of the job).
constexpr std::size_t kFixSamplePoints = 1500;
// Candidate scale factors tried for "shrink to fit", largest first.
constexpr int kShrinkSteps = 19;  // 0.95, 0.90, ... 0.05
// Anchor grid of the "move" search: cells per axis over the machine's reach box.
constexpr int kMoveGridCells = 32;
// Detour searches (planSafeTravel, up to tenths of a second each) one preflight may spend.
constexpr int kMaxDetourSearches = 16;
// Full preflight verifications a fix search may spend.
constexpr int kMaxFixVerifications = 3;

// A point of the job. The studio lists each problem under its layer (by name) and path, so
// there the point is named without them.
Message pointText(const Stroke& s, int k, const Vec2& p) {
  return FB_TR("Preflight", "layer %1 path %2 point %3 at (%4, %5) mm")
      .arg(s.layerIndex).arg(s.pathIndex).arg(k).arg(p.x(), 2).arg(p.y(), 2)
      .inStudio(FB_TR("Preflight", "point %1 at (%2, %3) mm").arg(k).arg(p.x(), 2).arg(p.y(), 2));
}

// What checking one stroke asks of the job-wide pass, in order: problems to add and travels
// to check (travel checks share the job's detour budget, so they run in job order). A travel
// `fromOutside` starts at the pose before the stroke (the previous stroke's end or home).
struct StrokeEvent {
  bool travel = false;
  bool fromOutside = false;
  JointAngles from, to;
  int pointIndex = 0;
  PreflightProblem problem;  // when !travel
};

// The result of checking one stroke on its own, assuming it starts from the home pose.
struct StrokePass {
  std::vector<StrokeEvent> events;
  std::optional<JointAngles> first;  // first reachable pose (unwrapped from the home pose)
  int firstIndex = -1;               // its point index
  std::optional<JointAngles> last;   // last reachable pose
  std::size_t points = 0;
  double minMarginRad = std::numeric_limits<double>::infinity();
};

// One pass over the job in one working mode; see preflight() for the contract. The costly part
// (inverse kinematics and move checks of every stroke) runs on the strokes in parallel, each as
// if it started from the home pose; a stroke is then merged in job order when its first pose is
// the one the job reaches it with (the usual case), or checked again in order otherwise, so the
// report does not depend on the threads.
class Preflight {
 public:
  Preflight(const MachineProfile& pr, WorkingMode mode, const PreflightOptions& o,
            FeasibilityReport& rep)
      : pr_(pr), g_(pr.geometry), mode_(mode), o_(o), rep_(rep),
        home_(o.home.value_or(kinematicFromCommanded(pr.calibration, pr.homeAngles))) {}

  void run(const std::vector<Stroke>& strokes) {
    std::optional<JointAngles> at;
    if (o_.includeHomeTravel) at = home_;
    std::vector<StrokePass> passes;
    for (std::size_t first = 0; first < strokes.size(); first += kChunkStrokes) {
      const std::size_t n = std::min(kChunkStrokes, strokes.size() - first);
      passes.assign(n, StrokePass{});
      parallelFor(n, planningThreads(), [&](std::size_t i) {
        checkStroke(strokes[first + i], static_cast<int>(first + i), passes[i]);
      });
      for (std::size_t i = 0; i < n; ++i) {
        const Stroke& s = strokes[first + i];
        const int si = static_cast<int>(first + i);
        if (!startsAsAssumed(s, passes[i], at)) {
          passes[i] = StrokePass{};
          checkStroke(s, si, passes[i], at.value_or(home_));
        }
        merge(s, si, passes[i], at);
      }
    }
    if (o_.includeHomeTravel && at && rep_.pointsChecked > 0) {
      static const Stroke kHome{{}, -1, -1, false};
      checkTravel(kHome, -1, 0, *at, home_);
    }
    rep_.feasible = rep_.problemCount == 0;
    if (!std::isfinite(rep_.minTypeIIMarginRad)) rep_.minTypeIIMarginRad = 0.0;
  }

 private:
  static constexpr std::size_t kChunkStrokes = 1024;

  // Checks stroke s on its own, the pose before it taken as `outside` (home by default).
  void checkStroke(const Stroke& s, int si, StrokePass& out) const { checkStroke(s, si, out, home_); }
  void checkStroke(const Stroke& s, int si, StrokePass& out, const JointAngles& outside) const {
    std::optional<JointAngles> at;  // the previous reachable pose of this stroke
    std::vector<JointAngles> poses;
    std::vector<int> index;  // point index of each pose
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const JointAngles& ref = poses.empty() ? at.value_or(outside) : poses.back();
      const int kk = static_cast<int>(k);
      std::optional<PreflightProblem> pending;  // set when jointsOf returns nullopt
      const auto q = jointsOf(s, si, kk, ref, poses.empty(), pending);
      if (!q) {  // unreachable point: check the run so far, start a new one after it
        checkRun(s, si, poses, index, out);
        problem(out, std::move(*pending));
        poses.clear();
        index.clear();
        continue;
      }
      ++out.points;
      if (!out.first) out.first = *q, out.firstIndex = kk;
      if (poses.empty() && checkPose(pr_, *q).ok())
        out.events.push_back({true, !at.has_value(), at.value_or(outside), *q, kk, {}});
      poses.push_back(*q);
      index.push_back(kk);
      at = *q;
    }
    checkRun(s, si, poses, index, out);
    out.last = at;
  }

  // Whether the stroke's first reachable pose, unwrapped from the pose the job is at, is the
  // one the stroke was checked with.
  bool startsAsAssumed(const Stroke& s, const StrokePass& pass, const std::optional<JointAngles>& at) const {
    if (!pass.first) return true;
    const IkResult ik = penInverse(pr_, s.points[static_cast<std::size_t>(pass.firstIndex)], mode_);
    if (!ik.ok()) return false;
    const JointAngles q = nearWithinLimits(pr_, ik.angles, at.value_or(home_));
    return q.theta1 == pass.first->theta1 && q.theta2 == pass.first->theta2;
  }

  void merge(const Stroke& s, int si, StrokePass& pass, std::optional<JointAngles>& at) {
    for (StrokeEvent& e : pass.events) {
      if (!e.travel) {
        add(std::move(e.problem));
      } else if (!e.fromOutside) {
        checkTravel(s, si, e.pointIndex, e.from, e.to);
      } else if (at) {
        checkTravel(s, si, e.pointIndex, *at, e.to);
      }
    }
    rep_.pointsChecked += pass.points;
    rep_.minTypeIIMarginRad = std::min(rep_.minTypeIIMarginRad, pass.minMarginRad);
    if (pass.last) at = pass.last;
  }

  // Continuous joint angles of point k, unwrapped near `ref`; reports reach and assembly
  // problems (in `pending`) and returns nullopt for them.
  std::optional<JointAngles> jointsOf(const Stroke& s, int si, int k, const JointAngles& ref,
                                      bool strokeStart, std::optional<PreflightProblem>& pending) const {
    const Vec2& p = s.points[k];
    Vec2 distal = p;  // P, where the pen is at p
    const IkResult ik = penInverse(pr_, p, mode_, &distal);
    if (!ik.ok()) {
      const bool leg1 = unreachableLeg(g_, calibratedPenOffset(pr_), p, mode_) == 1;
      pending = PreflightProblem{si, s.layerIndex, s.pathIndex, k, MoveKind::Point, p,
                                 MoveStatus::CannotClose,
                                 FB_TR("Preflight", "%1 is out of reach of leg %2")
                                     .arg(pointText(s, k, p)).arg(leg1 ? 1 : 2)};
      return std::nullopt;
    }
    JointAngles q{unwrapNear(ik.angles.theta1, ref.theta1), unwrapNear(ik.angles.theta2, ref.theta2)};
    if (strokeStart) q = nearWithinLimits(pr_, ik.angles, ref);
    if (assemblyModeOf(makePose(g_, q, distal)) != pr_.assembly) {
      const AssemblyMode other =
          pr_.assembly == AssemblyMode::Plus ? AssemblyMode::Minus : AssemblyMode::Plus;
      pending = PreflightProblem{si, s.layerIndex, s.pathIndex, k, MoveKind::Point, p,
                                 MoveStatus::AssemblyChange,
                                 FB_TR("Preflight", "%1 needs assembly mode %2 in working mode %3")
                                     .arg(pointText(s, k, p)).arg(toString(other)).arg(toString(mode_))};
      return std::nullopt;
    }
    return q;
  }

  static void problem(StrokePass& out, PreflightProblem p) {
    StrokeEvent e;
    e.problem = std::move(p);
    out.events.push_back(std::move(e));
  }

  // Pen-down moves through consecutive reachable points of one stroke.
  void checkRun(const Stroke& s, int si, const std::vector<JointAngles>& poses,
                const std::vector<int>& index, StrokePass& out) const {
    if (poses.empty()) return;
    const PathCheck c = checkJointPath(pr_, poses);
    out.minMarginRad = std::min(out.minMarginRad, c.minTypeIIMarginRad);
    for (const PathProblem& p : c.problems) {
      if (p.move == 0 && p.check.atFraction == 0.0) {
        const int k = index[0];
        problem(out, {si, s.layerIndex, s.pathIndex, k, MoveKind::Point, s.points[k], p.check.status,
                      FB_TR("Preflight", "%1: %2").arg(pointText(s, k, s.points[k])).arg(describeMove(p.check))});
      } else {
        const int k = index[p.move + 1];
        problem(out, {si, s.layerIndex, s.pathIndex, k, MoveKind::Draw, p.check.where, p.check.status,
                      FB_TR("Preflight", "the line to %1 %2").arg(pointText(s, k, s.points[k]))
                          .arg(describeMove(p.check))});
      }
    }
  }

  void checkTravel(const Stroke& s, int si, int k, const JointAngles& from, const JointAngles& to) {
    const MoveCheck c = checkJointMove(pr_, from, to);
    if (c.ok()) {
      rep_.minTypeIIMarginRad = std::min(rep_.minTypeIIMarginRad, c.minTypeIIMarginRad);
      return;
    }
    const bool searched = o_.allowTravelDetours && detourSearches_ < kMaxDetourSearches;
    if (searched) {
      ++detourSearches_;
      if (planSafeTravel(pr_, from, to)) return;
    }
    const Message target = si < 0 ? FB_TR("Preflight", "the travel back to the home pose")
                                   : FB_TR("Preflight", "the travel to %1").arg(pointText(s, k, s.points[k]));
    Message reason = FB_TR("Preflight", "%1 %2").arg(target).arg(describeMove(c));
    if (searched)
      reason = FB_TR("Preflight", "%1; no safe detour found").arg(std::move(reason));
    else if (o_.allowTravelDetours)
      reason = FB_TR("Preflight", "%1; detour not searched (limit of searches per job reached)")
                   .arg(std::move(reason));
    add({si, s.layerIndex, s.pathIndex, k, MoveKind::Travel, c.where, c.status, std::move(reason)});
  }

  void add(PreflightProblem problem) {
    ++rep_.problemCount;
    if (rep_.problems.size() < o_.maxListedProblems) rep_.problems.push_back(std::move(problem));
  }

  const MachineProfile& pr_;
  const Geometry& g_;
  WorkingMode mode_;
  const PreflightOptions& o_;
  FeasibilityReport& rep_;
  JointAngles home_;
  int detourSearches_ = 0;
};

// A sample of the job's points for the quick fix search: the four extreme points first (they
// reject most candidates at once), then a stride sample in job order.
std::vector<Vec2> samplePoints(const std::vector<Stroke>& strokes) {
  std::size_t total = 0;
  for (const Stroke& s : strokes) total += s.points.size();
  const std::size_t stride = std::max<std::size_t>(1, total / kFixSamplePoints);
  std::vector<Vec2> out;
  std::array<Vec2, 4> extreme;
  for (const Stroke& s : strokes)
    if (!s.points.empty()) {
      extreme.fill(s.points.front());
      break;
    }
  for (const Stroke& s : strokes)
    for (const Vec2& p : s.points) {
      if (p.x() < extreme[0].x()) extreme[0] = p;
      if (p.x() > extreme[1].x()) extreme[1] = p;
      if (p.y() < extreme[2].y()) extreme[2] = p;
      if (p.y() > extreme[3].y()) extreme[3] = p;
    }
  out.assign(extreme.begin(), extreme.end());
  std::size_t i = 0;
  for (const Stroke& s : strokes)
    for (const Vec2& p : s.points)
      if (i++ % stride == 0) out.push_back(p);
  return out;
}

// Quick necessary check: every sampled point of the transformed job has a safe pose.
bool quickOk(const std::vector<Vec2>& pts, const MachineProfile& pr, WorkingMode mode,
             const JointAngles& home, double scale, const Vec2& anchor, const Vec2& newAnchor) {
  JointAngles ref = home;
  for (const Vec2& p0 : pts) {
    const Vec2 p = newAnchor + scale * (p0 - anchor);
    Vec2 distal = p;
    const IkResult ik = penInverse(pr, p, mode, &distal);
    if (!ik.ok()) return false;
    const JointAngles q = nearWithinLimits(pr, ik.angles, ref);
    if (assemblyModeOf(makePose(pr.geometry, q, distal)) != pr.assembly) return false;
    if (!checkPose(pr, q).ok()) return false;
    ref = q;
  }
  return true;
}

std::vector<Stroke> transformed(std::vector<Stroke> strokes, double scale, const Vec2& anchor,
                                const Vec2& newAnchor) {
  for (Stroke& s : strokes)
    for (Vec2& p : s.points) p = newAnchor + scale * (p - anchor);
  return strokes;
}

bool fullOk(const std::vector<Stroke>& strokes, const MachineProfile& pr, WorkingMode mode,
            PreflightOptions o) {
  o.suggestFixes = false;
  o.maxListedProblems = 0;
  return preflight(strokes, pr, mode, o).feasible;
}

void suggestFixes(const std::vector<Stroke>& strokes, const MachineProfile& pr, WorkingMode mode,
                  const PreflightOptions& o, FeasibilityReport& rep) {
  const auto box = strokeBounds(strokes);
  if (!box) return;
  const Vec2 anchor = o.anchorMm.value_or(box->center());
  const JointAngles home = o.home.value_or(kinematicFromCommanded(pr.calibration, pr.homeAngles));
  const std::vector<Vec2> pts = samplePoints(strokes);
  int budget = kMaxFixVerifications;
  for (int i = 1; i <= kShrinkSteps && budget > 0; ++i) {
    const double s = 1.0 - 0.05 * i;
    if (!quickOk(pts, pr, mode, home, s, anchor, anchor)) continue;
    --budget;
    if (fullOk(transformed(strokes, s, anchor, anchor), pr, mode, o)) {
      rep.shrinkFactor = s;
      break;
    }
  }
  // Move: anchors on a grid over the reach box, nearest to the current anchor first.
  const Geometry& g = pr.geometry;
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2);
  const double x0 = -0.5 * g.w - reach, x1 = 0.5 * g.w + reach, y0 = -reach, y1 = reach;
  std::vector<Vec2> candidates;
  for (int j = 0; j <= kMoveGridCells; ++j)
    for (int i = 0; i <= kMoveGridCells; ++i)
      candidates.emplace_back(x0 + (x1 - x0) * i / kMoveGridCells, y0 + (y1 - y0) * j / kMoveGridCells);
  std::sort(candidates.begin(), candidates.end(), [&](const Vec2& a, const Vec2& b) {
    return (a - anchor).squaredNorm() < (b - anchor).squaredNorm();
  });
  budget = kMaxFixVerifications;
  for (const Vec2& c : candidates) {
    if (budget == 0) break;
    if (!quickOk(pts, pr, mode, home, 1.0, anchor, c)) continue;
    --budget;
    if (fullOk(transformed(strokes, 1.0, anchor, c), pr, mode, o)) {
      rep.suggestedAnchorMm = c;
      break;
    }
  }
}

}  // namespace

Message FeasibilityReport::summaryMessage() const {
  if (feasible)
    return FB_TR("Preflight", "mode %1: feasible, worst type II margin %2 deg")
        .arg(toString(mode)).arg(degFromRad(minTypeIIMarginRad), 1);
  Message out = problemCount == 1 ? FB_TR("Preflight", "mode %1: 1 problem").arg(toString(mode))
                                  : FB_TR("Preflight", "mode %1: %2 problems").arg(toString(mode)).arg(problemCount);
  if (!problems.empty()) out = FB_TR("Preflight", "%1 (first: %2)").arg(std::move(out)).arg(problems.front().reason);
  if (shrinkFactor)
    out = FB_TR("Preflight", "%1; fix: shrink to %2%").arg(std::move(out)).arg(100.0 * *shrinkFactor, 0);
  if (suggestedAnchorMm)
    out = FB_TR("Preflight", "%1; fix: move the centre to (%2, %3) mm")
              .arg(std::move(out)).arg(suggestedAnchorMm->x(), 1).arg(suggestedAnchorMm->y(), 1);
  return out;
}

std::string FeasibilityReport::summary() const { return summaryMessage().text(); }

FeasibilityReport preflight(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                            WorkingMode mode, const PreflightOptions& options) {
  FeasibilityReport rep;
  rep.mode = mode;
  rep.minTypeIIMarginRad = std::numeric_limits<double>::infinity();
  Preflight(profile, mode, options, rep).run(strokes);
  if (!rep.feasible && options.suggestFixes) suggestFixes(strokes, profile, mode, options, rep);
  return rep;
}

ModeChoice chooseMode(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                      const PreflightOptions& options, const std::vector<WorkingMode>& candidates) {
  ModeChoice choice;
  double best = -1.0;
  for (WorkingMode m : candidates) {
    choice.reports.push_back(preflight(strokes, profile, m, options));
    const FeasibilityReport& r = choice.reports.back();
    if (r.feasible && r.minTypeIIMarginRad > best) {
      best = r.minTypeIIMarginRad;
      choice.mode = m;
    }
  }
  return choice;
}

}  // namespace fivebar
