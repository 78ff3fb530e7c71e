// SPDX-License-Identifier: GPL-3.0-or-later
#include "grbl_protocol.hpp"

#include <algorithm>
#include <cctype>

#include "core/kinematics/units.hpp"
#include "gcode_words.hpp"

namespace fivebar::grbl {
namespace {

// How long a '?' may stay unanswered before the host assumes the byte was lost on the wire and
// polls again. GRBL always answers '?', so this only matters on a broken link.
constexpr double kStatusLostAfterS = 3.0;

std::string upperNoSpaces(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != ' ') out.push_back(char(std::toupper(static_cast<unsigned char>(c))));
  return out;
}

}  // namespace

std::string describe(EnqueueStatus status) {
  switch (status) {
    case EnqueueStatus::Queued: return "queued";
    case EnqueueStatus::TooLong:
      return "line longer than GRBL's " + std::to_string(kMaxLineChars) +
             " characters (spaces and comments not counted)";
    case EnqueueStatus::Empty: return "empty line";
    case EnqueueStatus::ForbiddenCharacter:
      return "line contains a real-time character (? ! ~ or a byte >= 0x80) or a line break";
  }
  return "unknown";
}

bool isExclusiveLine(std::string_view line) {
  const std::string u = upperNoSpaces(line);
  if (u.rfind("$J=", 0) == 0) return false;
  if (!u.empty() && u[0] == '$') return true;
  return u.find("G10L2") != std::string::npos || u.find("G10L20") != std::string::npos ||
         u.find("L2G10") != std::string::npos || u.find("L20G10") != std::string::npos ||
         u.find("G28.1") != std::string::npos || u.find("G30.1") != std::string::npos;
}

GrblProtocol::GrblProtocol(Writer write, int rxBufferBytes)
    : write_(std::move(write)), rxBufferBytes_(rxBufferBytes) {}

void GrblProtocol::addListener(ProtocolListener* listener) { listeners_.push_back(listener); }
void GrblProtocol::removeListener(ProtocolListener* listener) {
  listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), listener), listeners_.end());
}

EnqueueResult GrblProtocol::enqueue(std::string line) {
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  if (line.empty()) return {EnqueueStatus::Empty, 0};
  if (int(gcode::compact(line).size()) > kMaxLineChars) return {EnqueueStatus::TooLong, 0};
  for (char c : line)
    if (realtime::isRealtime(c) || c == '\n' || c == '\r')
      return {EnqueueStatus::ForbiddenCharacter, 0};
  const std::uint64_t id = nextId_++;
  const bool exclusive = isExclusiveLine(line);
  queue_.push_back({id, std::move(line), exclusive});
  pump();
  return {EnqueueStatus::Queued, id};
}

void GrblProtocol::pump() {
  if (!connected_) return;
  std::string out;
  while (!queue_.empty()) {
    const Line& next = queue_.front();
    const int cost = int(next.text.size()) + 1;
    if (!inFlight_.empty() && (inFlight_.back().exclusive || next.exclusive)) break;
    // An empty buffer always takes one line (rxBufferBytes = 1 gives send-response streaming).
    if (!inFlight_.empty() && bytesInFlight_ + cost > rxBufferBytes_) break;
    out += next.text;
    out += '\n';
    bytesInFlight_ += cost;
    inFlight_.push_back(next);
    queue_.pop_front();
  }
  if (!out.empty()) write_(out);
}

void GrblProtocol::sendRealtime(char byte) {
  if (!connected_) return;
  if (byte == realtime::kStatus) {
    statusOutstanding_ = true;
    lastPollS_ = nowS_;
  }
  write_(std::string_view(&byte, 1));
}

std::vector<std::uint64_t> GrblProtocol::dropQueued() {
  std::vector<std::uint64_t> ids;
  for (const Line& l : queue_) ids.push_back(l.id);
  queue_.clear();
  return ids;
}

void GrblProtocol::receive(std::string_view bytes) {
  for (char c : bytes) {
    if (c == '\n') {
      handleLine(rxPartial_);
      rxPartial_.clear();
    } else if (c != '\r') {
      rxPartial_.push_back(c);
      // A board that never sends a line end must not grow this without bound.
      if (rxPartial_.size() > 4096) rxPartial_.erase(0, rxPartial_.size() - 256);
    }
  }
}

void GrblProtocol::handleLine(std::string_view raw) {
  const ParsedLine p = parseLine(raw);
  if (p.kind == LineKind::Empty) return;
  for (auto* l : listeners_) l->onLine(p);
  switch (p.kind) {
    case LineKind::Ok:
    case LineKind::Error: {
      if (inFlight_.empty()) return;  // stray answer after a reset or alarm: nothing to release
      if (inFlight_.front().id == parametersId_) {
        parametersId_ = 0;
        if (p.kind == LineKind::Ok) offsetFromParameters();
      }
      Ack ack{inFlight_.front().id, std::move(inFlight_.front().text),
              p.kind == LineKind::Error ? p.code : 0};
      if (ack.ok()) noteSettingWrite(ack.line);
      bytesInFlight_ -= int(ack.line.size()) + 1;
      inFlight_.pop_front();
      for (auto* l : listeners_) l->onAck(ack);
      pump();
      return;
    }
    case LineKind::Alarm: {
      std::vector<std::uint64_t> lost;
      resetCounters(&lost, nullptr);
      lastStatus_.state = MachineState::Alarm;
      for (auto* l : listeners_) l->onAlarm(p.code, lost);
      return;
    }
    case LineKind::Banner: {
      std::vector<std::uint64_t> lost, dropped;
      resetCounters(&lost, &dropped);
      statusOutstanding_ = false;
      // A reset restores G54 and clears G92: the offset is known again from the next report
      // (GRBL sends WCO: on the first report after a reset) or from "$#".
      activeSystem_ = "G54";
      params_.erase("G92");
      wco_.reset();
      overrides_.reset();  // a reset puts them back to 100 %: known again from the next Ov:
      version_ = p.text;
      for (auto* l : listeners_) l->onReset(version_, lost, dropped);
      return;
    }
    case LineKind::Version: version_ = p.text.substr(0, p.text.find(':')); return;
    case LineKind::Feedback: {
      const size_t colon = p.text.find(':');
      if (colon == std::string::npos) return;
      const std::string name = p.text.substr(0, colon);
      std::string values = p.text.substr(colon + 1);
      if (name == "TLO") values += ",0,0";
      if (name == "PRB") values = values.substr(0, values.find(':'));
      if (auto a = parseAxes(values)) params_[name] = *a;
      return;
    }
    case LineKind::GcodeState: {
      for (const char* g : {"G54", "G55", "G56", "G57", "G58", "G59"})
        if (p.text.find(g) != std::string::npos) activeSystem_ = g;
      return;
    }
    case LineKind::Status: handleStatus(p.status); return;
    case LineKind::Setting: settings_[p.settingId] = p.settingValue; return;
    default: return;
  }
}

