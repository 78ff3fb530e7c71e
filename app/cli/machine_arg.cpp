// SPDX-License-Identifier: GPL-3.0-or-later
#include "machine_arg.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#ifdef FIVEBAR_HAVE_DRIVERS
#include "drivers/transport/open_transport.hpp"
#include "machine_cli.hpp"
#endif

namespace fivebar::cli {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::optional<double> parseNumber(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);  // from_chars rejects a leading '+'
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::optional<MachineProfile> loadMachine(const std::string& presetOrPath, std::string_view command,
                                          std::ostream& err) {
  ProfileLoad load = resolveMachine(presetOrPath);
  if (load.profile) return std::move(load.profile);
  for (const ValidationIssue& issue : load.issues) {
    err << "fivebar " << command << ": ";
    // A preset-name problem or an unreadable file already names its subject.
    if (issue.field == "machine" || issue.field == "file" || issue.field == "json")
      err << issue.message << "\n";
    else
      err << presetOrPath << ": " << issue.field << ": " << issue.message << "\n";
  }
  return std::nullopt;
}

#ifdef FIVEBAR_HAVE_DRIVERS
std::unique_ptr<Transport> portTransport(const Options& o) {
  return makePortTransport(QString::fromStdString(o.required("--port")), baudFrom(o));
}
#endif

std::optional<NumberPair> parseNumberPair(std::string_view line) {
  const std::size_t comma = line.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const auto a = parseNumber(line.substr(0, comma));
  const auto b = parseNumber(line.substr(comma + 1));
  if (!a || !b) return std::nullopt;
  return NumberPair{*a, *b};
}

std::string fixed9(double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9f", value);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);
  return s;
}

std::string poseAngleDeg(double angleRad) {
  double deg = normalizeDeg(degFromRad(angleRad));
  if (std::round(deg * 1e9) <= -180e9) deg = 180.0;
  return fixed9(deg);
}

}  // namespace fivebar::cli
