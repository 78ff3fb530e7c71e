// fivebar stream / send / setup: the machine commands (GRBL 1.1 over a serial port or the
// simulator's pseudo-terminal). Protocol rules and resume format: docs/machine-protocol.md.
#include <QCoreApplication>
#include <QDateTime>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "drivers/grbl_codes.hpp"
#include "drivers/machine_link.hpp"
#include "drivers/machine_setup.hpp"
#include "drivers/serial_transport.hpp"
#include "drivers/stream_session.hpp"
#include "machine_arg.hpp"
#include "options.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kStreamHelp =
    "usage: fivebar stream JOB.gcode --port DEVICE [--baud 115200] [--machine PRESET|FILE]\n"
    "                      [--resume]\n"
    "Streams the job with GRBL character counting (128-byte buffer). Progress goes to stderr.\n"
    "Exit 0 once every line is acknowledged and the machine is Idle. On an error, alarm or\n"
    "disconnect the machine is brought to a clean state, JOB.gcode.progress is saved and the\n"
    "exit code is 1; --resume continues from the last completed pen-down point with a safe\n"
    "pen-up approach (needs --machine, or the machine recorded in the progress file).\n";

constexpr const char* kSendHelp =
    "usage: fivebar send --port DEVICE [--baud 115200] [--timeout S] LINE...\n"
    "Sends each LINE and prints what the board answers. Settings ($N=V) and other $ commands\n"
    "go one at a time. Real-time commands: ? ! ~ reset (0x18) jog-cancel (0x85).\n"
    "Exit 0 when every line was answered ok, 1 on error:N (explained) or no answer.\n";

constexpr const char* kSetupHelp =
    "usage: fivebar setup --port DEVICE --machine PRESET|FILE [--baud 115200] [--write]\n"
    "                     [--backup FILE]\n"
    "Reads the board's settings ($$) and compares them with the ones the machine profile\n"
    "expects (see fivebar grbl-settings). With --write, first saves the board's settings to\n"
    "the backup file (default grbl-settings-backup-DATE.txt), then writes the differences one\n"
    "at a time. Exit 0 when the board matches (or was written), 1 on differences without\n"
    "--write or on any failure.\n";

// QCoreApplication for a command that needs Qt's event loop.
struct QtApp {
  int argc = 1;
  char name[8] = "fivebar";
  char* argv[2] = {name, nullptr};
  QCoreApplication app{argc, argv};
};

int baudFrom(const Options& o) {
  const std::string b = o.value("--baud").value_or("115200");
  try {
    const int v = std::stoi(b);
    if (v > 0) return v;
  } catch (...) {
  }
  throw UsageError("--baud needs a positive integer, got '" + b + "'");
}

// The machine for `stream`: --machine, else the one recorded in the progress file on resume.
std::optional<MachineProfile> streamMachine(const Options& o, const std::string& jobPath,
                                            std::string& name, bool& failed) {
  failed = false;
  name = o.value("--machine").value_or("");
  if (name.empty() && o.flag("--resume")) {
    std::string ignored;
    if (auto p = job::loadProgress(job::progressPathFor(jobPath), &ignored)) name = p->machine;
  }
  if (name.empty()) return std::nullopt;
  auto profile = loadMachine(name, "stream", std::cerr);
  failed = !profile;
  return profile;
}

}  // namespace

int runStream(const Args& args) {
  const Options o(args, {"--port", "--baud", "--machine"}, {"--resume", "--help"});
  if (o.flag("--help")) { std::cout << kStreamHelp; return 0; }
  if (o.positional().size() != 1) throw UsageError("stream needs exactly one JOB.gcode");
  QtApp qt;
  StreamOptions options;
  options.jobPath = o.positional()[0];
  options.resume = o.flag("--resume");
  bool failed = false;
  options.profile = streamMachine(o, options.jobPath, options.machineName, failed);
  if (failed) return 1;
  SerialTransport port(QString::fromStdString(o.required("--port")), baudFrom(o));
  MachineLink link(port);
  StreamSession session(link, options);
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar stream: " << error.toStdString() << "\n";
    return 1;
  }
  std::string problem;
  if (!session.begin(&problem)) {
    std::cerr << "fivebar stream: " << problem << "\n";
    return 1;
  }
  int exitCode = 1;
  QObject::connect(&session, &StreamSession::progress, [](const QString& text) {
    std::cerr << "\r" << text.toStdString() << "   " << std::flush;
  });
  QObject::connect(&session, &StreamSession::finished, [&](bool ok, const QString& message) {
    std::cerr << "\n" << (ok ? "fivebar stream: " : "fivebar stream: stopped: ")
              << message.toStdString() << "\n";
    exitCode = ok ? 0 : 1;
    qt.app.quit();
  });
  link.start();
  qt.app.exec();
  port.close();
  return exitCode;
}

