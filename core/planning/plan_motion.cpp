// planStrokes: placed strokes -> PlannedJob (segmentation, feeds, travel, tool commands, timing).
#include <algorithm>
#include <cmath>
#include <atomic>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <limits>
#include <optional>

#include "core/planning/backlash_compensation.hpp"
#include "core/planning/feeds.hpp"
#include "core/support/memory_hint.hpp"
#include "core/kinematics/move_samples.hpp"
#include "core/machine/pen_kinematics.hpp"
#include "core/support/parallel.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/safety.hpp"
#include "core/planning/segmentation.hpp"
#include "core/kinematics/singularity.hpp"
#include "core/planning/time_estimate.hpp"
#include "core/planning/time_optimal.hpp"

namespace fivebar {
namespace {

// Strokes segmented in parallel before being drawn in order (bounds the memory held).
constexpr size_t kChunkStrokes = 2048;
// FK samples per travel move for its XY length.
constexpr int kTravelLengthSamples = 16;
// Lever arm factor of the older estimate of the G-code rounding error, used when it is smaller
// than the bound from the type II margin (gcodeRoundingBoundMm).
constexpr double kRoundingLeverFactor = 4.0;
// Decimals of a degree of the G-code angles (GcodeOptions::angleDecimals, core/output/gcode.hpp):
// the segmentation measures its moves between angles rounded so.
constexpr int kGcodeAngleDecimals = 4;

Message layerLabel(const std::vector<Layer>& layers, int layerIndex) {
  if (layerIndex >= 0 && static_cast<size_t>(layerIndex) < layers.size()) {
    const Layer& l = layers[static_cast<size_t>(layerIndex)];
    return FB_TR("Planner", "layer '%1'").arg(l.name.empty() ? l.id : l.name);
  }
  return FB_TR("Planner", "layer %1").arg(layerIndex);
}

// The fixes of a stroke the planner cannot draw.
std::vector<PlanFix> strokeFixes() { return {{FixKind::MoveOrShrink}, {FixKind::TryAnotherMode}}; }

class MotionPlanner {
 public:
  MotionPlanner(const std::vector<Stroke>& strokes, const std::vector<Layer>& layers,
                const MachineProfile& profile, WorkingMode mode, const PlanOptions& options,
                PlanResult& out)
      : strokes_(strokes), layers_(layers), p_(profile), g_(profile.geometry), mode_(mode),
        opt_(options), out_(out), job_(out.job), pen_(calibratedPenOffset(profile)) {
    limits_ = feedLimitsOf(profile);
    limits_.minSegmentDurationS = options.minSegmentDurationS;
  }

  // exactBudgetMm: the joint-linear budget of a stroke whose points are its geometry;
  // flattenedBudgetMm: of a stroke of flattened curves (Stroke::flattened).
  void run(double exactBudgetMm, double flattenedBudgetMm) {
    segExact_.deviationBudgetMm = distalBudgetMm(exactBudgetMm);
    segFlattened_.deviationBudgetMm = distalBudgetMm(flattenedBudgetMm);
    // The moves are measured between the angles as the G-code carries them.
    segExact_.angleDecimalsDeg = segFlattened_.angleDecimalsDeg = kGcodeAngleDecimals;
    job_.profileName = p_.name;
    job_.mode = mode_;
    job_.assembly = p_.assembly;
    if (!startPose()) return;
    job_.strokes.resize(strokes_.size());
    // One allocation for the moves in the usual case: a move per point at most when strokes are
    // merged, plus tool and travel moves (reserveMoves grows it when long lines are split).
    size_t points = 0;
    for (const Stroke& s : strokes_) points += s.points.size();
    job_.moves.reserve(points + 8 * strokes_.size());
    adviseHugePages(job_.moves.data(), job_.moves.capacity() * sizeof(JobMove));
    // Segmentation and feeds of a stroke do not depend on where the pen comes from (only the
    // turn its angles are unwrapped to, fixed up in drawStroke): chunks of strokes are
    // prepared by every free thread, the next chunk while this one is drawn in order (the
    // drawing thread joins in when it is done), so the job does not depend on the threads.
    const size_t helpers = static_cast<size_t>(std::max(1, planningThreads()));
    ChunkWork chunks[2];
    ChunkWork* cur = &chunks[0];
    ChunkWork* ahead = &chunks[1];
    if (!strokes_.empty()) {
      cur->reset(0, std::min(kChunkStrokes, strokes_.size()), job_.start);
      runChunk(*cur, helpers - 1);
    }
    for (size_t first = 0; first < strokes_.size(); first += kChunkStrokes) {
      if (cancelled()) return;
      const size_t nextFirst = first + kChunkStrokes;
      std::vector<std::future<void>> workers;
      if (nextFirst < strokes_.size()) {
        ahead->reset(nextFirst, std::min(kChunkStrokes, strokes_.size() - nextFirst),
                     cur->lastEnd());
        for (size_t t = 0; t < helpers; ++t)
          workers.push_back(std::async(std::launch::async, [this, ahead] { work(*ahead); }));
      }
      reserveMoves(cur->slots);
      for (size_t i = 0; i < cur->n; ++i) drawStroke(first + i, cur->slots[i]);
      if (!workers.empty()) {
        runChunk(*ahead, 0);
        for (std::future<void>& w : workers) w.get();
      }
      std::swap(cur, ahead);
    }
    if (cancelled()) return;
    if (penDown_) penUp();
    travelTo(job_.start, -1, -1, nullptr, [] { return FB_TR("Planner", "travel back to the start pose"); });
  }

