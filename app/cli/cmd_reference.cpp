// fivebar reference / home: declare the current pose the profile's home pose (G10 L20), and
// bring the machine home ($H with switches, else a checked pen-up move to the home pose).
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "core/kinematics/units.hpp"
#include "core/planning/safety.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/jog/jog.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/check/motion_check.hpp"
#include "drivers/protocol/pose_sync.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "machine_arg.hpp"
#include "machine_cli.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kReferenceHelp =
    "usage: fivebar reference --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE [--baud 115200] [--yes] [--keep]\n"
    "Declares the machine's current pose to be the profile's home pose: the board's work\n"
    "coordinates are set (G10 L20 P0, kept in its EEPROM) so that X/Y read the home angles.\n"
    "Put the arms in the home pose first (by hand, or after $H on a machine with switches).\n"
    "What is checked: the board must be at rest and not in alarm; nothing moves. Asks for\n"
    "confirmation on the terminal unless --yes. Afterwards the reported pose is read back and\n"
    "compared with the home pose, and this computer remembers the board's position as known\n"
    "(fivebar stream, send and home refuse to move a board whose position is not known).\n"
    "--keep confirms the pose the board reports instead, without changing it: for a reset that\n"
    "lost no steps (the arms stand where the board says). Exit 0 when the reference is set, 1\n"
    "otherwise.\n";

constexpr const char* kHomeHelp =
    "usage: fivebar home --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE [--baud 115200] [--timeout S]\n"
    "Brings the machine to the profile's home pose. With homing switches (profile\n"
    "connection.hasHomingSwitches) it runs GRBL's homing cycle ($H) and then compares the pose\n"
    "with the home pose (run fivebar reference once after homing if they differ). Without\n"
    "switches it reads the board's pose and moves there pen up by a safe travel: every move\n"
    "checked like a jog (workspace, joint limits, type II singularity margin); when the pose\n"
    "is unknown or no safe travel exists it refuses and says why. Exit 0 at the home pose.\n";

double timeoutFrom(const Options& o, double fallback) {
  const auto t = o.value("--timeout");
  return t ? numberArg(*t, "--timeout", true) : fallback;  // seconds
}

std::string homeText(const MachineProfile& p) {
  return motion::anglesText(degFromRad(p.homeAngles.theta1), degFromRad(p.homeAngles.theta2));
}

// Asks on the terminal; false (and says so) unless the answer is yes.
bool confirmed(const char* question) {
  std::printf("%s [y/N] ", question);
  std::fflush(stdout);
  std::string answer;
  std::getline(std::cin, answer);
  if (answer == "y" || answer == "Y" || answer == "yes") return true;
  std::cerr << "fivebar reference: not confirmed; nothing was changed\n";
  return false;
}

bool atHome(const MachineProfile& p, const motion::BoardPose& pose, double tolDeg) {
  return std::abs(pose.workDeg[0] - degFromRad(p.homeAngles.theta1)) <= tolDeg &&
         std::abs(pose.workDeg[1] - degFromRad(p.homeAngles.theta2)) <= tolDeg;
}

// One session with the board: read the pose, maybe send lines (each answered before the next),
// wait for rest, read the pose again. The command's logic decides in the callbacks.
class Procedure : public grbl::ProtocolListener {
 public:
  // decide(pose): lines to send (empty: done) or nullopt after reporting a refusal.
  using Decide =
      std::function<std::optional<std::vector<std::string>>(const motion::BoardPose&, MachineLink&)>;
  using Verify = std::function<int(const motion::BoardPose&)>;  // exit code
  Procedure(MachineLink& link, std::string command, double timeoutS, Decide decide, Verify verify)
      : link_(link), command_(std::move(command)), timeoutS_(timeoutS), sync_(link.protocol(), timeoutS),
        decide_(std::move(decide)), verify_(std::move(verify)) {
    link_.protocol().addListener(this);
  }
  ~Procedure() override { link_.protocol().removeListener(this); }

  bool step(double nowS) {
    if (done_) return true;
    if (phase_ == Phase::Sending) {
      if (nowS > deadlineS_) return fail("no answer within " + std::to_string(int(timeoutS_)) + " s");
      if (pending_ != 0) return false;
      if (next_ < lines_.size()) {
        const auto r = link_.protocol().enqueue(lines_[next_++]);
        if (!r.ok()) return fail("'" + lines_[next_ - 1] + "': " + grbl::describe(r.status));
        pending_ = r.id;
        return false;
      }
      phase_ = Phase::Verify;
      sync_.restart();
    }
    const auto st = sync_.step(nowS);
    if (st == grbl::PoseSync::State::Failed) return fail("cannot read the machine's pose: " + sync_.problem());
    if (st == grbl::PoseSync::State::Waiting) return false;
    const auto pose = motion::boardPoseOf(link_.protocol());
    if (!pose) return false;
    if (phase_ == Phase::Verify) return finish(verify_(*pose));
    if (link_.protocol().state() == grbl::MachineState::Alarm && !allowAlarm)
      return fail("the machine is in alarm: check it, then unlock with \"fivebar send --port " +
                  link_.transport().name().toStdString() + " '$X'\" and run this again");
    const auto lines = decide_(*pose, link_);
    if (!lines) return finish(1);
    lines_ = *lines;
    phase_ = Phase::Sending;
    deadlineS_ = nowS + timeoutS_;
    return false;
  }
  int exitCode() const { return exitCode_; }
  bool allowAlarm = false;