void GrblProtocol::handleStatus(const StatusReport& r) {
  statusOutstanding_ = false;
  ++statusReports_;
  if (r.wco) wco_ = r.wco;
  if (r.overrides) overrides_ = MotionOverrides{(*r.overrides)[0], (*r.overrides)[1]};
  lastStatus_ = r;
  for (auto* l : listeners_) l->onStatus(r);
}

void GrblProtocol::resetCounters(std::vector<std::uint64_t>* lost,
                                 std::vector<std::uint64_t>* dropped) {
  for (const Line& l : inFlight_)
    if (lost) lost->push_back(l.id);
  inFlight_.clear();
  bytesInFlight_ = 0;
  parametersId_ = 0;
  if (dropped) *dropped = dropQueued();
}

void GrblProtocol::tick(double nowS) {
  nowS_ = nowS;
  if (!connected_ || pollIntervalS_ <= 0.0) return;
  if (statusOutstanding_ && nowS - lastPollS_ < kStatusLostAfterS) return;
  if (nowS - lastPollS_ < pollIntervalS_) return;
  sendRealtime(realtime::kStatus);
}

void GrblProtocol::setPollInterval(double intervalS) {
  pollIntervalS_ = intervalS <= 0.0 ? 0.0 : std::max(intervalS, kMinPollIntervalS);
}

void GrblProtocol::disconnected(const std::string& reason) {
  if (!connected_) return;
  connected_ = false;
  resetCounters(nullptr, nullptr);
  settings_.clear();
  queue_.clear();
  overrides_.reset();
  statusOutstanding_ = false;
  for (auto* l : listeners_) l->onDisconnected(reason);
}

std::optional<Axes> GrblProtocol::workPositionDeg() const {
  if (lastStatus_.wpos) return lastStatus_.wpos;
  if (!lastStatus_.mpos || !wco_) return std::nullopt;
  Axes w = *lastStatus_.mpos;
  for (int i = 0; i < 3; ++i) w.v[size_t(i)] -= wco_->v[size_t(i)];
  return w;
}

std::optional<JointAngles> GrblProtocol::motorAngles() const {
  const std::optional<Axes> w = workPositionDeg();
  if (!w) return std::nullopt;
  return JointAngles{radFromDeg(w->x()), radFromDeg(w->y())};
}

std::uint64_t GrblProtocol::requestSettings() {
  const EnqueueResult r = enqueue("$$");
  return r.ok() ? r.id : 0;
}

// "$130=180.000" acknowledged: the board now holds it.
void GrblProtocol::noteSettingWrite(const std::string& line) {
  if (line.size() < 4 || line[0] != '$' || !std::isdigit(static_cast<unsigned char>(line[1]))) return;
  const std::size_t eq = line.find('=');
  if (eq == std::string::npos) return;
  const auto id = parseNumber(std::string_view(line).substr(1, eq - 1));
  const auto value = parseNumber(std::string_view(line).substr(eq + 1));
  if (id && value) settings_[int(*id)] = *value;
}

std::uint64_t GrblProtocol::requestParameters() {
  const EnqueueResult r = enqueue("$#");
  parametersId_ = r.ok() ? r.id : 0;
  return parametersId_;
}

std::optional<Axes> GrblProtocol::parameter(const std::string& name) const {
  const auto it = params_.find(name);
  return it == params_.end() ? std::nullopt : std::optional<Axes>(it->second);
}

// WCO = active G5x offset + G92 offset (+ tool length offset on Z), as GRBL computes it.
void GrblProtocol::offsetFromParameters() {
  const auto system = parameter(activeSystem_);
  if (!system) return;
  Axes w = *system;
  w.count = 3;
  if (const auto g92 = parameter("G92"))
    for (size_t i = 0; i < 3; ++i) w.v[i] += g92->v[i];
  if (const auto tlo = parameter("TLO")) w.v[2] += tlo->v[0];
  wco_ = w;
}

std::optional<Axes> GrblProtocol::machinePositionDeg() const {
  if (lastStatus_.mpos) return lastStatus_.mpos;
  if (lastStatus_.wpos && wco_) {
    Axes m = *lastStatus_.wpos;
    for (int i = 0; i < 3; ++i) m.v[size_t(i)] += wco_->v[size_t(i)];
    return m;
  }
  return std::nullopt;
}

}  // namespace fivebar::grbl