 private:
  bool cancelled() const { return opt_.cancel != nullptr && opt_.cancel->load(); }

  bool startPose() {
    job_.start = kinematicFromCommanded(p_.calibration, p_.homeAngles);  // home is commanded
    const FkResult fk = forward(g_, job_.start, p_.assembly);
    if (!fk.ok()) {
      problem(FB_TR("Planner", "start pose"), Vec2::Zero(),
              FB_TR("Planner", "the profile's home pose does not close the linkage"),
              {PlanFix{FixKind::ReachableHomePose}});
      return false;
    }
    job_.startXY = penOf(job_.start, fk.p);
    at_ = job_.start;
    atXY_ = job_.startXY;
    return true;
  }

  // A stroke segmented (angles unwrapped near the home pose) with its feeds.
  // A pen-up travel between two poses: the safe joint path with its XY lengths and feeds.
  struct TravelPlan {
    JointAngles from, to;
    bool found = false;
    std::vector<JointWaypoint> chain;  // chain[0] = from
    std::vector<SegmentFeed> feeds;
  };

  struct Prepared {
    std::optional<TravelPlan> travel;  // from the previous stroke's end, planned ahead
    SegmentedStroke seg;
    std::vector<SegmentFeed> feeds;
    PathCheck check;  // every move of the stroke, as segmented (angles near the home pose)
    bool usable() const { return seg.ok() && !seg.waypoints.empty() && check.ok(); }
  };

  // One chunk of strokes prepared by whichever threads are free: each takes the next stroke; the
  // thread that completes the second of two neighbouring strokes also plans the travel between
  // them (as drawStroke will use it unless a stroke fails or moves by whole turns).
  struct ChunkWork {
    size_t first = 0, n = 0;
    std::vector<Prepared> slots;
    std::optional<JointAngles> before;  // end of the last usable stroke before the chunk
    std::unique_ptr<std::atomic<int>[]> pairs;  // pairs[i] == 2: strokes i-1 and i prepared
    std::atomic<size_t> next{0}, done{0};
    std::mutex errorMutex;
    std::exception_ptr error;

    void reset(size_t firstStroke, size_t count, std::optional<JointAngles> endBefore) {
      first = firstStroke;
      n = count;
      slots.assign(n, Prepared{});
      before = endBefore;
      pairs = std::make_unique<std::atomic<int>[]>(n);
      for (size_t i = 0; i < n; ++i) pairs[i].store(i == 0 ? 1 : 0);
      next.store(0);
      done.store(0);
      error = nullptr;
    }
    std::optional<JointAngles> lastEnd() const {
      for (size_t i = n; i-- > 0;)
        if (slots[i].usable()) return slots[i].seg.waypoints.back().q;
      return before;
    }
  };

