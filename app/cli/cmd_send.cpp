// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar send: one-off lines to a GRBL board, every line that can move the machine checked
// first (drivers/check/motion_check.hpp) from the board's real pose (drivers/protocol/pose_sync.hpp).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "drivers/protocol/gcode_words.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/protocol/pose_sync.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "machine_arg.hpp"
#include "machine_cli.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kSendHelp =
    "usage: fivebar send --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE [--baud 115200] [--timeout S]\n"
    "                    [--unchecked] LINE...\n"
    "Sends each LINE and prints what the board answers. Settings ($N=V) and other $ commands\n"
    "go one at a time. Real-time commands: ? ! ~ reset (0x18) jog-cancel (0x85).\n"
    "What is checked: before the first line the board's real pose is read (status report, and\n"
    "$# for the work offset). Every line that can move the machine - G0/G1 with X or Y, $J=,\n"
    "G28/G30, G53 moves - is checked from that pose along its joint-linear move: workspace,\n"
    "joint limits and the type II singularity margin of the --machine profile, as jog and job\n"
    "moves are, and - when the board's soft limits are on ($20=1; its $$ is read first) - against\n"
    "the board's travel $130/$131 in machine coordinates, so no line raises ALARM:2. A refused\n"
    "line is not sent, and nothing after it. Always refused: G2/G3 (no arc\n"
    "in joint space), G38 probing, G20, G10/G92/G55-G59 coordinate changes (use fivebar\n"
    "reference). Without --machine, lines that move the machine are refused; non-motion lines\n"
    "and $ commands pass. --unchecked sends motion lines without the check (a warning is\n"
    "printed): for experts only.\n"
    "Exit 0 when every line was answered ok, 1 on a refused line, error:N (explained) or no\n"
    "answer.\n";

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

// Sends the lines one by one (the protocol serialises $ commands itself) and prints the answers.
class Sender : public grbl::ProtocolListener {
 public:
  Sender(MachineLink& link, std::vector<std::string> lines, double timeoutS,
         std::optional<MachineProfile> profile, bool unchecked)
      : link_(link), lines_(std::move(lines)), timeoutS_(timeoutS), profile_(std::move(profile)),
        unchecked_(unchecked), poseSync_(link.protocol(), timeoutS) {
    link_.protocol().addListener(this);
    poseSync_.wantSettings(profile_.has_value() && !unchecked_);  // the board's soft limits
  }
  ~Sender() override { link_.protocol().removeListener(this); }

  // Called on every clock tick; true when done. First learns the board's pose (a status report,
  // the machine at rest, the work offset), then sends the lines one by one.
  bool step(double nowS) {
    if (done_) return true;
    if (!synced_) {
      if (link_.protocol().statusReportsSeen() == 0) {
        if (syncDeadlineS_ == 0.0) syncDeadlineS_ = nowS + timeoutS_;
        if (nowS > syncDeadlineS_) return fail("no status report: is it a GRBL 1.1 board at this baud rate?");
        return false;
      }
      synced_ = true;
      link_.protocol().setPollInterval(0.0);
    }
    if (pending_ > 0) {
      if (nowS < waitingUntilS_) return false;
      return fail("no answer within " + seconds(timeoutS_));
    }
    if (nowS < quietUntilS_) return false;
    if (next_ == lines_.size()) {
      if (!moved_) return finish();
      // A move was sent: wait until the board reports it at rest, so that this computer
      // remembers where it stands (drivers/protocol/pose_trust.hpp) and the next command may trust it.
      if (restDeadlineS_ == 0.0) {
        restDeadlineS_ = nowS + std::max(timeoutS_, 30.0);
        reportsAtEnd_ = link_.protocol().statusReportsSeen();
        link_.protocol().setPollInterval(0.2);
      }
      const grbl::MachineState st = link_.protocol().state();
      if (link_.protocol().statusReportsSeen() > reportsAtEnd_ &&
          (st == grbl::MachineState::Idle || st == grbl::MachineState::Alarm))
        return finish();
      if (nowS > restDeadlineS_) return fail("the machine did not come to rest within " + seconds(std::max(timeoutS_, 30.0)));
      return false;
    }
    const bool goesHome = goesToStoredPosition(lines_[next_]);
    if (needsPose(lines_[next_]) && (!pose_ || (goesHome && !(pose_->g28Machine && pose_->g30Machine)))) {
      if (pose_) poseSync_.restart();  // known, but without the stored positions: ask $#
      pose_.reset();
      poseSync_.wantStoredPositions(goesHome);
      const auto st = poseSync_.step(nowS);
      if (st == grbl::PoseSync::State::Failed) return fail("cannot read the machine's pose: " + poseSync_.problem());
      if (st == grbl::PoseSync::State::Waiting) return false;
      pose_ = motion::boardPoseOf(link_.protocol());
    }
    sendNext(nowS);
    return done_;
  }
  int exitCode() const { return exitCode_; }

