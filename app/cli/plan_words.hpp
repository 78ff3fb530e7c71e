// SPDX-License-Identifier: GPL-3.0-or-later
// The CLI's words for what to change when a job cannot be planned (core/planning/plan_fix.hpp):
// plain English naming the `fivebar plan` option that does it, numbers in the C locale (they are
// typed on a command line).
#pragma once

#include <string>

#include "core/planning/plan_fix.hpp"
#include "core/support/message.hpp"

namespace fivebar::cli {

Message fixWords(const PlanFix& fix);
// The same as text, for the report (reportToJson's FixWords).
std::string fixText(const PlanFix& fix);

}  // namespace fivebar::cli