  void work(ChunkWork& w) const {
    for (size_t i = w.next.fetch_add(1); i < w.n; i = w.next.fetch_add(1)) {
      try {
        prepare(w.first + i, w.slots[i]);
        if (w.pairs[i].fetch_add(1) == 1) travelInto(w, i);
        if (i + 1 < w.n && w.pairs[i + 1].fetch_add(1) == 1) travelInto(w, i + 1);
      } catch (...) {
        const std::lock_guard lock(w.errorMutex);
        if (!w.error) w.error = std::current_exception();
      }
      if (w.done.fetch_add(1) + 1 == w.n) w.done.notify_all();
    }
  }

  // Prepares the chunk on this thread and `extra` more, and waits until it is complete.
  void runChunk(ChunkWork& w, size_t extra) const {
    std::vector<std::future<void>> workers;
    for (size_t t = 0; t < extra; ++t)
      workers.push_back(std::async(std::launch::async, [this, &w] { work(w); }));
    work(w);
    for (size_t d = w.done.load(); d < w.n; d = w.done.load()) w.done.wait(d);
    for (std::future<void>& f : workers) f.get();
    if (w.error) std::rethrow_exception(w.error);
  }

  void travelInto(ChunkWork& w, size_t i) const {
    Prepared& p = w.slots[i];
    if (!p.usable()) return;
    const std::optional<JointAngles> from =
        i == 0 ? w.before
               : w.slots[i - 1].usable()
                     ? std::optional<JointAngles>(w.slots[i - 1].seg.waypoints.back().q)
                     : std::nullopt;
    if (from) p.travel = planTravel(*from, p.seg.waypoints.front().q);
  }

  void prepare(size_t k, Prepared& out) const {
    const Stroke& s = strokes_[k];
    if (s.points.empty()) return;
    SegmentationOptions so = s.flattened ? segFlattened_ : segExact_;
    so.deviationBudgetMm -= 0.5 * s.bridgedGapMm;  // the drawn bridge's share (strokes.hpp)
    if (pen_) {  // the pen is off P: segment the path of P that draws the pen's stroke
      Vec2 failedAt = Vec2::Zero();
      const auto distal = distalPath(g_, *pen_, mode_, s.points, &failedAt);
      if (!distal) {
        out.seg.status = SegmentStatus::OutOfReach;
        out.seg.failedAt = failedAt;
        return;
      }
      out.seg = segmentStroke(g_, mode_, p_.assembly, *distal, job_.start, so);
      if (!out.seg.ok()) {
        out.seg.failedAt = penOf(out.seg.failedAt);
        return;
      }
      for (JointWaypoint& w : out.seg.waypoints) w.p = penOf(w.q, w.p);
    } else {
      out.seg = segmentStroke(g_, mode_, p_.assembly, s.points, job_.start, so);
    }
    if (!out.seg.ok()) return;
    out.check = checkWaypoints(out.seg);
    // Feeds even when the check fails here: drawStroke may turn the stroke into the joint limits
    // (unwrapNearCurrent) and check it again; the feeds do not depend on the turn.
    out.feeds = planFeeds(g_, p_.assembly, out.seg.waypoints, drawSpeed(s.layerIndex), limits_);
  }

  // The safety rule on the moves that will be sent: every joint-linear move between waypoints.
  PathCheck checkWaypoints(const SegmentedStroke& seg) const {
    std::vector<JointAngles> poses;
    poses.reserve(seg.waypoints.size());
    for (const JointWaypoint& w : seg.waypoints) poses.push_back(w.q);
    return checkJointPath(p_, poses);
  }

  // Room for a chunk's moves (draws plus a few tool and travel moves per stroke), growing the
  // job geometrically so that the moves are not copied once per chunk.
  void reserveMoves(const std::vector<Prepared>& chunk) {
    size_t need = job_.moves.size();
    for (const Prepared& p : chunk) need += p.feeds.size() + 6;
    if (need > job_.moves.capacity()) {
      job_.moves.reserve(std::max(need, 2 * job_.moves.capacity()));
      adviseHugePages(job_.moves.data(), job_.moves.capacity() * sizeof(JobMove));
    }
  }

