// SPDX-License-Identifier: GPL-3.0-or-later
// The studio at the REAL GRBL 1.1h firmware (../shared/tools/grbl-sim), issue 23's check:
// `fivebar-studio --port PTY --machine hoang2015` (offscreen, settings of its own) connects at
// start as its Connect button does; within 15 s the firmware has received the studio's status
// queries and its `$$` read, and answered them (the firmware's own byte log, -L).
// Skipped when ../shared or the built simulator is absent (scripts/test.sh builds it).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>

#include "firmware_support.hpp"

namespace fivebar {
namespace {

using firmware::Board;
namespace fs = std::filesystem;

// The studio in the background, offscreen, its output in `log`; ended (SIGTERM) on destruction.
class StudioRun {
 public:
  StudioRun(const std::vector<std::string>& arguments, const fs::path& configHome, const fs::path& log) {
    std::vector<std::string> args = {FIVEBAR_STUDIO};
    args.insert(args.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string config = configHome.string(), out = log.string();
    pid_ = fork();
    if (pid_ == 0) {
      setenv("QT_QPA_PLATFORM", "offscreen", 1);
      setenv("XDG_CONFIG_HOME", config.c_str(), 1);  // no remembered profile, port or layout
      if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(out.c_str(), "a", stderr))
        _exit(127);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~StudioRun() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    for (int i = 0; i < 200 && waitpid(pid_, nullptr, WNOHANG) == 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  StudioRun(const StudioRun&) = delete;
  StudioRun& operator=(const StudioRun&) = delete;
  // False once the process has ended.
  bool running() const { return pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0; }

 private:
  pid_t pid_ = -1;
};

// What the firmware's byte log (-L: "WALL_S SIM_S MACHINE_S RX|TX BYTES", control bytes escaped,
// a line per read or write) holds so
// far: status queries received, "$$" lines received, status reports and setting lines sent.
struct Heard {
  int statusQueries = 0, settingsReads = 0, statusReports = 0, settingsSent = 0;
  bool enough() const { return statusQueries >= 2 && settingsReads >= 1 && statusReports >= 2 && settingsSent >= 1; }
};

Heard readByteLog(const fs::path& file) {
  Heard h;
  std::istringstream in(firmware::readText(file));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string wall, simulated, machine, direction;
    fields >> wall >> simulated >> machine >> direction;
    std::string bytes;
    std::getline(fields, bytes);
    if (!bytes.empty() && bytes.front() == ' ') bytes.erase(0, 1);
    if (direction == "RX") {
      if (bytes.find('?') != std::string::npos) ++h.statusQueries;
      if (bytes.find("$$\\n") != std::string::npos) ++h.settingsReads;
    } else if (direction == "TX") {
      if (bytes.find("<Idle|") != std::string::npos) ++h.statusReports;
      if (bytes.find("$100=") != std::string::npos) ++h.settingsSent;
    }
  }
  return h;
}

TEST(StudioOnFirmware, PortAtStartQueriesStatusAndReadsTheSettingsWithin15s) {
  if (!firmware::firmwareAvailable()) GTEST_SKIP() << "the GRBL firmware simulator is not built";
  const fs::path dir = fs::temp_directory_path() / ("fivebar-studio-fw-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "config");
  const fs::path pty = dir / "grblpty", bytes = dir / "bytes.log", log = dir / "studio.log";
  Board board(pty, dir / "state", dir / "steps.csv", {"-L", bytes.string()});
  ASSERT_TRUE(board.up()) << "the firmware did not create " << pty;
  const auto start = std::chrono::steady_clock::now();
  StudioRun studio({"--port", pty.string(), "--machine", "hoang2015"}, dir / "config", log);
  Heard heard;
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(15) && studio.running()) {
    heard = readByteLog(bytes);
    if (heard.enough()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(studio.running()) << "the studio ended early:\n" << firmware::readText(log);
  EXPECT_GE(heard.statusQueries, 2) << firmware::readText(bytes);
  EXPECT_GE(heard.settingsReads, 1) << firmware::readText(bytes);
  EXPECT_GE(heard.statusReports, 2) << "the firmware did not answer the status queries";
  EXPECT_GE(heard.settingsSent, 1) << "the firmware did not list its settings";
  EXPECT_LT(seconds, 15.0);
  std::printf("status queries %d, $$ reads %d after %.1f s\n", heard.statusQueries, heard.settingsReads, seconds);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fivebar
