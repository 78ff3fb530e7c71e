// SPDX-License-Identifier: GPL-3.0-or-later
// Preflight of a placed job (strokes in the machine frame) against a machine profile in one
// working mode: reach, continuous joint limits, type I/II margins and assembly mode, for every
// point and every joint-linear move between consecutive points, travels (home -> first stroke,
// between strokes, last stroke -> home) included. chooseMode() runs it for every working mode.
// The plan never changes assembly mode: everything is checked in profile.assembly.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/safety.hpp"
#include "core/planning/strokes.hpp"
#include "core/support/message.hpp"

namespace fivebar {

struct PreflightOptions {
  // Check the travel from the home pose to the first stroke and back after the last one.
  bool includeHomeTravel = true;
  std::optional<JointAngles> home;  // KINEMATIC angles; nullopt = the profile's home pose
                                    // (homeAngles are commanded: converted with its calibration)
  // Travels that fail the straight joint move are accepted when planSafeTravel finds a detour
  // (at most 16 searches per preflight; later failing travels are reported as problems).
  bool allowTravelDetours = true;
  // Compute the shrink / move fixes when the job is infeasible.
  bool suggestFixes = true;
  // Point about which "shrink" scales the job and which "move" relocates (usually the
  // Placement::centerMm); nullopt = centre of the strokes' bounding box.
  std::optional<Vec2> anchorMm;
  std::size_t maxListedProblems = 50;  // problems listed; all are counted
};

enum class MoveKind { Draw, Travel, Point };

struct PreflightProblem {
  int strokeIndex = -1;   // index into the checked strokes; -1 for the return travel to home
  int layerIndex = -1;    // Stroke::layerIndex (-1 for home travel)
  int pathIndex = -1;     // Stroke::pathIndex
  int pointIndex = -1;    // index of the point (Point) or of the move's end point (Draw)
  MoveKind kind = MoveKind::Point;
  Vec2 whereMm = Vec2::Zero();  // machine frame
  MoveStatus status = MoveStatus::Ok;
  Message reason;         // human sentence, names the stroke and the point
};

struct FeasibilityReport {
  WorkingMode mode = WorkingMode::PlusPlus;
  bool feasible = false;
  double minTypeIIMarginRad = 0.0;  // worst (smallest) type II margin over all checked moves
  std::size_t pointsChecked = 0;
  std::size_t problemCount = 0;              // all problems found
  std::vector<PreflightProblem> problems;    // the first maxListedProblems of them
  // Fixes on offer when infeasible (each alone makes the job pass preflight):
  std::optional<double> shrinkFactor;   // scale the job about the anchor by this factor (< 1)
  std::optional<Vec2> suggestedAnchorMm; // move the anchor here, at the current scale
  // One line, e.g. "mode ++: feasible, worst type II margin 21.3 deg"; summary() is its text.
  Message summaryMessage() const;
  std::string summary() const;
};

FeasibilityReport preflight(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                            WorkingMode mode, const PreflightOptions& options = {});

struct ModeChoice {
  std::optional<WorkingMode> mode;          // feasible mode with the largest worst-case margin
  std::vector<FeasibilityReport> reports;   // one per candidate mode, in candidate order
};

// Auto mode selection: preflight in each candidate mode (default all four); picks the feasible
// one with the largest minTypeIIMarginRad (ties: earlier candidate). nullopt when none is feasible.
ModeChoice chooseMode(const std::vector<Stroke>& strokes, const MachineProfile& profile,
                      const PreflightOptions& options = {},
                      const std::vector<WorkingMode>& candidates = {kAllWorkingModes.begin(),
                                                                    kAllWorkingModes.end()});

}  // namespace fivebar