  // Shifts the stroke's angles by whole turns so that it starts nearest the current pose; when
  // that turn takes a motor of the stroke beyond its joint limits (on commanded angles), by the
  // nearest turn that keeps that motor's whole stroke inside them. Returns whether the angles
  // changed (joint limits then need a new check).
  bool unwrapNearCurrent(SegmentedStroke& seg) const {
    if (seg.waypoints.empty()) return false;
    const JointAngles q0 = seg.waypoints[0].q;
    JointAngles lo = q0, hi = q0;
    for (const JointWaypoint& w : seg.waypoints) {
      lo = {std::min(lo.theta1, w.q.theta1), std::min(lo.theta2, w.q.theta2)};
      hi = {std::max(hi.theta1, w.q.theta1), std::max(hi.theta2, w.q.theta2)};
    }
    const JointAngles cLo = commandedFromKinematic(p_.calibration, lo);
    const JointAngles cHi = commandedFromKinematic(p_.calibration, hi);
    const JointLimits& l = p_.limits;  // commanded
    const auto turn = [](double nearest, double from, double to, double min, double max) {
      for (double shift : {nearest, nearest + 2.0 * kPi, nearest - 2.0 * kPi})
        if (from + shift >= min && to + shift <= max) return shift;
      return nearest;
    };
    const double d1 = turn(unwrapNear(q0.theta1, at_.theta1) - q0.theta1, cLo.theta1, cHi.theta1,
                           l.theta1Min, l.theta1Max);
    const double d2 = turn(unwrapNear(q0.theta2, at_.theta2) - q0.theta2, cLo.theta2, cHi.theta2,
                           l.theta2Min, l.theta2Max);
    if (d1 == 0.0 && d2 == 0.0) return false;
    for (JointWaypoint& w : seg.waypoints) w.q = {w.q.theta1 + d1, w.q.theta2 + d2};
    return true;
  }

  void drawStroke(size_t k, Prepared& prepared) {
    const Stroke& s = strokes_[k];
    PlannedStroke& ps = job_.strokes[k];
    ps.layerIndex = s.layerIndex;
    ps.pathIndex = s.pathIndex;
    ps.reversed = s.reversed;
    if (s.points.empty()) return;
    SegmentedStroke& seg = prepared.seg;
    if (unwrapNearCurrent(seg) && seg.ok()) prepared.check = checkWaypoints(seg);
    if (!seg.ok()) {
      problem(pathLabel(s), seg.failedAt,
              seg.status == SegmentStatus::OutOfReach
                  ? FB_TR("Planner", "a point is out of reach in working mode %1").arg(toString(mode_))
                  : FB_TR("Planner", "the drawn curve cannot follow the stroke here (singular region)"),
              strokeFixes(), s.layerIndex, s.pathIndex);
      return;
    }
    if (!prepared.check.ok()) {
      const MoveCheck& c = prepared.check.problems.front().check;
      problem(pathLabel(s), c.where,
              c.status == MoveStatus::NearTypeI
                  ? describeMove(c)
                  : FB_TR("Planner", "the drawn line %1").arg(describeMove(c)),
              strokeFixes(), s.layerIndex, s.pathIndex);
      return;
    }
    minMargin_ = std::min(minMargin_, prepared.check.minTypeIIMarginRad);
    const int layer = s.layerIndex;
    const bool newLayer = layer != lastLayer_;
    lastLayer_ = layer;
    if (penDown_) penUp();
    if (newLayer && k > 0 && layerTool(layer).pauseBefore) push(JobMoveKind::Pause, -1, layer);
    const TravelPlan* ahead = prepared.travel ? &*prepared.travel : nullptr;
    if (!travelTo(seg.waypoints[0].q, static_cast<int>(k), layer, ahead, [&] { return FB_TR("Planner", "travel to %1").arg(pathLabel(s)); }))
      return;
    penDown(static_cast<int>(k), layer);
    ps.firstMove = static_cast<int>(job_.moves.size());
    draw(seg, prepared, static_cast<int>(k), layer);
    // This stroke's share of the report: its joint deviation plus its own flattening error.
    const double flatteningMm = s.flattened ? opt_.flatteningToleranceMm : 0.0;
    if (!seg.waypoints.empty()) {
      maxFlatteningMm_ = std::max(maxFlatteningMm_, flatteningMm);
      maxBridgedGapMm_ = std::max(maxBridgedGapMm_, s.bridgedGapMm);
      maxStrokeDeviationMm_ = std::max(maxStrokeDeviationMm_,
                                       seg.maxDeviationMm + flatteningMm + 0.5 * s.bridgedGapMm);
    }
    ps.moveCount = static_cast<int>(job_.moves.size()) - ps.firstMove;
    for (const JointWaypoint& w : seg.waypoints) ps.lengthMm += w.pathLengthMm;
    job_.summary.penDownMm += ps.lengthMm;
  }

