// SPDX-License-Identifier: GPL-3.0-or-later
// The planned job: what the planner produces and what G-code, the time estimate, the trajectory
// (studio animation) and the report are made from. Joint targets are continuous (unwrapped)
// motor angles in radians; XY targets are machine-frame millimetres; times in seconds.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

enum class JobMoveKind : unsigned char {
  Draw,     // pen down, joint-linear move along a stroke
  Travel,   // pen up, joint-linear move between strokes (checked by planSafeTravel)
  PenUp,    // tool raised (servo M5 / M3 S<up>, Z up, laser off); no motion
  PenDown,  // tool lowered (servo M3 S<down>, Z down, laser on); no motion
  Dwell,    // wait (G4 P<s>), e.g. for the servo to settle; no motion
  Pause,    // job paused until the operator resumes (M0), e.g. a pen change between layers
};
constexpr std::string_view toString(JobMoveKind kind) {
  switch (kind) {
    case JobMoveKind::Draw: return "draw";
    case JobMoveKind::Travel: return "travel";
    case JobMoveKind::PenUp: return "pen-up";
    case JobMoveKind::PenDown: return "pen-down";
    case JobMoveKind::Dwell: return "dwell";
    case JobMoveKind::Pause: return "pause";
  }
  return "?";
}

inline bool isMotion(JobMoveKind kind) { return kind == JobMoveKind::Draw || kind == JobMoveKind::Travel; }

struct JobMove {
  // (Fields ordered for size: a large job holds millions of moves.)
  JointAngles target;            // joint target after the move (rad, continuous); unchanged
                                 // from the previous move for non-motion kinds
  Vec2 targetXY = Vec2::Zero();  // machine-frame end-effector after the move (mm)
  double feedMmPerS = 0.0;       // planned XY speed over the move (Draw/Travel)
  double jointFeedRadPerS = 0.0; // |dtheta| / duration at cruise: the G-code F (in deg/min)
  double dwellS = 0.0;           // Dwell: how long; PenUp/PenDown: settle time that follows
  double toolValue = 0.0;        // PenDown/Draw: servo S or laser S; Z-axis: Z target (mm)
  double maxDeviationMm = 0.0;   // Draw: max distance of the real (FK) curve from the stroke
  double durationS = 0.0;        // planned duration from the GRBL time model
  double startTimeS = 0.0;       // planned start time since the job start
  int strokeIndex = -1;          // stroke (index into PlannedJob::strokes) it belongs to, or -1
  int layerIndex = -1;           // layer of that stroke, or -1
  JobMoveKind kind = JobMoveKind::Draw;
  bool feedLimited = false;      // feed lowered below the asked speed (motor limits, minimum
                                 // segment duration, or acceleration)
};

// Identification of one planned stroke, for messages and the studio.
struct PlannedStroke {
  int layerIndex = 0;
  int pathIndex = 0;
  bool reversed = false;
  double lengthMm = 0.0;
  int firstMove = 0;  // index of its first Draw move in PlannedJob::moves
  int moveCount = 0;  // number of Draw moves
};

struct JobSummary {
  double estimatedTimeS = 0.0;
  double timeOptimalS = 0.0;    // the time-optimal reference (core/planning/time_optimal.hpp)
  double penDownMm = 0.0;       // drawn length (sum of stroke lengths)
  double travelMm = 0.0;        // pen-up XY path length (FK along the travel moves)
  int segments = 0;             // number of Draw moves
  int travelMoves = 0;
  int feedLimitedSegments = 0;  // Draw moves whose feed was lowered below the asked speed
  double maxDeviationMm = 0.0;  // over every Draw move
  double minTypeIIMarginRad = 0.0;  // smallest type II margin at any planned target
};

struct PlannedJob {
  std::string profileName;
  WorkingMode mode = WorkingMode::PlusPlus;
  AssemblyMode assembly = AssemblyMode::Plus;
  JointAngles start;             // pose the job starts (and ends) at, rad
  Vec2 startXY = Vec2::Zero();   // mm
  std::vector<JobMove> moves;
  std::vector<PlannedStroke> strokes;
  JobSummary summary;
};

}  // namespace fivebar
