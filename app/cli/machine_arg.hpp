// SPDX-License-Identifier: GPL-3.0-or-later
// Shared pieces of the kinematics, workspace and profile commands: "--machine PRESET|FILE"
// resolution with readable errors, strict parsing of "a,b" number pairs from text lines, and
// (in a build with the drivers) the link a machine command's "--port NAME [--baud N]" names.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "core/machine/profile.hpp"

#ifdef FIVEBAR_HAVE_DRIVERS
#include "drivers/transport/transport.hpp"
#include "options.hpp"
#endif

namespace fivebar::cli {

#ifdef FIVEBAR_HAVE_DRIVERS
// The transport for --port (required) at --baud (default 115200), not yet opened: a serial
// device or pseudo-terminal, or a network port "tcp:HOST:PORT" (drivers/transport/open_transport.hpp).
// Throws UsageError for a missing --port or a bad --baud.
std::unique_ptr<Transport> portTransport(const Options& o);
#endif

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