  void onAck(const grbl::Ack& a) override {
    if (a.id != pending_) return;
    pending_ = 0;
    if (!a.ok()) fail("'" + a.line + "' was refused: " + grbl::describeError(a.errorCode));
  }
  void onAlarm(int code, const std::vector<std::uint64_t>&) override {
    if (phase_ == Phase::Sending) fail(grbl::describeAlarm(code));
  }
  void onDisconnected(const std::string& reason) override { fail("connection lost: " + reason); }

 private:
  enum class Phase { Read, Sending, Verify };
  bool fail(const std::string& why) {
    if (!done_) std::cerr << "fivebar " << command_ << ": " << why << "\n";
    return finish(1);
  }
  bool finish(int code) {
    if (!done_) exitCode_ = code;
    done_ = true;
    return true;
  }

  MachineLink& link_;
  std::string command_;
  double timeoutS_;
  grbl::PoseSync sync_;
  Decide decide_;
  Verify verify_;
  Phase phase_ = Phase::Read;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
  std::uint64_t pending_ = 0;
  double deadlineS_ = 0.0;
  bool done_ = false;
  int exitCode_ = 1;
};

int runProcedure(const Options& o, const std::string& command, double timeoutS, Procedure::Decide decide,
                 Procedure::Verify verify, bool allowAlarm = false) {
  QtApp qt;
  const std::unique_ptr<Transport> transport = portTransport(o);
  Transport& port = *transport;
  MachineLink link(port, 0.0);
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar " << command << ": " << error.toStdString() << "\n";
    return 1;
  }
  Procedure proc(link, command, timeoutS, std::move(decide), std::move(verify));
  proc.allowAlarm = allowAlarm;
  QObject::connect(&link, &MachineLink::ticked, [&](double now) {
    if (proc.step(now)) qt.app.quit();
  });
  link.start();
  qt.app.exec();
  port.close();
  return proc.exitCode();
}

}  // namespace

int runReference(const Args& args) {
  const Options o(args, {"--port", "--baud", "--machine", "--timeout"}, {"--yes", "--keep", "--help"});
  if (o.flag("--help")) { std::cout << kReferenceHelp; return 0; }
  const bool keep = o.flag("--keep");
  if (!o.positional().empty()) throw UsageError("reference takes no positional arguments");
  const auto profile = loadMachine(o.required("--machine"), "reference", std::cerr);
  if (!profile) return 1;
  const bool yes = o.flag("--yes");
  const double timeoutS = timeoutFrom(o, 10.0);
  const auto decide = [&](const motion::BoardPose& pose,
                          MachineLink& link) -> std::optional<std::vector<std::string>> {
    std::printf("the machine stands at %s (work), %s (machine)\n",
                motion::anglesText(pose.workDeg[0], pose.workDeg[1]).c_str(),
                motion::anglesText(pose.workDeg[0] + pose.wco[0], pose.workDeg[1] + pose.wco[1]).c_str());
    if (keep) {
      const JointAngles q{radFromDeg(pose.workDeg[0]), radFromDeg(pose.workDeg[1])};
      if (const MoveCheck here = checkPose(*profile, q); !here.ok()) {
        std::cerr << "fivebar reference: the board reports " << motion::anglesText(pose.workDeg[0], pose.workDeg[1])
                  << ", which is not a safe pose of " << profile->name << " (" << describe(here)
                  << "): it cannot be where the arms stand. Put them in the home pose and run this "
                     "without --keep\n";
        return std::nullopt;
      }
      if (!yes && !confirmed("Do the arms stand exactly where the board reports?")) return std::nullopt;
      link.poseTrust().confirmed();
      return std::vector<std::string>{};
    }
    std::printf("this pose becomes the home pose of %s: %s\n", profile->name.c_str(), homeText(*profile).c_str());
    if (!yes && !confirmed("Are the arms in the home pose?")) return std::nullopt;
    link.poseTrust().confirmed();  // known from the report after the new offset on
    return std::vector<std::string>{jog::referencePoseCommand(*profile)};
  };
  const auto verify = [&](const motion::BoardPose& pose) {
    if (keep) {
      std::printf("the reported pose %s is confirmed: the position is known\n",
                  motion::anglesText(pose.workDeg[0], pose.workDeg[1]).c_str());
      return 0;
    }
    if (!atHome(*profile, pose, 0.01)) {
      std::cerr << "fivebar reference: the board now reports "
                << motion::anglesText(pose.workDeg[0], pose.workDeg[1]) << ", not the home pose "
                << homeText(*profile) << "\n";
      return 1;
    }
    std::printf("reference set: the machine reports the home pose %s (work offset %.3f, %.3f)\n",
                homeText(*profile).c_str(), pose.wco[0], pose.wco[1]);
    return 0;
  };
  return runProcedure(o, "reference", timeoutS, decide, verify);
}