  void draw(const SegmentedStroke& seg, const Prepared& prepared, int stroke, int layer) {
    const std::vector<SegmentFeed>& feeds = prepared.feeds;
    for (size_t i = 0; i < feeds.size(); ++i) {
      const JointWaypoint& w = seg.waypoints[i + 1];
      JobMove& m = push(JobMoveKind::Draw, stroke, layer);
      m.target = w.q;
      m.targetXY = w.p;
      m.feedMmPerS = feeds[i].feedMmPerS;
      m.jointFeedRadPerS = feeds[i].jointFeedRadPerS;
      m.feedLimited = feeds[i].limited();
      m.maxDeviationMm = w.deviationMm;
      m.toolValue = toolDownValue(layer);
      moved(w.q, w.p, kPi / 2.0);  // margins: the stroke's check
      job_.summary.segments += 1;
      job_.summary.feedLimitedSegments += m.feedLimited ? 1 : 0;
      job_.summary.maxDeviationMm = std::max(job_.summary.maxDeviationMm, w.deviationMm);
    }
  }

  // The travel from `from` to `to` (thread-safe: reads the profile only).
  TravelPlan planTravel(const JointAngles& from, const JointAngles& to) const {
    TravelPlan t;
    t.from = from;
    t.to = to;
    const auto path = planSafeTravel(p_, from, to);
    if (!path) return t;
    t.found = true;
    const FkResult start = forward(g_, from, p_.assembly);
    t.chain.push_back({from, start.ok() ? penOf(from, start.p) : Vec2::Zero(), 0.0, 0.0});
    for (const JointAngles& q : *path) {
      const auto [length, end] = travelLength(t.chain.back().q, q);
      t.chain.push_back({q, penOf(q, end), 0.0, length});
    }
    t.feeds = planFeeds(g_, p_.assembly, t.chain, p_.travelSpeedMmPerS, limits_);
    return t;
  }

  // Adds the travel from the current pose to `target` (the one planned ahead when it starts
  // here); `what` names it in a problem.
  template <typename What>
  bool travelTo(const JointAngles& target, int stroke, int layer, const TravelPlan* ahead,
                const What& what) {
    if (std::abs(target.theta1 - at_.theta1) < 1e-12 && std::abs(target.theta2 - at_.theta2) < 1e-12)
      return true;
    const bool reuse = ahead && ahead->from.theta1 == at_.theta1 &&
                       ahead->from.theta2 == at_.theta2 && ahead->to.theta1 == target.theta1 &&
                       ahead->to.theta2 == target.theta2;
    const TravelPlan fresh = reuse ? TravelPlan{} : planTravel(at_, target);
    const TravelPlan& t = reuse ? *ahead : fresh;
    if (!t.found) {
      const FkResult fk = forward(g_, target, p_.assembly);
      problem(what(), fk.ok() ? fk.p : atXY_, FB_TR("Planner", "no safe pen-up travel reaches it"),
              {PlanFix{FixKind::AwayFromSingular}, PlanFix{FixKind::TryAnotherMode}});
      return false;
    }
    for (size_t i = 0; i < t.feeds.size(); ++i) {
      JobMove& m = push(JobMoveKind::Travel, stroke, layer);
      m.target = t.chain[i + 1].q;
      m.targetXY = t.chain[i + 1].p;
      m.feedMmPerS = t.feeds[i].feedMmPerS;
      m.jointFeedRadPerS = t.feeds[i].jointFeedRadPerS;
      m.feedLimited = t.feeds[i].limited();
      moved(m.target, m.targetXY);
      job_.summary.travelMm += t.chain[i + 1].pathLengthMm;
      job_.summary.travelMoves += 1;
    }
    return true;
  }

