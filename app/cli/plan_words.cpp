// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI's words for plan fixes. Contract: plan_words.hpp.
#include "plan_words.hpp"

namespace fivebar::cli {

Message fixWords(const PlanFix& fix) {
  switch (fix.kind) {
    case FixKind::MoveOrShrink: return FB_TR("Planner", "move or shrink the drawing (--at, --scale, --fit)");
    case FixKind::TryAnotherMode: return FB_TR("Planner", "try another working mode (--mode)");
    case FixKind::AwayFromSingular: return FB_TR("Planner", "move the drawing away from singular regions (--at)");
    case FixKind::AwayFromEdge: return FB_TR("Planner", "move the drawing away from the workspace edge (--at)");
    case FixKind::Shrink:
      return FB_TR("Planner", "shrink the drawing to %1 % (--scale %2)")
          .arg(fix.scale * 100.0, 0).arg(fixedText(fix.scale, 3));
    case FixKind::MoveCentre: {
      const double x = fix.centreMm.x(), y = fix.centreMm.y();
      return FB_TR("Planner", "move the drawing's centre to x %1 mm, y %2 mm (--at %3,%4)")
          .arg(x, 1).arg(y, 1).arg(fixedText(x, 1)).arg(fixedText(y, 1));
    }
    case FixKind::UseMode: return FB_TR("Planner", "use working mode %1 (--mode %1)").arg(toString(fix.mode));
    case FixKind::FitToWorkspace: return FB_TR("Planner", "fit the drawing into the workspace (--fit)");
    case FixKind::ReachableHomePose: return FB_TR("Planner", "set a reachable home pose in the profile");
    case FixKind::CheckProfile: return FB_TR("Planner", "check the profile");
  }
  return FB_TR("Planner", "check the profile");
}

std::string fixText(const PlanFix& fix) { return fixWords(fix).text(); }

}  // namespace fivebar::cli
