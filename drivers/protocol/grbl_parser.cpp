// SPDX-License-Identifier: GPL-3.0-or-later
#include "grbl_parser.hpp"

#include <charconv>
#include <cmath>
#include <vector>

namespace fivebar::grbl {
namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  while (true) {
    const size_t p = s.find(sep, start);
    out.push_back(s.substr(start, p == std::string_view::npos ? s.npos : p - start));
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
  return out;
}

std::optional<int> parseInt(std::string_view s) {
  int v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::optional<MachineState> parseState(std::string_view name) {
  static constexpr std::pair<std::string_view, MachineState> kStates[] = {
      {"Idle", MachineState::Idle},   {"Run", MachineState::Run},
      {"Hold", MachineState::Hold},   {"Jog", MachineState::Jog},
      {"Alarm", MachineState::Alarm}, {"Door", MachineState::Door},
      {"Check", MachineState::Check}, {"Home", MachineState::Home},
      {"Sleep", MachineState::Sleep}};
  for (const auto& [n, s] : kStates)
    if (n == name) return s;
  return std::nullopt;
}

// Applies one "Name:value" field of a status report; false when the value is malformed.
bool applyField(StatusReport& r, std::string_view name, std::string_view value) {
  if (name == "MPos") return bool(r.mpos = parseAxes(value));
  if (name == "WPos") return bool(r.wpos = parseAxes(value));
  if (name == "WCO") return bool(r.wco = parseAxes(value));
  if (name == "Pn") { r.pins = std::string(value); return true; }
  if (name == "A") {  // report.c: S or C (spindle), F (flood), M (mist), only with some on
    if (value.empty() || value.find_first_not_of("SCFM") != std::string_view::npos) return false;
    r.accessories = std::string(value);
    return true;
  }
  const auto parts = split(value, ',');
  if (name == "Bf") {
    if (parts.size() != 2) return false;
    r.plannerBlocksFree = parseInt(parts[0]);
    r.rxBytesFree = parseInt(parts[1]);
    if (r.plannerBlocksFree < 0 || r.rxBytesFree < 0) r.plannerBlocksFree = r.rxBytesFree = std::nullopt;
    return r.plannerBlocksFree && r.rxBytesFree;
  }
  if (name == "FS" || name == "F") {
    r.feed = parseNumber(parts[0]);
    if (name == "FS" && parts.size() > 1) r.spindle = parseNumber(parts[1]);
    return r.feed.has_value();
  }
  if (name == "Ov") {
    if (parts.size() != 3) return false;
    std::array<int, 3> ov{};
    for (int i = 0; i < 3; ++i) {
      const auto v = parseInt(parts[size_t(i)]);
      if (!v || *v < 0 || *v > 255) return false;  // GRBL keeps each override in a byte
      ov[size_t(i)] = *v;
    }
    r.overrides = ov;
    return true;
  }
  if (name == "Ln") {
    const auto v = parseInt(value);
    if (v) r.lineNumber = *v;
    return v.has_value();
  }
  return true;  // fields this host does not use (T:, ...) are ignored
}

}  // namespace

std::string_view toString(MachineState s) {
  switch (s) {
    case MachineState::Idle: return "Idle";
    case MachineState::Run: return "Run";
    case MachineState::Hold: return "Hold";
    case MachineState::Jog: return "Jog";
    case MachineState::Alarm: return "Alarm";
    case MachineState::Door: return "Door";
    case MachineState::Check: return "Check";
    case MachineState::Home: return "Home";
    case MachineState::Sleep: return "Sleep";
    case MachineState::Unknown: break;
  }
  return "Unknown";
}

std::optional<double> parseNumber(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  if (!std::isfinite(v)) return std::nullopt;  // from_chars reads "inf" and "nan"; GRBL never sends them
  return v;
}

std::optional<Axes> parseAxes(std::string_view text) {
  const auto parts = split(text, ',');
  if (parts.size() < 2 || parts.size() > 3) return std::nullopt;
  Axes a;
  for (const auto& p : parts) {
    const auto v = parseNumber(p);
    if (!v) return std::nullopt;
    a.v[size_t(a.count++)] = *v;
  }
  return a;
}

std::optional<StatusReport> parseStatus(std::string_view body) {
  const auto fields = split(body, '|');
  StatusReport r;
  const auto stateParts = split(fields[0], ':');
  const auto state = parseState(stateParts[0]);
  if (!state) return std::nullopt;
  r.state = *state;
  if (stateParts.size() > 1) {
    const auto sub = parseInt(stateParts[1]);
    if (!sub) return std::nullopt;
    r.subState = *sub;
  }
  for (size_t i = 1; i < fields.size(); ++i) {
    const size_t colon = fields[i].find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    if (!applyField(r, fields[i].substr(0, colon), fields[i].substr(colon + 1)))
      return std::nullopt;
  }
  return r;
}

ParsedLine parseLine(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' '))
    line.remove_suffix(1);
  ParsedLine p;
  p.text = std::string(line);
  p.raw = p.text;
  if (line.empty()) { p.kind = LineKind::Empty; return p; }
  if (line == "ok") { p.kind = LineKind::Ok; return p; }
  if (startsWith(line, "error:") || startsWith(line, "ALARM:")) {
    const auto code = parseInt(line.substr(6));
    if (!code) return p;
    p.kind = line[0] == 'e' ? LineKind::Error : LineKind::Alarm;
    p.code = *code;
    return p;
  }
  if (startsWith(line, "Grbl ")) {
    p.kind = LineKind::Banner;
    const auto rest = line.substr(5);
    p.text = std::string(rest.substr(0, rest.find(' ')));
    return p;
  }
  if (line.front() == '<' && line.back() == '>') {
    if (auto st = parseStatus(line.substr(1, line.size() - 2))) {
      p.kind = LineKind::Status;
      p.status = *st;
    }
    return p;
  }
  if (line.front() == '[' && line.back() == ']') {
    const auto body = line.substr(1, line.size() - 2);
    static constexpr std::pair<std::string_view, LineKind> kTags[] = {
        {"MSG:", LineKind::Message}, {"GC:", LineKind::GcodeState},
        {"VER:", LineKind::Version}, {"OPT:", LineKind::Option}};
    p.kind = LineKind::Feedback;
    p.text = std::string(body);
    for (const auto& [tag, kind] : kTags) {
      if (!startsWith(body, tag)) continue;
      p.kind = kind;
      p.text = std::string(body.substr(tag.size()));
    }
    return p;
  }
  if (line.front() == '$') {
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos) return p;
    const auto id = parseInt(line.substr(1, eq - 1));
    const auto value = parseNumber(line.substr(eq + 1));
    if (!id || !value) return p;
    p.kind = LineKind::Setting;
    p.settingId = *id;
    p.settingValue = *value;
    return p;
  }
  if (line.front() == '>') p.kind = LineKind::StartupEcho;
  return p;
}

}  // namespace fivebar::grbl
