// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's words for plan fixes. Contract: plan_words.hpp.
#include "widgets/document/plan_words.hpp"

#include "core/support/message.hpp"
#include "i18n/translated.hpp"

namespace fivebar::widgets {
namespace {

Message studioMessage(const PlanFix& fix) {
  switch (fix.kind) {
    case FixKind::MoveOrShrink: return FB_TR("Planner", "move or shrink the drawing in the Placement panel");
    case FixKind::TryAnotherMode: return FB_TR("Planner", "try another working mode in the Workspace panel");
    case FixKind::AwayFromSingular:
      return FB_TR("Planner", "move the drawing away from singular regions in the Placement panel");
    case FixKind::AwayFromEdge:
      return FB_TR("Planner", "move the drawing away from the workspace edge in the Placement panel");
    case FixKind::Shrink:
      return FB_TR("Planner", "set Scale to %1 % in the Placement panel").arg(fix.scale * 100.0, 0);
    case FixKind::MoveCentre:
      return FB_TR("Planner", "set Centre X to %1 mm and Centre Y to %2 mm in the Placement panel")
          .arg(fix.centreMm.x(), 1).arg(fix.centreMm.y(), 1);
    case FixKind::UseMode:
      return FB_TR("Planner", "choose working mode %1 in the Workspace panel").arg(toString(fix.mode));
    case FixKind::FitToWorkspace: return FB_TR("Planner", "press Fit to workspace in the Placement panel");
    case FixKind::ReachableHomePose: return FB_TR("Planner", "set a reachable home pose in the profile");
    case FixKind::CheckProfile: return FB_TR("Planner", "check the profile");
  }
  return FB_TR("Planner", "check the profile");
}

}  // namespace

QString fixWords(const PlanFix& fix) { return translated(studioMessage(fix)); }

QStringList fixWords(const std::vector<PlanFix>& fixes) {
  QStringList out;
  for (const PlanFix& f : fixes) out << fixWords(f);
  return out;
}

}  // namespace fivebar::widgets