int runHome(const Args& args) {
  const Options o(args, {"--port", "--baud", "--machine", "--timeout"}, {"--help"});
  if (o.flag("--help")) { std::cout << kHomeHelp; return 0; }
  if (!o.positional().empty()) throw UsageError("home takes no positional arguments");
  const auto profile = loadMachine(o.required("--machine"), "home", std::cerr);
  if (!profile) return 1;
  const double timeoutS = timeoutFrom(o, profile->hasHomingSwitches ? 120.0 : 60.0);
  const std::string port = o.required("--port");
  const auto decide = [&](const motion::BoardPose& pose,
                          MachineLink& link) -> std::optional<std::vector<std::string>> {
    if (profile->hasHomingSwitches) return std::vector<std::string>{"$H"};  // known after its ok
    if (!link.poseTrust().known()) {
      std::cerr << "fivebar home: the machine's position is not known ("
                << grbl::toString(link.poseTrust().doubt()) << "), so no move to the home pose can be "
                << "planned. Put the arms in the home pose " << homeText(*profile) << " by hand and run "
                << "'fivebar reference --port " << port << " --machine " << o.required("--machine") << "'\n";
      return std::nullopt;
    }
    if (atHome(*profile, pose, 1e-3)) return std::vector<std::string>{};
    const JointAngles from{radFromDeg(pose.workDeg[0]), radFromDeg(pose.workDeg[1])};
    if (const MoveCheck here = checkPose(*profile, from); !here.ok()) {
      std::cerr << "fivebar home: the machine reports " << motion::anglesText(pose.workDeg[0], pose.workDeg[1])
                << ", which is not a safe pose of " << profile->name << " (" << describe(here)
                << "): its reference is probably not set. Put the arms in the home pose "
                << homeText(*profile) << " by hand and run 'fivebar reference --port " << port
                << " --machine " << o.required("--machine") << "'\n";
      return std::nullopt;
    }
    const auto travel = planSafeTravel(*profile, from, profile->homeAngles);
    if (!travel) {
      std::cerr << "fivebar home: no safe pen-up travel from "
                << motion::anglesText(pose.workDeg[0], pose.workDeg[1]) << " to the home pose "
                << homeText(*profile) << "; jog the machine closer first\n";
      return std::nullopt;
    }
    std::vector<std::string> lines{"G90"};
    for (const std::string& s : stream::penUpCommands(profile->tool)) lines.push_back(s);
    motion::BoardPose at = pose;
    for (const JointAngles& q : *travel) {
      const std::string line = stream::moveTo({degFromRad(q.theta1), degFromRad(q.theta2)}, true);
      const motion::LineCheck c = motion::checkLine(*profile, line, at);  // the one motion check
      if (!c.ok()) {
        std::cerr << "fivebar home: refused '" << line << "': " << c.reason << "\n";
        return std::nullopt;
      }
      motion::applyLine(line, c, at);
      lines.push_back(line);
    }
    std::printf("moving pen up to the home pose %s in %zu checked move(s)\n", homeText(*profile).c_str(),
                travel->size());
    link.poseTrust().aboutToMove();
    return lines;
  };
  const auto verify = [&](const motion::BoardPose& pose) {
    if (atHome(*profile, pose, 0.01)) {
      std::printf("at the home pose %s\n", homeText(*profile).c_str());
      return 0;
    }
    if (profile->hasHomingSwitches) {
      std::printf("homed; the work pose is %s, not the home pose %s: run 'fivebar reference --port %s "
                  "--machine %s --yes' once now so that the switches define the home pose\n",
                  motion::anglesText(pose.workDeg[0], pose.workDeg[1]).c_str(), homeText(*profile).c_str(),
                  port.c_str(), o.required("--machine").c_str());
      return 0;
    }
    std::cerr << "fivebar home: the machine stopped at " << motion::anglesText(pose.workDeg[0], pose.workDeg[1])
              << ", not at the home pose " << homeText(*profile) << "\n";
    return 1;
  };
  // $H is the way out of the alarm a board with homing switches starts in.
  return runProcedure(o, "home", timeoutS, decide, verify, profile->hasHomingSwitches);
}

}  // namespace fivebar::cli
