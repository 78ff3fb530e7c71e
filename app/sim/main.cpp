// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-sim: the simulated GRBL 1.1 five-bar controller on a pseudo-terminal, so that
// QSerialPort (the studio, `fivebar stream`) or any other sender opens it like a real board.
//
//   fivebar-sim --pty PATH [--machine PRESET|FILE] [--set-up] [--referenced] [--homing-switches]
//               [--speedup N]
//               [--instant] [--fault drop-after=N|reset-after=N|error-on=N|alarm-after=N]
//               [--record FILE] [--baud N] [--true-machine FILE]
//               [--drawn FILE.svg|FILE.csv]
//   fivebar-sim --help | --version
//
// PATH becomes a symlink to the pty's slave device. --record writes the pen-down joint path
// and counters as JSON on exit (SIGTERM / SIGINT) and when an injected drop closes the link.
// --baud N emulates the serial wire (N/10 bytes per second each way, 8N1); without it bytes
// pass as fast as the pty carries them.
#include <fcntl.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSocketNotifier>
#include <QTimer>
#include <atomic>
#include <clocale>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>

#include "core/machine/profile.hpp"
#include "pty.hpp"
#include "wire.hpp"
#include "record.hpp"
#include "drivers/sim/sim_machine.hpp"

namespace {

std::atomic<bool> gQuit{false};
void onSignal(int) { gQuit = true; }

struct Args {
  std::string ptyPath;
  std::string machine = "maker-plotter";
  double speedup = 1.0;
  bool instant = false;
  bool setUp = false;
  bool referenced = false;
  bool homingSwitches = false;
  bool help = false;
  bool version = false;
  fivebar::sim::Fault fault;
  std::string recordPath;
  std::string trueMachine;  // profile file or preset of the real machine ("" the --machine one)
  std::string drawnPath;
  double baud = 0.0;  // 0: no wire emulation
};

constexpr const char* kUsage =
    "usage: fivebar-sim --pty PATH [--machine PRESET|FILE] [--set-up] [--referenced]\n"
    "                   [--homing-switches] [--true-machine FILE] [--drawn FILE.svg|FILE.csv]\n"
    "                   [--speedup N] [--instant] [--baud N] [--record FILE]\n"
    "                   [--fault drop-after=N|reset-after=N|error-on=N|alarm-after=N]\n"
    "A simulated GRBL 1.1h board driving the five-bar of --machine (default maker-plotter) on a\n"
    "pseudo-terminal; PATH becomes a symlink to it. Like a board after power-up it stands at\n"
    "MPos 0,0,0, sends nothing when the port opens and has the firmware's default settings.\n"
    "  --set-up       settings as after 'fivebar setup --write' for the machine\n"
    "  --referenced   G54 as after 'fivebar reference' at the power-up pose (reads as home)\n"
    "  --homing-switches  switches at machine 0 on every axis ($H homes); without it none\n"
    "                 are wired and $H ends in ALARM:9, as the firmware in ../shared\n"
    "  --speedup N    machine seconds per wall second; --instant: moves complete at once\n"
    "  --baud N       time the bytes as on a serial wire of N baud\n"
    "  --record FILE  the pen-down joint path and counters as JSON on exit\n"
    "  --fault ...    one injected fault after N received lines\n"
    "  --true-machine FILE  the real machine the motors drive: a profile whose geometry is the\n"
    "                 true geometry and whose calibration section gives the true motor zero\n"
    "                 offsets, backlash and pen offset (default: --machine itself)\n"
    "  --drawn FILE   what its pen really drew, written on exit like --record: SVG when FILE\n"
    "                 ends in .svg, else CSV stroke,x_mm,y_mm (machine frame, mm)\n"
    "  --help         this text; --version: the version\n";

int usage(const std::string& problem) {
  std::cerr << "fivebar-sim: " << problem << "\n" << kUsage;
  return 2;
}

// Returns an error message, or "" when the arguments are complete.
std::string parseArgs(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string opt = argv[i];
    if (opt == "--instant") { a.instant = true; continue; }
    if (opt == "--set-up") { a.setUp = true; continue; }
    if (opt == "--referenced") { a.referenced = true; continue; }
    if (opt == "--homing-switches") { a.homingSwitches = true; continue; }
    if (opt == "--help" || opt == "-h") { a.help = true; return ""; }
    if (opt == "--version") { a.version = true; return ""; }
    if (i + 1 >= argc) return "option " + opt + " needs a value";
    const std::string value = argv[++i];
    if (opt == "--pty") a.ptyPath = value;
    else if (opt == "--machine") a.machine = value;
    else if (opt == "--record") a.recordPath = value;
    else if (opt == "--true-machine") a.trueMachine = value;
    else if (opt == "--drawn") a.drawnPath = value;
    else if (opt == "--baud") {
      try { a.baud = std::stod(value); } catch (...) { a.baud = -1; }
      if (!(a.baud > 0)) return "--baud needs a positive number, got '" + value + "'";
    } else if (opt == "--speedup") {
      try { a.speedup = std::stod(value); } catch (...) { a.speedup = -1; }
      if (!(a.speedup > 0)) return "--speedup needs a positive number, got '" + value + "'";
    } else if (opt == "--fault") {
      const auto f = fivebar::sim::parseFault(value);
      if (!f) return "--fault '" + value + "' is not drop-after=N, reset-after=N, error-on=N or alarm-after=N";
      a.fault = *f;
    } else {
      return "unknown option " + opt;
    }
  }
  return a.ptyPath.empty() ? "--pty PATH is required" : "";
}

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; the GRBL wire keeps the point
  Args args;
  if (const std::string problem = parseArgs(argc, argv, args); !problem.empty()) return usage(problem);
  if (args.help) {
    std::cout << kUsage;
    return 0;
  }
  if (args.version) {
    std::cout << "fivebar-sim " FIVEBAR_VERSION "\n";
    return 0;
  }
  const fivebar::ProfileLoad load = fivebar::resolveMachine(args.machine);
  if (!load.profile) {
    std::cerr << "fivebar-sim: --machine " << args.machine << ": "
              << (load.issues.empty() ? "unknown" : load.issues.front().field + ": " + load.issues.front().message.text())
              << "\n";
    return 1;
  }
  fivebar::sim::SimConfig config{*load.profile, args.fault, args.instant, args.setUp, args.referenced,
                                  args.homingSwitches, std::nullopt};
  if (!args.trueMachine.empty()) {
    const fivebar::ProfileLoad real = fivebar::resolveMachine(args.trueMachine);
    if (!real.profile) {
      std::cerr << "fivebar-sim: --true-machine " << args.trueMachine << ": "
                << (real.issues.empty() ? "unknown"
                                        : real.issues.front().field + ": " + real.issues.front().message.text())
                << "\n";
      return 1;
    }
    config.trueMachine = real.profile;
  }
  std::string error;
  fivebar::simapp::Pty pty;
  if (!pty.open(args.ptyPath, &error)) {
    std::cerr << "fivebar-sim: " << error << "\n";
    return 1;
  }
  fivebar::sim::SimMachine machine(config);
  std::signal(SIGTERM, onSignal);
  std::signal(SIGINT, onSignal);

  const auto finish = [&](int code) {
    if (!args.recordPath.empty()) {
      const std::string err = fivebar::simapp::writeRecord(machine, args.recordPath);
      if (!err.empty()) std::cerr << "fivebar-sim: " << err << "\n";
    }
    if (!args.drawnPath.empty()) {
      const std::string err = fivebar::simapp::writeDrawn(machine, args.drawnPath);
      if (!err.empty()) std::cerr << "fivebar-sim: " << err << "\n";
    }
    pty.close();
    app.exit(code);
  };
  fivebar::simapp::Wire wire(args.baud);
  QElapsedTimer clock;
  clock.start();
  const auto pump = [&] {
    const double nowS = double(clock.nsecsElapsed()) * 1e-9;
    const std::string in = wire.deliverIn(nowS);
    if (!in.empty()) machine.receive(in);
    wire.queueOut(machine.takeOutput(), nowS);
    pty.write(wire.deliverOut(nowS));
    if (machine.linkDropped()) finish(0);
  };
  QSocketNotifier notifier(pty.masterFd(), QSocketNotifier::Read);
  QObject::connect(&notifier, &QSocketNotifier::activated, [&] {
    wire.queueIn(pty.read(), double(clock.nsecsElapsed()) * 1e-9);
    pump();
  });
  qint64 lastNs = 0;
  QTimer timer;
  QObject::connect(&timer, &QTimer::timeout, [&] {
    if (gQuit) { finish(0); return; }
    const qint64 now = clock.nsecsElapsed();
    machine.advance(double(now - lastNs) * 1e-9 * args.speedup);
    lastNs = now;
    pump();
  });
  timer.start(1);
  std::cerr << "fivebar-sim: " << load.profile->name << " on " << args.ptyPath << " -> "
            << pty.slavePath() << (args.instant ? " (instant)" : "") << "\n";
  pump();
  return app.exec();
}
