// SPDX-License-Identifier: GPL-3.0-or-later
// MotionPlanner (motion_planner.hpp): strokes prepared in parallel chunks and drawn in order.
#include "core/planning/motion_planner.hpp"

#include <algorithm>
#include <cmath>
#include <future>

#include "core/support/memory_hint.hpp"
#include "core/support/parallel.hpp"

namespace fivebar::motion {

// Strokes segmented in parallel before being drawn in order (bounds the memory held).
constexpr size_t kChunkStrokes = 2048;

Message layerLabel(const std::vector<Layer>& layers, int layerIndex) {
  if (layerIndex >= 0 && static_cast<size_t>(layerIndex) < layers.size()) {
    const Layer& l = layers[static_cast<size_t>(layerIndex)];
    return FB_TR("Planner", "layer '%1'").arg(l.name.empty() ? l.id : l.name);
  }
  return FB_TR("Planner", "layer %1").arg(layerIndex);
}

// exactBudgetMm: the joint-linear budget of a stroke whose points are its geometry;
// flattenedBudgetMm: of a stroke of flattened curves (Stroke::flattened).
void MotionPlanner::run(double exactBudgetMm, double flattenedBudgetMm) {
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

bool MotionPlanner::startPose() {
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

void MotionPlanner::work(ChunkWork& w) const {
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
void MotionPlanner::runChunk(ChunkWork& w, size_t extra) const {
  std::vector<std::future<void>> workers;
  for (size_t t = 0; t < extra; ++t)
    workers.push_back(std::async(std::launch::async, [this, &w] { work(w); }));
  work(w);
  for (size_t d = w.done.load(); d < w.n; d = w.done.load()) w.done.wait(d);
  for (std::future<void>& f : workers) f.get();
  if (w.error) std::rethrow_exception(w.error);
}

void MotionPlanner::travelInto(ChunkWork& w, size_t i) const {
  Prepared& p = w.slots[i];
  if (!p.usable()) return;
  const std::optional<JointAngles> from =
      i == 0 ? w.before
             : w.slots[i - 1].usable()
                   ? std::optional<JointAngles>(w.slots[i - 1].seg.waypoints.back().q)
                   : std::nullopt;
  if (from) p.travel = planTravel(*from, p.seg.waypoints.front().q);
}

void MotionPlanner::prepare(size_t k, Prepared& out) const {
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
PathCheck MotionPlanner::checkWaypoints(const SegmentedStroke& seg) const {
  std::vector<JointAngles> poses;
  poses.reserve(seg.waypoints.size());
  for (const JointWaypoint& w : seg.waypoints) poses.push_back(w.q);
  return checkJointPath(p_, poses);
}

// Room for a chunk's moves (draws plus a few tool and travel moves per stroke), growing the
// job geometrically so that the moves are not copied once per chunk.
void MotionPlanner::reserveMoves(const std::vector<Prepared>& chunk) {
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
bool MotionPlanner::unwrapNearCurrent(SegmentedStroke& seg) const {
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

void MotionPlanner::drawStroke(size_t k, Prepared& prepared) {
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

void MotionPlanner::draw(const SegmentedStroke& seg, const Prepared& prepared, int stroke, int layer) {
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

Message MotionPlanner::pathLabel(const Stroke& s) const {
  return FB_TR("Planner", "%1 path %2").arg(layerLabel(layers_, s.layerIndex)).arg(s.pathIndex);
}

}  // namespace fivebar::motion
