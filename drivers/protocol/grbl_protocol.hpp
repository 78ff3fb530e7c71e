// SPDX-License-Identifier: GPL-3.0-or-later
// GrblProtocol: the host side of the GRBL 1.1 serial protocol as a pure state machine. No I/O:
// bytes to send go out through a write function, received bytes come in through receive(), time
// comes in through tick(nowS). It owns
//  - line framing of received bytes and dispatch of parsed lines to listeners;
//  - character-counting streaming: at most rxBufferBytes (128) unacknowledged bytes, counting
//    line.size() + 1 per line, released on each ok / error:N;
//  - the rule that "$" system commands and settings writes ($N=V, also G10 L2/L20, G28.1,
//    G30.1 which write EEPROM) go one at a time: sent only when nothing is in flight, and
//    nothing else is sent until they are answered;
//  - real-time bytes (? ! ~ 0x18 0x85 0x90-0x9D), which bypass the budget;
//  - status polling at a configurable rate (at most 5 Hz), never two '?' outstanding;
//  - the reset rule: a banner or an ALARM invalidates every counter; lines in flight are lost.
// Positions: the board's X/Y are theta1/theta2 in degrees (conventions.md).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "grbl_parser.hpp"
#include "overrides.hpp"

namespace fivebar::grbl {

inline constexpr int kRxBufferBytes = 128;  // GRBL 1.1 serial receive buffer
// Longest line GRBL 1.1h accepts: its line buffer holds 80 bytes with the terminator, and it
// stores neither spaces nor comments, so this counts the characters of the compacted line.
inline constexpr int kMaxLineChars = 79;
inline constexpr int kPlannerBlocks = 15;   // usable planner blocks (Bf reports 15 when empty)
// Blocks that may still be running after the planner dropped them: stepper.c discards a planner
// block once it is cut into step segments, and its ring of SEGMENT_BUFFER_SIZE 6 holds up to 5
// segments (about 10 ms each, each of one block) still to execute. Measured on the real firmware:
// a reset right after Bf: freed a block lost up to 2 mm of that block's drawing.
inline constexpr int kSegmentBufferBlocks = 5;
inline constexpr double kMinPollIntervalS = 0.2;  // 5 Hz: polling never faster than this

namespace realtime {
inline constexpr char kStatus = '?';
inline constexpr char kFeedHold = '!';
inline constexpr char kCycleStart = '~';
inline constexpr char kSoftReset = 0x18;
inline constexpr char kJogCancel = char(0x85);
inline constexpr char kFeed100 = char(0x90);  // feed override reset; 0x91-0x94 +-10 / +-1 %
inline constexpr char kRapid100 = char(0x95); // rapid override 100 / 50 / 25 % (0x95-0x97)
inline constexpr char kSpindle100 = char(0x99);  // spindle override 0x99-0x9D
// True for every byte GRBL intercepts as a real-time command.
constexpr bool isRealtime(char c) {
  const auto u = static_cast<unsigned char>(c);
  return c == kStatus || c == kFeedHold || c == kCycleStart || c == kSoftReset || u >= 0x80;
}
}  // namespace realtime

// Answer to one line: errorCode 0 for "ok", N for "error:N".
struct Ack {
  std::uint64_t id = 0;
  std::string line;
  int errorCode = 0;
  bool ok() const { return errorCode == 0; }
};

// Receives protocol events. Every method has an empty default.
class ProtocolListener {
 public:
  virtual ~ProtocolListener() = default;
  virtual void onAck(const Ack& /*ack*/) {}
  virtual void onStatus(const StatusReport& /*report*/) {}
  virtual void onAlarm(int /*code*/, const std::vector<std::uint64_t>& /*lostIds*/) {}
  // The board reset (banner seen). lostIds: lines sent but never answered, now discarded;
  // lines queued but not sent are discarded too (dropped lists them).
  virtual void onReset(const std::string& /*version*/, const std::vector<std::uint64_t>& /*lostIds*/,
                       const std::vector<std::uint64_t>& /*dropped*/) {}
  virtual void onLine(const ParsedLine& /*line*/) {}
  virtual void onDisconnected(const std::string& /*reason*/) {}
};

enum class EnqueueStatus { Queued, TooLong, Empty, ForbiddenCharacter };
struct EnqueueResult {
  EnqueueStatus status = EnqueueStatus::Queued;
  std::uint64_t id = 0;  // valid when Queued
  bool ok() const { return status == EnqueueStatus::Queued; }
};
std::string describe(EnqueueStatus status);

// True for lines that must go one at a time: "$" commands except "$J=", and G10 L2/L20,
// G28.1, G30.1 (EEPROM writes).
bool isExclusiveLine(std::string_view line);

class GrblProtocol {
 public:
  using Writer = std::function<void(std::string_view bytes)>;
  explicit GrblProtocol(Writer write, int rxBufferBytes = kRxBufferBytes);

