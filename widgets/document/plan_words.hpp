// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's words for what to change when a job cannot be planned (core/planning/plan_fix.hpp):
// the names of its own controls (Placement panel, Workspace panel), in the user's language with
// its number format. The CLI words the same codes with its options (app/cli/plan_words.hpp).
#pragma once

#include <QString>
#include <QStringList>
#include <vector>

#include "core/planning/plan_fix.hpp"

namespace fivebar::widgets {

QString fixWords(const PlanFix& fix);
QStringList fixWords(const std::vector<PlanFix>& fixes);

}  // namespace fivebar::widgets