  void onLine(const grbl::ParsedLine& l) override {
    if (l.kind == grbl::LineKind::Ok || l.kind == grbl::LineKind::Error) return;
    if (l.kind == grbl::LineKind::Status && !wantStatus_) return;
    if (l.kind == grbl::LineKind::Banner) return;  // onReset reports it
    if (!userLine_ && l.kind != grbl::LineKind::Alarm && l.kind != grbl::LineKind::Message &&
        l.kind != grbl::LineKind::Status)
      return;  // the answer to the pose reading's own $#
    std::cout << l.raw << "\n";
    if (l.kind == grbl::LineKind::Status) { wantStatus_ = false; pending_ = 0; }
    if (l.kind == grbl::LineKind::Alarm) std::cerr << grbl::describeAlarm(l.code) << "\n";
  }
  void onAck(const grbl::Ack& a) override {
    if (a.id != userLineId_) return;  // the pose reading's own $#
    pending_ = 0;
    userLine_ = false;
    if (a.ok()) { std::cout << "ok\n"; return; }
    std::cerr << "'" << a.line << "': " << grbl::describeError(a.errorCode) << "\n";
    exitCode_ = 1;
    pose_.reset();  // the line was not executed: read the pose again before the next move
  }
  void onReset(const std::string& v, const std::vector<std::uint64_t>&,
               const std::vector<std::uint64_t>&) override {
    if (synced_) std::cout << "Grbl " << v << " (reset)\n";
    if (resetPending_) { resetPending_ = false; pending_ = 0; }
    pose_.reset();
    poseSync_.restart();
  }
  void onDisconnected(const std::string& reason) override { fail("connection lost: " + reason); }