namespace {

// Sends the lines of `send` one by one (the protocol serialises $ commands itself) and prints
// the answers. Returns the exit code.
class Sender : public grbl::ProtocolListener {
 public:
  Sender(MachineLink& link, std::vector<std::string> lines, double timeoutS)
      : link_(link), lines_(std::move(lines)), timeoutS_(timeoutS) {
    link_.protocol().addListener(this);
  }
  ~Sender() override { link_.protocol().removeListener(this); }

  // Called on every clock tick; true when done. First waits for a status report (the board is
  // up and any stale banner has been read), then sends the lines one by one.
  bool step(double nowS) {
    if (done_) return true;
    if (!synced_) {
      if (syncDeadlineS_ == 0.0) syncDeadlineS_ = nowS + timeoutS_;
      if (link_.protocol().statusReportsSeen() == 0) {
        if (nowS > syncDeadlineS_) return fail("no status report: is it a GRBL 1.1 board at this baud rate?");
        return false;
      }
      synced_ = true;
      link_.protocol().setPollInterval(0.0);
    }
    if (pending_ > 0) {
      if (nowS < waitingUntilS_) return false;
      return fail("no answer within " + std::to_string(int(timeoutS_)) + " s");
    }
    if (nowS < quietUntilS_) return false;
    if (next_ == lines_.size()) return finish();
    sendNext(nowS);
    return done_;
  }
  int exitCode() const { return exitCode_; }

  void onLine(const grbl::ParsedLine& l) override {
    if (l.kind == grbl::LineKind::Ok || l.kind == grbl::LineKind::Error) return;
    if (l.kind == grbl::LineKind::Status && !wantStatus_) return;
    if (l.kind == grbl::LineKind::Banner) return;  // onReset reports it
    std::cout << l.raw << "\n";
    if (l.kind == grbl::LineKind::Status) { wantStatus_ = false; pending_ = 0; }
    if (l.kind == grbl::LineKind::Alarm) std::cerr << grbl::describeAlarm(l.code) << "\n";
  }
  void onAck(const grbl::Ack& a) override {
    pending_ = 0;
    if (a.ok()) { std::cout << "ok\n"; return; }
    std::cerr << "'" << a.line << "': " << grbl::describeError(a.errorCode) << "\n";
    exitCode_ = 1;
  }
  void onReset(const std::string& v, const std::vector<std::uint64_t>&,
               const std::vector<std::uint64_t>&) override {
    if (synced_) std::cout << "Grbl " << v << " (reset)\n";
    if (resetPending_) { resetPending_ = false; pending_ = 0; }
  }
  void onDisconnected(const std::string& reason) override { fail("connection lost: " + reason); }

 private:
  void sendNext(double nowS) {
    const std::string line = lines_[next_++];
    waitingUntilS_ = nowS + timeoutS_;
    namespace rt = grbl::realtime;
    if (line == "?") { wantStatus_ = true; pending_ = 1; link_.protocol().sendRealtime(rt::kStatus); return; }
    if (line == "!" || line == "~" || line == "jog-cancel" || line == "0x85") {
      link_.protocol().sendRealtime(line == "!" ? rt::kFeedHold : line == "~" ? rt::kCycleStart : rt::kJogCancel);
      quietUntilS_ = nowS + 0.2;  // no answer to wait for; give the board a moment
      return;
    }
    if (line == "reset" || line == "0x18") {
      resetPending_ = true;
      pending_ = 1;
      link_.protocol().sendRealtime(rt::kSoftReset);
      return;
    }
    const auto r = link_.protocol().enqueue(line);
    if (!r.ok()) { fail("'" + line + "': " + grbl::describe(r.status)); return; }
    pending_ = 1;
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
  std::size_t next_ = 0;
  int pending_ = 0;
  double waitingUntilS_ = 0.0;
  double quietUntilS_ = 0.0;
  double syncDeadlineS_ = 0.0;
  bool synced_ = false;
  bool wantStatus_ = false;
  bool resetPending_ = false;
  bool done_ = false;
  int exitCode_ = 0;
};

}  // namespace

int runSend(const Args& args) {
  const Options o(args, {"--port", "--baud", "--timeout"}, {"--help"});
  if (o.flag("--help")) { std::cout << kSendHelp; return 0; }
  if (o.positional().empty()) throw UsageError("send needs at least one LINE");
  double timeoutS = 10.0;
  if (auto t = o.value("--timeout")) {
    try { timeoutS = std::stod(*t); } catch (...) { timeoutS = -1; }
    if (!(timeoutS > 0)) throw UsageError("--timeout needs a positive number of seconds");
  }
  QtApp qt;
  SerialTransport port(QString::fromStdString(o.required("--port")), baudFrom(o));
  MachineLink link(port, 0.5);  // polls only until the first report; then only on "?"
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar send: " << error.toStdString() << "\n";
    return 1;
  }
  Sender sender(link, o.positional(), timeoutS);
  QObject::connect(&link, &MachineLink::ticked, [&](double now) {
    if (sender.step(now)) qt.app.quit();
  });
  link.start();
  qt.app.exec();
  port.close();
  return sender.exitCode();
}

