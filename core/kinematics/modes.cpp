// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/kinematics/modes.hpp"

namespace fivebar {

std::string_view toString(WorkingMode m) {
  switch (m) {
    case WorkingMode::PlusPlus: return "++";
    case WorkingMode::PlusMinus: return "+-";
    case WorkingMode::MinusPlus: return "-+";
    case WorkingMode::MinusMinus: return "--";
  }
  return "?";
}

std::string_view toString(AssemblyMode m) { return m == AssemblyMode::Plus ? "+" : "-"; }

std::optional<WorkingMode> parseWorkingMode(std::string_view text) {
  for (WorkingMode m : kAllWorkingModes)
    if (toString(m) == text) return m;
  return std::nullopt;
}

std::optional<AssemblyMode> parseAssemblyMode(std::string_view text) {
  for (AssemblyMode m : kAllAssemblyModes)
    if (toString(m) == text) return m;
  return std::nullopt;
}

}  // namespace fivebar