 private:
  static bool goesToStoredPosition(const std::string& line) {  // G28 / G30 (not .1)
    const gcode::Words w = gcode::parseWords(gcode::compact(line));
    return w.ok() && (w.hasCode('G', 28) || w.hasCode('G', 30));
  }
  bool needsPose(const std::string& line) const {
    if (!profile_ || unchecked_) return false;
    return motion::interpretLine(line, motion::BoardPose{}).verdict != motion::Verdict::Pass;
  }
  void sendNext(double nowS) {
    const std::string line = lines_[next_++];
    waitingUntilS_ = nowS + timeoutS_;
    namespace rt = grbl::realtime;
    if (line == "?") { wantStatus_ = true; pending_ = 1; link_.protocol().sendRealtime(rt::kStatus); return; }
    if (line == "!" || line == "~" || line == "jog-cancel" || line == "0x85") {
      link_.protocol().sendRealtime(line == "!" ? rt::kFeedHold : line == "~" ? rt::kCycleStart : rt::kJogCancel);
      quietUntilS_ = nowS + 0.2;  // no answer to wait for; give the board a moment
      pose_.reset();
      poseSync_.restart();
      return;
    }
    if (line == "reset" || line == "0x18") {
      resetPending_ = true;
      pending_ = 1;
      link_.protocol().sendRealtime(rt::kSoftReset);
      return;
    }
    if (!unchecked_ && !checkLine(line)) return;
    if (unchecked_ && motion::interpretLine(line, motion::BoardPose{}).verdict == motion::Verdict::Motion) {
      link_.poseTrust().aboutToMove();  // unchecked, but the host still saw it move
      moved_ = true;
    }
    const auto r = link_.protocol().enqueue(line);
    if (!r.ok()) { fail("'" + line + "': " + grbl::describe(r.status)); return; }
    userLineId_ = r.id;
    userLine_ = true;
    pending_ = 1;
  }
  // The motion check; false (after reporting) when the line is refused.
  bool checkLine(const std::string& line) {
    if (!profile_) {
      const motion::LineCheck c = motion::interpretLine(line, motion::BoardPose{});
      if (c.verdict == motion::Verdict::Pass) return true;
      fail("refused '" + line + "': " +
           (c.verdict == motion::Verdict::Refused
                ? c.reason.text()
                : std::string("it moves the machine; give --machine PRESET|FILE so that the move "
                              "can be checked against the machine's workspace")));
      return false;
    }
    const motion::LineCheck c = motion::checkLine(*profile_, line, pose_.value_or(motion::BoardPose{}));
    if (!c.ok()) {
      fail("refused '" + line + "' (not sent): " + c.reason.text());
      return false;
    }
    const bool moves = c.verdict == motion::Verdict::Motion;
    if (moves && !link_.poseTrust().known()) {
      fail("refused '" + line + "' (not sent): the machine's position is not known (" +
           std::string(grbl::toString(link_.poseTrust().doubt())) +
           "): put the arms in the home pose and run 'fivebar reference', or home the machine, first");
      return false;
    }
    if (moves) {
      link_.poseTrust().aboutToMove();
      moved_ = true;
    }
    if (c.systemCommand) {
      pose_.reset();  // $H, $X, settings...: read the pose again before the next move
      poseSync_.restart();
    } else if (pose_) {
      motion::applyLine(line, c, *pose_);
    }
    return true;
  }
  bool fail(const std::string& why) {
    if (!done_) std::cerr << "fivebar send: " << why << "\n";
    exitCode_ = 1;
    done_ = true;
    return true;
  }
  bool finish() { done_ = true; return true; }

  MachineLink& link_;
  std::vector<std::string> lines_;
  double timeoutS_;
  std::optional<MachineProfile> profile_;
  bool unchecked_;
  grbl::PoseSync poseSync_;
  std::optional<motion::BoardPose> pose_;
  std::size_t next_ = 0;
  int pending_ = 0;
  std::uint64_t userLineId_ = 0;
  bool userLine_ = false;
  double waitingUntilS_ = 0.0;
  double quietUntilS_ = 0.0;
  double syncDeadlineS_ = 0.0;
  bool synced_ = false;
  bool moved_ = false;            // a motion line was sent
  double restDeadlineS_ = 0.0;    // waiting for the board at rest after the last line
  std::uint64_t reportsAtEnd_ = 0;
  bool wantStatus_ = false;
  bool resetPending_ = false;
  bool done_ = false;
  int exitCode_ = 0;
};

}  // namespace

int runSend(const Args& args) {
  const Options o(args, {"--port", "--baud", "--timeout", "--machine"}, {"--help", "--unchecked"});
  if (o.flag("--help")) { std::cout << kSendHelp; return 0; }
  if (o.positional().empty()) throw UsageError("send needs at least one LINE");
  double timeoutS = 10.0;
  if (auto t = o.value("--timeout")) timeoutS = numberArg(*t, "--timeout", true);  // seconds
  std::optional<MachineProfile> profile;
  if (const auto m = o.value("--machine")) {
    profile = loadMachine(*m, "send", std::cerr);
    if (!profile) return 1;
  }
  const bool unchecked = o.flag("--unchecked");
  if (unchecked) std::cerr << "fivebar send: " << kUncheckedWarning;
  QtApp qt;
  const std::unique_ptr<Transport> transport = portTransport(o);
  Transport& port = *transport;
  MachineLink link(port, 0.5);  // polls only until the first report; then only on "?"
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar send: " << error.toStdString() << "\n";
    return 1;
  }
  Sender sender(link, o.positional(), timeoutS, std::move(profile), unchecked);
  QObject::connect(&link, &MachineLink::ticked, [&](double now) {
    if (sender.step(now)) qt.app.quit();
  });
  link.start();
  qt.app.exec();
  port.close();
  return sender.exitCode();
}

}  // namespace fivebar::cli