  // XY length (mm) of the joint-linear move a -> b by FK samples, and where it ends.
  std::pair<double, Vec2> travelLength(const JointAngles& a, const JointAngles& b) const {
    Vec2 p[kTravelLengthSamples + 1];
    double length = 0.0;
    if (sampleJointMove(g_, p_.assembly, a, b, kTravelLengthSamples, p)) {
      for (int k = 1; k <= kTravelLengthSamples; ++k) length += (p[k] - p[k - 1]).norm();
      return {length, p[kTravelLengthSamples]};
    }
    // Some sample does not close (a travel that passed the safety check always does): the
    // samples that do.
    Vec2 prev = forward(g_, a, p_.assembly).p;
    for (int k = 1; k <= kTravelLengthSamples; ++k) {
      const double u = static_cast<double>(k) / kTravelLengthSamples;
      const FkResult fk = forward(g_, {a.theta1 + u * (b.theta1 - a.theta1),
                                       a.theta2 + u * (b.theta2 - a.theta2)}, p_.assembly);
      if (!fk.ok()) continue;
      length += (fk.p - prev).norm();
      prev = fk.p;
    }
    return {length, prev};
  }



  void penDown(int stroke, int layer) {
    JobMove& m = push(JobMoveKind::PenDown, stroke, layer);
    m.toolValue = toolDownValue(layer);
    m.dwellS = p_.tool.kind == ToolKind::PenServo ? p_.tool.penDownDelayS : 0.0;
    penDown_ = true;
  }

  void penUp() {
    JobMove& m = push(JobMoveKind::PenUp, -1, lastLayer_);
    m.toolValue = p_.tool.kind == ToolKind::ZAxis ? p_.tool.zUpMm
                  : p_.tool.kind == ToolKind::Laser ? 0.0 : p_.tool.penUpS;
    m.dwellS = p_.tool.kind == ToolKind::PenServo ? p_.tool.penUpDelayS : 0.0;
    penDown_ = false;
  }

  JobMove& push(JobMoveKind kind, int stroke, int layer) {
    JobMove& m = job_.moves.emplace_back();
    m.kind = kind;
    m.target = at_;
    m.targetXY = atXY_;
    m.strokeIndex = stroke;
    m.layerIndex = layer;
    return m;
  }

  // `p` is the pen; the margin is that of the linkage, at P.
  double typeIIMarginAt(const JointAngles& q, const Vec2& p) const {
    const Vec2 P = pen_ ? forward(g_, q, p_.assembly).p : p;
    return singularityMargins(g_, makePose(g_, q, P)).typeII;
  }

  // The pen of the pose q whose distal joint is P (P itself without a pen offset).
  Vec2 penOf(const JointAngles& q, const Vec2& P) const {
    return pen_ ? penFromDistal(pen_, g_, elbow1(g_, q.theta1), P) : P;
  }
  // The pen where P is at `P` in the planned working mode (for a failure's place).
  Vec2 penOf(const Vec2& P) const {
    const IkResult ik = inverse(g_, P, mode_);
    return ik.ok() ? penOf(ik.angles, P) : P;
  }
  // The budget of P's deviation that keeps the pen within `budgetMm` (pen_kinematics.hpp): the
  // mapping's chord tolerance paid, the rest divided by the pen's lever factor.
  double distalBudgetMm(double budgetMm) const {
    if (!pen_) return budgetMm;
    return (budgetMm - kDistalChordToleranceMm) / penDeviationFactor(g_, pen_);
  }

  void moved(const JointAngles& q, const Vec2& p) { moved(q, p, typeIIMarginAt(q, p)); }
  void moved(const JointAngles& q, const Vec2& p, double typeIIRad) {
    at_ = q;
    atXY_ = p;
    minMargin_ = std::min(minMargin_, typeIIRad);
    job_.summary.minTypeIIMarginRad = minMargin_;
  }

