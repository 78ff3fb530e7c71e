// SPDX-License-Identifier: GPL-3.0-or-later
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
#include "core/output/grbl_setting_table.hpp"
#include "drivers/protocol/grbl_codes.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/transport/serial_transport.hpp"
#include "drivers/stream/stream_session.hpp"
#include "machine_arg.hpp"
#include "machine_cli.hpp"
#include "options.hpp"
#include "stop_signals.hpp"

namespace fivebar::cli {
namespace {

constexpr const char* kStreamHelp =
    "usage: fivebar stream JOB.gcode --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE [--baud 115200]\n"
    "                      [--resume] [--force-profile] [--ignore-settings] [--unchecked]\n"
    "Streams the job with GRBL character counting (128-byte buffer). Progress goes to stderr.\n"
    "What is checked, before the first byte: every line of the file is read as GRBL reads it\n"
    "and every joint move is checked along the path from the job's start (its header's start\n"
    "pose, else its first target): workspace, joint limits and the type II singularity margin\n"
    "of --machine. G2/G3, G10/G92/G55-G59, G20, G28/G30 and $ commands are refused. The first\n"
    "offending line is named and nothing is sent. A job planned for another profile (its\n"
    "'; profile:' header) is refused unless --force-profile. Then the board's real pose is read\n"
    "($# for the work offset): when it differs from the job's start (or the resume point), a\n"
    "checked pen-up travel gets there first, or the stream is refused with the reason (e.g. a\n"
    "board just powered up reads 0,0 until 'fivebar reference').\n"
    "The machine's position must be KNOWN: this computer remembers where each board last stood\n"
    "still; after a power cut, a reset in motion (ALARM:3), a lost connection or a board that\n"
    "reports another position, the stream is refused until 'fivebar reference' (arms in the\n"
    "home pose) or homing ($H). The board's $$ is read anew and compared with the profile\n"
    "($100/$101, $110/$111, $120/$121, $130/$131, $20, $22): a difference refuses the stream,\n"
    "naming each setting (fix: fivebar setup --write; --ignore-settings streams anyway).\n"
    "--unchecked skips the checks (a warning is printed): for experts only.\n"
    "Ctrl+C (or SIGTERM) stops cleanly: feed hold, soft reset with the position kept, pen up,\n"
    "progress saved; a second Ctrl+C resets at once.\n"
    "Exit 0 once every line is acknowledged and the machine is Idle. On an error, alarm, stall or\n"
    "disconnect the machine is brought to a clean state, JOB.gcode.progress is saved and the\n"
    "exit code is 1; --resume continues from the last completed pen-down point with a safe\n"
    "pen-up approach (needs --machine, or the machine recorded in the progress file).\n";

constexpr const char* kSetupHelp =
    "usage: fivebar setup --port DEVICE|tcp:HOST:PORT --machine PRESET|FILE [--baud 115200] [--write]\n"
    "                     [--backup FILE]\n"
    "Reads the board's settings ($$) and compares them with the ones the machine profile\n"
    "expects (see fivebar grbl-settings). With --write, first saves the board's settings to\n"
    "the backup file (default grbl-settings-backup-DATE.txt), then writes the differences one\n"
    "at a time. Exit 0 when the board matches (or was written), 1 on differences without\n"
    "--write or on any failure.\n";

// The machine for `stream`: --machine, else the one recorded in the progress file on resume.
std::optional<MachineProfile> streamMachine(const Options& o, const std::string& jobPath,
                                            std::string& name, bool& failed) {
  failed = false;
  name = o.value("--machine").value_or("");
  if (name.empty() && o.flag("--resume")) {
    std::string ignored;
    if (auto p = stream::loadProgress(stream::progressPathFor(jobPath), &ignored)) name = p->machine;
  }
  if (name.empty()) return std::nullopt;
  auto profile = loadMachine(name, "stream", std::cerr);
  failed = !profile;
  return profile;
}

}  // namespace

int runStream(const Args& args) {
  const Options o(args, {"--port", "--baud", "--machine"},
                  {"--resume", "--help", "--unchecked", "--force-profile", "--ignore-settings"});
  if (o.flag("--help")) { std::cout << kStreamHelp; return 0; }
  if (o.positional().size() != 1) throw UsageError("stream needs exactly one JOB.gcode");
  QtApp qt;
  StreamOptions options;
  options.jobPath = o.positional()[0];
  options.resume = o.flag("--resume");
  options.checked = !o.flag("--unchecked");
  options.forceProfile = o.flag("--force-profile");
  options.checkSettings = !o.flag("--ignore-settings");
  options.portName = o.required("--port");
  if (!options.checked) std::cerr << "fivebar stream: " << kUncheckedWarning;
  bool failed = false;
  options.profile = streamMachine(o, options.jobPath, options.machineName, failed);
  if (failed) return 1;
  const std::unique_ptr<Transport> transport = portTransport(o);
  Transport& port = *transport;
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
  // Ctrl+C / SIGTERM: the clean stop (hold, reset with the position kept, pen up, progress
  // saved); a second one resets at once.
  StopSignals stopOnSignal([&](int count) {
    if (count == 1) {
      std::cerr << "\nfivebar stream: stopping (feed hold, then reset and pen up; Ctrl+C again to "
                   "reset at once)\n";
      session.requestStop();
      return;
    }
    link.protocol().sendRealtime(grbl::realtime::kSoftReset);
    std::cerr << "\nfivebar stream: reset at once; the position may be lost (set the reference "
                 "again before resuming)\n";
    exitCode = 1;
    QTimer::singleShot(200, &qt.app, [&] { qt.app.quit(); });  // let the reset byte leave
  });
  link.start();
  qt.app.exec();
  port.close();
  return exitCode;
}

namespace {

// One row per setting the profile expects: the board's value, the profile's, the unit and what
// the setting means (core/output/grbl_setting_table.hpp; X and Y are the motor angles).
void printComparison(const setup::Settings& board, const setup::Settings& wanted,
                     const std::vector<setup::SettingDiff>& diffs) {
  std::printf("%-8s %14s %14s  %-10s %s\n", "setting", "board", "profile", "unit", "meaning");
  for (const auto& [id, w] : wanted) {
    const auto b = board.find(id);
    const bool differs =
        std::any_of(diffs.begin(), diffs.end(), [id = id](const auto& d) { return d.id == id; });
    char boardText[32] = "-";
    if (b != board.end()) std::snprintf(boardText, sizeof boardText, "%.4f", b->second);
    const GrblSettingInfo* info = grblSettingInfo(id);
    std::printf("$%-7d %14s %14.4f  %-10s %s%s\n", id, boardText, w, info ? info->unit : "",
                info ? info->meaning : "", differs ? "  (differs)" : "");
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
  const std::unique_ptr<Transport> transport = portTransport(o);
  Transport& port = *transport;
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