namespace {

void printComparison(const setup::Settings& board, const setup::Settings& wanted,
                     const std::vector<setup::SettingDiff>& diffs) {
  std::printf("%-8s %14s %14s\n", "setting", "board", "profile");
  for (const auto& [id, w] : wanted) {
    const auto b = board.find(id);
    const bool differs =
        std::any_of(diffs.begin(), diffs.end(), [id = id](const auto& d) { return d.id == id; });
    char boardText[32] = "-";
    if (b != board.end()) std::snprintf(boardText, sizeof boardText, "%.4f", b->second);
    std::printf("$%-7d %14s %14.4f%s\n", id, boardText, w, differs ? "  differs" : "");
  }
  std::printf("%zu setting(s) differ\n", diffs.size());
}

std::string saveBackupFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.flush();
  return out ? std::string() : path + ": cannot write the backup file";
}

}  // namespace

int runSetup(const Args& args) {
  const Options o(args, {"--port", "--baud", "--machine", "--backup"}, {"--write", "--help"});
  if (o.flag("--help")) { std::cout << kSetupHelp; return 0; }
  if (!o.positional().empty()) throw UsageError("setup takes no positional arguments");
  const auto profile = loadMachine(o.required("--machine"), "setup", std::cerr);
  if (!profile) return 1;
  const bool write = o.flag("--write");
  const std::string backupPath = o.value("--backup").value_or(
      "grbl-settings-backup-" +
      QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")).toStdString() +
      ".txt");
  QtApp qt;
  SerialTransport port(QString::fromStdString(o.required("--port")), baudFrom(o));
  MachineLink link(port, 0.5);
  QString error;
  if (!port.open(&error)) {
    std::cerr << "fivebar setup: " << error.toStdString() << "\n";
    return 1;
  }
  const setup::Settings wanted = setup::expectedSettings(*profile);
  setup::SettingsSync sync(link.protocol());
  std::vector<setup::SettingDiff> diffs;
  int exitCode = 1;
  bool reading = false, writing = false;
  const double timeoutS = 10.0;
  double deadlineS = -1.0;
  const auto stop = [&](int code, const std::string& message) {
    if (!message.empty()) std::cerr << "fivebar setup: " << message << "\n";
    exitCode = code;
    qt.app.quit();
  };
  QObject::connect(&link, &MachineLink::ticked, [&](double nowS) {
    if (deadlineS < 0.0) deadlineS = nowS + timeoutS;
    if (sync.state() == setup::SetupState::Failed) return stop(1, sync.problem());
    if (!reading) {
      if (link.protocol().statusReportsSeen() == 0) {
        if (nowS > deadlineS) stop(1, "no status report: is it a GRBL 1.1 board at this baud rate?");
        return;
      }
      reading = true;
      deadlineS = nowS + timeoutS;
      return sync.read();
    }
    if (sync.state() != setup::SetupState::Done) {
      if (nowS > deadlineS) stop(1, "no answer within " + std::to_string(int(timeoutS)) + " s");
      return;
    }
    if (writing) {
      std::printf("wrote %zu setting(s); backup of the previous settings: %s\n", diffs.size(),
                  backupPath.c_str());
      return stop(0, "");
    }
    diffs = setup::compare(sync.board(), wanted);
    printComparison(sync.board(), wanted, diffs);
    if (diffs.empty() || !write) return stop(diffs.empty() ? 0 : 1, "");
    writing = true;
    deadlineS = nowS + timeoutS + 0.5 * double(diffs.size());
    sync.apply(diffs, [&](const std::string& text) { return saveBackupFile(backupPath, text); });
  });
  link.start();
  qt.app.exec();
  port.close();
  return exitCode;
}

}  // namespace fivebar::cli
