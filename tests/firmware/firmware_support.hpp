// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the tests that run the REAL GRBL 1.1h firmware (../shared/tools/grbl-sim, a host
// build of gnea/grbl on a pseudo-terminal): where the simulator is, starting and stopping it,
// running the built `fivebar` CLI against it, and reading its motor step trace.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fivebar::firmware {

namespace fs = std::filesystem;

inline fs::path simulatorExe() {
  const char* build = std::getenv("GRBL_SIM_BUILD");
  const char* home = std::getenv("HOME");
  if (build) return fs::path(build) / "grbl_sim.exe";
  return home ? fs::path(home) / ".cache/grbl-sim/grbl_sim.exe" : fs::path();
}
inline fs::path startScript() { return fs::path(FIVEBAR_SHARED_DIR) / "tools/grbl-sim/start.sh"; }
// True when ../shared and the built simulator are both there (the tests skip otherwise).
inline bool firmwareAvailable() { return fs::exists(startScript()) && fs::exists(simulatorExe()); }

// One motor-step sample of the firmware's trace (-s FILE -r 0.001): machine time, the X/Y/Z step
// counters since power-up, the spindle (0 = off: pen up for a pen-servo tool with penUpS 0).
struct Sample {
  double t = 0.0;
  long s1 = 0, s2 = 0;
  int spindle = 0;
};

inline std::vector<Sample> readTrace(const fs::path& file) {
  std::vector<Sample> out;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream s(line);
    Sample x;
    long z = 0;
    if (s >> x.t >> x.s1 >> x.s2 >> z >> x.spindle) out.push_back(x);
  }
  return out;
}

// A powered board: the firmware on a pty at `pty`, its EEPROM in `stateDir` (kept across
// restarts, as a board's), its step trace written to `trace`; `extra` options of grbl_sim.exe
// after those (e.g. {"-L", FILE}: every byte received and sent). `speedup` > 1 runs the machine
// that many times faster than the wall clock (README: for tests where timing is not what they
// check). The destructor pulls the cable.
class Board {
 public:
  Board(const fs::path& pty, const fs::path& stateDir, const fs::path& trace,
        const std::vector<std::string>& extra = {}, int speedup = 1)
      : pty_(pty) {
    fs::remove(pty);
    std::vector<std::string> args = {"sh",          startScript().string(), pty.string(), std::to_string(speedup),
                                     stateDir.string(), "-s", trace.string(), "-r", "0.001"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      if (!std::freopen("/dev/null", "w", stdout)) _exit(127);
      execv("/bin/sh", argv.data());
      _exit(127);
    }
    for (int i = 0; i < 200 && !fs::exists(pty); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  ~Board() { powerOff(); }
  Board(const Board&) = delete;
  Board& operator=(const Board&) = delete;

  bool up() const { return pid_ > 0 && fs::exists(pty_); }
  // Like pulling the USB cable (and the power): the process ends at once, the pty vanishes.
  void powerOff() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  fs::path pty_;
  pid_t pid_ = -1;
};

// A `fivebar` CLI run in the background, its stdout and stderr in `log`.
class CliRun {
 public:
  CliRun(const std::string& arguments, const fs::path& log) {
    pid_ = fork();
    if (pid_ == 0) {
      const std::string command = "exec " + std::string(FIVEBAR_CLI) + " " + arguments + " >" +
                                  log.string() + " 2>&1";
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
  }
  ~CliRun() {
    if (pid_ > 0 && !finished_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  CliRun(const CliRun&) = delete;
  CliRun& operator=(const CliRun&) = delete;

  // Sends a signal to the CLI itself (the shell exec'd it), as Ctrl+C or kill would.
  void signal(int sig) const {
    if (pid_ > 0 && !finished_) ::kill(pid_, sig);
  }

  // The exit code, or -1 when it did not end within timeoutS (then it is killed).
  int wait(double timeoutS) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        finished_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
  }

 private:
  pid_t pid_ = -1;
  bool finished_ = false;
};

// Runs the CLI in the foreground; returns its exit code, its output in *output.
inline int runCli(const std::string& arguments, const fs::path& log, double timeoutS,
                  std::string* output = nullptr) {
  CliRun run(arguments, log);
  const int code = run.wait(timeoutS);
  if (output) {
    std::ifstream in(log);
    *output = std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return code;
}

inline std::string readText(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace fivebar::firmware