  void addListener(ProtocolListener* listener);
  void removeListener(ProtocolListener* listener);

  // Queues a line (without '\n') for counted streaming and sends what the budget allows.
  EnqueueResult enqueue(std::string line);
  // Sends one real-time byte at once (never counted).
  void sendRealtime(char byte);
  // Drops the lines queued but not yet sent; returns their ids. Lines in flight stay counted.
  std::vector<std::uint64_t> dropQueued();

  // Bytes from the board, in any fragmentation.
  void receive(std::string_view bytes);
  // Advances the poll clock (seconds, monotonic); sends '?' when due and none is outstanding.
  void tick(double nowS);
  void setPollInterval(double intervalS);  // clamped to >= kMinPollIntervalS; <= 0 disables
  // Receive-buffer budget for character counting (bytes). 1 = send-response (one line at a
  // time, waiting for each answer): the baseline the benchmarks compare against.
  void setRxBufferBytes(int bytes) { rxBufferBytes_ = bytes; }
  // The transport is gone: every counter resets, listeners hear onDisconnected once.
  void disconnected(const std::string& reason);

  int bytesInFlight() const { return bytesInFlight_; }
  std::size_t linesInFlight() const { return inFlight_.size(); }
  std::size_t linesQueued() const { return queue_.size(); }
  bool idleLink() const { return inFlight_.empty() && queue_.empty(); }
  bool statusOutstanding() const { return statusOutstanding_; }
  const StatusReport& lastStatus() const { return lastStatus_; }
  MachineState state() const { return lastStatus_.state; }
  const std::string& version() const { return version_; }
  std::uint64_t statusReportsSeen() const { return statusReports_; }
  // Motor angles (rad) from the last report's work position (WPos, or MPos - WCO): the frame in
  // which the G-code's X/Y are theta1/theta2. nullopt before the first report, and while the
  // reports carry MPos but the work offset is not known yet (GRBL sends WCO: only on some
  // reports; requestParameters() asks for it).
  std::optional<JointAngles> motorAngles() const;
  // Work position (X, Y deg, Z mm), under the same rule as motorAngles().
  std::optional<Axes> workPositionDeg() const;
  // Feed and rapid override as the board last reported them (an Ov: field; most reports have
  // none, so this keeps the last one); nullopt before the first and after a reset or a
  // disconnect until the next.
  const std::optional<MotionOverrides>& reportedOverrides() const { return overrides_; }
  // The work coordinate offset, from a WCO: report or from `$#` (G54..G59 active + G92, TLO).
  const std::optional<Axes>& workOffset() const { return wco_; }
  // Sends "$#" (the board's coordinate parameters: G54..G59, G28, G30, G92, TLO); its answer
  // sets the work offset and the stored G28 / G30 positions. Returns the line's id (0 when it
  // could not be queued). Only valid in Idle or Alarm (GRBL answers error:8 otherwise).
  std::uint64_t requestParameters();
  bool parametersPending() const { return parametersId_ != 0; }
  // Stored positions (machine coordinates) from the last "$#": "G28", "G30", "G54".., "G92".
  std::optional<Axes> parameter(const std::string& name) const;
  // The board's $ settings as last listed (a "$$" answer, whoever asked) or written (an
  // acknowledged "$N=V"); empty before. Kept over resets (they live in the board's EEPROM).
  const std::map<int, double>& boardSettings() const { return settings_; }
  // Sends "$$"; returns the line's id (0 when it could not be queued).
  std::uint64_t requestSettings();
  // Raw machine position (MPos) in degrees, when known.
  std::optional<Axes> machinePositionDeg() const;

 private:
  struct Line {
    std::uint64_t id;
    std::string text;
    bool exclusive;
  };
  void pump();
  void handleLine(std::string_view raw);
  void handleStatus(const StatusReport& r);
  void offsetFromParameters();
  void noteSettingWrite(const std::string& line);
  void resetCounters(std::vector<std::uint64_t>* lost, std::vector<std::uint64_t>* dropped);

  Writer write_;
  int rxBufferBytes_;
  std::vector<ProtocolListener*> listeners_;
  std::deque<Line> queue_;
  std::deque<Line> inFlight_;
  int bytesInFlight_ = 0;
  std::uint64_t nextId_ = 1;
  std::string rxPartial_;
  double pollIntervalS_ = kMinPollIntervalS;
  double lastPollS_ = -1e300;
  double nowS_ = 0.0;
  bool statusOutstanding_ = false;
  StatusReport lastStatus_;
  std::optional<Axes> wco_;
  std::optional<MotionOverrides> overrides_;
  std::map<std::string, Axes> params_;
  std::map<int, double> settings_;
  std::string activeSystem_ = "G54";
  std::uint64_t parametersId_ = 0;
  std::string version_;
  std::uint64_t statusReports_ = 0;
  bool connected_ = true;
};

}  // namespace fivebar::grbl
