// SPDX-License-Identifier: GPL-3.0-or-later
// What to change when a job cannot be planned, as a code with its numbers: core says what, each
// front end words it (the CLI with the `fivebar plan` option that does it: app/cli/plan_words.hpp;
// the studio with its controls' names, in the user's language: widgets/document/plan_words.hpp).
#pragma once

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

enum class FixKind {
  MoveOrShrink,        // move or shrink the drawing
  TryAnotherMode,      // try another working mode
  AwayFromSingular,    // move the drawing away from singular regions
  AwayFromEdge,        // move the drawing away from the workspace edge
  Shrink,              // shrink the drawing to `scale` (1 = true size)
  MoveCentre,          // move the drawing's centre to `centreMm` (machine frame)
  UseMode,             // plan in working mode `mode`
  FitToWorkspace,      // fit the drawing into the workspace
  ReachableHomePose,   // set a reachable home pose in the profile
  CheckProfile,        // check the machine profile
};

struct PlanFix {
  FixKind kind = FixKind::CheckProfile;
  double scale = 1.0;               // Shrink
  Vec2 centreMm = Vec2::Zero();     // MoveCentre
  WorkingMode mode = WorkingMode::PlusPlus;  // UseMode
};

// A stable name of the kind ("shrink", "move_centre", ...): the report's "fix_kinds".
const char* toString(FixKind kind);

}  // namespace fivebar
