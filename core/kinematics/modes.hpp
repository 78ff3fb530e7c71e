// SPDX-License-Identifier: GPL-3.0-or-later
// Branch names of the five-bar (conventions.md): working modes ("++", "+-", "-+", "--") are the
// inverse-kinematics branches, one sign per arm; assembly modes ('+', '-') are the
// forward-kinematics branches.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fivebar {

enum class ArmSign { Plus, Minus };

// Working mode: sign of arm 1, sign of arm 2. '+' is elbow out.
enum class WorkingMode { PlusPlus, PlusMinus, MinusPlus, MinusMinus };

// Assembly mode: '+' when P lies left of the directed line R1->R2.
enum class AssemblyMode { Plus, Minus };

inline constexpr std::array<WorkingMode, 4> kAllWorkingModes{
    WorkingMode::PlusPlus, WorkingMode::PlusMinus, WorkingMode::MinusPlus, WorkingMode::MinusMinus};
inline constexpr std::array<AssemblyMode, 2> kAllAssemblyModes{AssemblyMode::Plus,
                                                               AssemblyMode::Minus};

constexpr ArmSign arm1Sign(WorkingMode m) {
  return (m == WorkingMode::PlusPlus || m == WorkingMode::PlusMinus) ? ArmSign::Plus
                                                                     : ArmSign::Minus;
}
constexpr ArmSign arm2Sign(WorkingMode m) {
  return (m == WorkingMode::PlusPlus || m == WorkingMode::MinusPlus) ? ArmSign::Plus
                                                                     : ArmSign::Minus;
}
constexpr WorkingMode workingModeFromSigns(ArmSign s1, ArmSign s2) {
  if (s1 == ArmSign::Plus) return s2 == ArmSign::Plus ? WorkingMode::PlusPlus : WorkingMode::PlusMinus;
  return s2 == ArmSign::Plus ? WorkingMode::MinusPlus : WorkingMode::MinusMinus;
}

std::string_view toString(WorkingMode m);   // "++", "+-", "-+", "--"
std::string_view toString(AssemblyMode m);  // "+", "-"
std::optional<WorkingMode> parseWorkingMode(std::string_view text);
std::optional<AssemblyMode> parseAssemblyMode(std::string_view text);

}  // namespace fivebar