  LayerToolSettings layerTool(int layer) const {
    if (layer >= 0 && static_cast<size_t>(layer) < layers_.size())
      return layers_[static_cast<size_t>(layer)].tool;
    return {};
  }
  double drawSpeed(int layer) const {
    const double v = layerTool(layer).drawSpeedMmPerS;
    return v > 0.0 ? v : p_.drawSpeedMmPerS;
  }
  double toolDownValue(int layer) const {
    const double power = layerTool(layer).power;
    switch (p_.tool.kind) {
      case ToolKind::PenServo: return power >= 0.0 ? power : p_.tool.penDownS;
      case ToolKind::Laser: return power >= 0.0 ? power : p_.tool.laserPowerS;
      case ToolKind::ZAxis: return p_.tool.zDownMm;
    }
    return 0.0;
  }

  Message pathLabel(const Stroke& s) const {
    return FB_TR("Planner", "%1 path %2").arg(layerLabel(layers_, s.layerIndex)).arg(s.pathIndex);
  }

  void problem(Message path, const Vec2& where, Message why, std::vector<PlanFix> fixes,
               int layerIndex = -1, int pathIndex = -1) {
    out_.report.problems.push_back(
        {std::move(path), where, std::move(why), std::move(fixes), layerIndex, pathIndex});
  }

  const std::vector<Stroke>& strokes_;
  const std::vector<Layer>& layers_;
  const MachineProfile& p_;
  const Geometry& g_;
  WorkingMode mode_;
  const PlanOptions& opt_;
  PlanResult& out_;
  PlannedJob& job_;
  const std::optional<PenOffset>& pen_;  // the calibrated pen offset (pen_kinematics.hpp)
  FeedLimits limits_;
  SegmentationOptions segExact_, segFlattened_;
  JointAngles at_;
  Vec2 atXY_ = Vec2::Zero();
  bool penDown_ = false;
  int lastLayer_ = std::numeric_limits<int>::min();
  double minMargin_ = kPi / 2.0;

