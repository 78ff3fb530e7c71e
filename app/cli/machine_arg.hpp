// Shared pieces of the kinematics, workspace and profile commands: "--machine PRESET|FILE"
// resolution with readable errors, and strict parsing of "a,b" number pairs from text lines.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "core/machine/profile.hpp"

namespace fivebar::cli {

// Resolves a --machine value. On failure writes "fivebar COMMAND: <source>: field: message" lines
// to `err` and returns nullopt.
std::optional<MachineProfile> loadMachine(const std::string& presetOrPath, std::string_view command,
                                          std::ostream& err);

// Parses "a,b" (two finite decimal numbers, optional blanks around each, optional trailing CR).
// nullopt for anything else.
struct NumberPair {
  double first = 0.0;
  double second = 0.0;
};
std::optional<NumberPair> parseNumberPair(std::string_view line);

// "%.9f" of a value, never printing "-0.000000000".
std::string fixed9(double value);

// An angle in degrees for a single pose: normalised to (-180, 180] after rounding to 9 decimals,
// so that -179.9999999999 prints as 180.000000000, not -180.000000000.
std::string poseAngleDeg(double angleRad);

}  // namespace fivebar::cli
