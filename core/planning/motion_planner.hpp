// SPDX-License-Identifier: GPL-3.0-or-later
// The motion planner behind planStrokes (plan_motion.cpp): placed strokes, drawn in order, become
// the job's moves. Internal to core/planning. Its work is split by responsibility:
// motion_planner.cpp prepares strokes in parallel chunks (segmentation, the safety check, feeds)
// and draws them in order; motion_travel.cpp plans the pen-up travel between them and the tool
// moves. The per-move helpers stay inline here: the draw loop calls them once per move.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "core/machine/pen_kinematics.hpp"
#include "core/planning/feeds.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/safety.hpp"
#include "core/planning/segmentation.hpp"
#include "core/kinematics/singularity.hpp"

namespace fivebar::motion {

// Decimals of a degree of the G-code angles (GcodeOptions::angleDecimals, core/output/gcode.hpp):
// the segmentation measures its moves between angles rounded so.
inline constexpr int kGcodeAngleDecimals = 4;

// "layer 'Outline'" (its name, else its id), or "layer 3" for an index without a layer.
Message layerLabel(const std::vector<Layer>& layers, int layerIndex);

// The fixes of a stroke the planner cannot draw.
inline std::vector<PlanFix> strokeFixes() { return {{FixKind::MoveOrShrink}, {FixKind::TryAnotherMode}}; }

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
  void run(double exactBudgetMm, double flattenedBudgetMm);

 private:
  bool cancelled() const { return opt_.cancel != nullptr && opt_.cancel->load(); }

  bool startPose();

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

  void work(ChunkWork& w) const;

  // Prepares the chunk on this thread and `extra` more, and waits until it is complete.
  void runChunk(ChunkWork& w, size_t extra) const;

  void travelInto(ChunkWork& w, size_t i) const;

  void prepare(size_t k, Prepared& out) const;

  // The safety rule on the moves that will be sent: every joint-linear move between waypoints.
  PathCheck checkWaypoints(const SegmentedStroke& seg) const;

  // Room for a chunk's moves (draws plus a few tool and travel moves per stroke), growing the
  // job geometrically so that the moves are not copied once per chunk.
  void reserveMoves(const std::vector<Prepared>& chunk);

  // Shifts the stroke's angles by whole turns so that it starts nearest the current pose; when
  // that turn takes a motor of the stroke beyond its joint limits (on commanded angles), by the
  // nearest turn that keeps that motor's whole stroke inside them. Returns whether the angles
  // changed (joint limits then need a new check).
  bool unwrapNearCurrent(SegmentedStroke& seg) const;

  void drawStroke(size_t k, Prepared& prepared);

  void draw(const SegmentedStroke& seg, const Prepared& prepared, int stroke, int layer);

  // The travel from `from` to `to` (thread-safe: reads the profile only).
  TravelPlan planTravel(const JointAngles& from, const JointAngles& to) const;

  // Adds the travel from the current pose to `target` (the one planned ahead when it starts
  // here); `what` names it in a problem.
  bool travelTo(const JointAngles& target, int stroke, int layer, const TravelPlan* ahead,
                const std::function<Message()>& what);

  // XY length (mm) of the joint-linear move a -> b by FK samples, and where it ends.
  std::pair<double, Vec2> travelLength(const JointAngles& a, const JointAngles& b) const;

  void penDown(int stroke, int layer);

  void penUp();

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

  Message pathLabel(const Stroke& s) const;

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

}  // namespace fivebar::motion