 public:
  double maxFlatteningMm_ = 0.0;       // largest flattening error of a drawn stroke
  double maxBridgedGapMm_ = 0.0;       // largest gap joining bridged in a drawn stroke
  double maxStrokeDeviationMm_ = 0.0;  // largest joint deviation + flattening of a drawn stroke
};

}  // namespace

double gcodeRoundingBoundMm(const MachineProfile& profile) {
  // Each angle is rounded to kGcodeAngleDecimals of a degree: |dtheta|_2 <= sqrt(2) * half a unit.
  // The pen moves by dP = A^-1 B dtheta (conventions.md, Hoang eq. 7): the rows of A are
  // (P - R_i), of length b_i, det A = b1 b2 sin(phi) with phi the angle between the distal links
  // (|sin phi| >= sin(type II margin) at every planned target), so |A^-1| <= sqrt(b1^2 + b2^2) /
  // (b1 b2 sin(margin)); |B_ii| <= a_i b_i. Without a usable margin the older lever estimate.
  const Geometry& g = profile.geometry;
  const double dThetaRad = std::sqrt(2.0) * radFromDeg(0.5 * std::pow(10.0, -kGcodeAngleDecimals));
  const double lever = kRoundingLeverFactor * std::max(g.a1 + g.b1, g.a2 + g.b2);
  const double sinMargin = std::sin(std::min(profile.typeIIMarginRad, kPi / 2.0));
  if (!(sinMargin > 0.0)) return lever * dThetaRad;
  const double jacobian = std::hypot(g.b1, g.b2) / (g.b1 * g.b2 * sinMargin) *
                          std::max(g.a1 * g.b1, g.a2 * g.b2);
  return std::min(lever, jacobian) * dThetaRad;
}

// Tolerance left for the joint-linear deviation of a stroke once its flattening is paid (the
// G-code rounding is part of the measured deviation: the moves are segmented between rounded
// angles).
double jointDeviationBudgetMm(const MachineProfile&, const PlanOptions& options, bool flattened) {
  return options.toleranceMm - (flattened ? options.flatteningToleranceMm : 0.0);
}

PlanResult planStrokes(const std::vector<Stroke>& strokes, const std::vector<Layer>& layers,
                       const MachineProfile& profile, WorkingMode mode,
                       const PlanOptions& options) {
  PlanResult out;
  out.report.mode = mode;
  out.report.toleranceMm = options.toleranceMm;
  const bool anyFlattened = std::any_of(strokes.begin(), strokes.end(),
                                       [](const Stroke& s) { return s.flattened; });
  // Below the worst case of the G-code rounding no tolerance can be promised (the rounding is
  // measured move by move, but a budget under its bound would fail somewhere as "cannot follow").
  double largestBridgeMm = 0.0;
  for (const Stroke& s : strokes) largestBridgeMm = std::max(largestBridgeMm, s.bridgedGapMm);
  const double budget = jointDeviationBudgetMm(profile, options, anyFlattened) - 0.5 * largestBridgeMm;
  if (!(budget > gcodeRoundingBoundMm(profile)) || !(options.toleranceMm > 0.0)) {
    out.status = PlanStatus::BadOptions;
    out.message = FB_TR("Planner", "tolerance %1 mm leaves nothing for the moves after flattening "
                                   "(%2 mm) and the G-code rounding (up to %3 mm)")
                      .arg(options.toleranceMm, 6)
                      .arg(anyFlattened ? options.flatteningToleranceMm : 0.0, 6)
                      .arg(gcodeRoundingBoundMm(profile), 6);
    return out;
  }
  StageClock clock(out.timings);
  MotionPlanner planner(strokes, layers, profile, mode, options, out);
  planner.run(jointDeviationBudgetMm(profile, options, false),
              jointDeviationBudgetMm(profile, options, true));
  clock.lap("segmentation, feeds, travel");
  // Backlash compensation (backlash_compensation.hpp): only when the profile's calibration has
  // play, so a job without it is byte-identical to before.
  if (profile.calibration && out.report.problems.empty()) {
    const MotorPlay play{profile.calibration->backlashRad1, profile.calibration->backlashRad2};
    if (!play.none()) {
      const BacklashPass pass = compensateBacklash(out.job, profile, play);
      if (!pass.ok)
        out.report.problems.push_back(
            {FB_TR("Planner", "backlash compensation"), pass.problem.where, pass.message,
             {PlanFix{FixKind::AwayFromEdge}}});
      clock.lap("backlash compensation");
    }
  }
  if (options.cancel != nullptr && options.cancel->load()) {
    out.status = PlanStatus::Cancelled;
    out.message = FB_TR("Planner", "planning cancelled");
    out.job = PlannedJob();
    return out;
  }
  fillJobTimes(out.job, profile);
  clock.lap("time estimate");
  if (out.job.moves.size() <= kTimeOptimalMaxMoves) {
    std::vector<double> layerSpeeds;
    for (const Layer& l : layers) layerSpeeds.push_back(l.tool.drawSpeedMmPerS);
    out.job.summary.timeOptimalS = timeOptimalJob(out.job, profile, layerSpeeds).totalS();
    clock.lap("time-optimal reference");
  }
  PlanReport& r = out.report;
  const JobSummary& s = out.job.summary;
  r.feasible = r.problems.empty();
  r.estimatedTimeS = s.estimatedTimeS;
  r.timeOptimalS = s.timeOptimalS;
  r.penDownMm = s.penDownMm;
  r.travelMm = s.travelMm;
  r.segments = s.segments;
  r.jointDeviationMm = s.maxDeviationMm;
  r.flatteningMm = planner.maxFlatteningMm_;
  r.bridgedGapMm = planner.maxBridgedGapMm_;
  r.roundingMm = 0.0;  // measured: part of the joint deviation (moves between rounded angles)
  r.maxDeviationMm = s.segments > 0 ? planner.maxStrokeDeviationMm_ : 0.0;
  r.minSingularityMarginDeg = degFromRad(s.minTypeIIMarginRad);
  r.feedLimitedSegments = s.feedLimitedSegments;
  out.status = r.feasible ? PlanStatus::Ok : PlanStatus::Infeasible;
  if (!r.feasible)
    out.message = FB_TR("Planner", "%1: %2").arg(r.problems.front().path).arg(r.problems.front().why);
  return out;
}

}  // namespace fivebar
