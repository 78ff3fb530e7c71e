// SPDX-License-Identifier: GPL-3.0-or-later
// The REAL GRBL 1.1h firmware (../shared/tools/grbl-sim) on behaviours the simulated GRBL and the
// motion check copy from it:
//  - a feed hold while Idle is a completed hold: the status says Hold:0 at once;
//  - a line sent during a hold is not read (protocol_exec_rt_suspend): its ok comes only after
//    the cycle start;
//  - a target beyond the soft limits that comes while a move runs holds the feed (Hold:1, a
//    controlled stop), then ALARM:2, the line not answered;
//  - with soft limits on, `fivebar send` refuses a target outside the board's travel (machine
//    coordinates) before a byte is sent, and the same line sent unchecked raises ALARM:2.
// Skipped when ../shared or the built simulator is absent (scripts/test.sh builds it).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <termios.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "core/kinematics/units.hpp"
#include "core/machine/profile.hpp"
#include "firmware_support.hpp"

namespace fivebar {
namespace {

namespace fs = std::filesystem;
using firmware::Board;

// The board's serial line, raw: bytes out, lines in.
class Wire {
 public:
  explicit Wire(const fs::path& pty) {
    fd_ = ::open(pty.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ < 0) return;
    termios t{};
    if (::tcgetattr(fd_, &t) == 0) {
      ::cfmakeraw(&t);
      ::tcsetattr(fd_, TCSANOW, &t);
    }
  }
  ~Wire() {
    if (fd_ >= 0) ::close(fd_);
  }
  bool ok() const { return fd_ >= 0; }
  void send(const std::string& bytes) { (void)!::write(fd_, bytes.data(), bytes.size()); }
  // Reads until a line containing `what` arrives (true) or timeoutS pass (false). Lines read
  // are kept in seen().
  bool waitFor(const std::string& what, double timeoutS) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    while (std::chrono::steady_clock::now() < end) {
      char buf[256];
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n > 0) {
        partial_.append(buf, std::size_t(n));
        std::size_t nl;
        while ((nl = partial_.find('\n')) != std::string::npos) {
          std::string line = partial_.substr(0, nl);
          partial_.erase(0, nl + 1);
          if (!line.empty() && line.back() == '\r') line.pop_back();
          seen_ += line + "\n";
          if (line.find(what) != std::string::npos) return true;
        }
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    }
    return false;
  }
  const std::string& seen() const { return seen_; }

 private:
  int fd_ = -1;
  std::string partial_;
  std::string seen_;
};

class FirmwareBoard : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!firmware::firmwareAvailable())
      GTEST_SKIP() << "no ../shared/tools/grbl-sim or no built simulator (" << firmware::simulatorExe() << ")";
    dir_ = fs::temp_directory_path() / ("fivebar-board-fw-" + std::to_string(getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    pty_ = dir_ / "grblpty";
    board_ = std::make_unique<Board>(pty_, dir_ / "state", dir_ / "steps.txt");
    ASSERT_TRUE(board_->up()) << "the firmware did not start";
  }
  void TearDown() override {
    board_.reset();
    if (!HasFailure() && !dir_.empty()) fs::remove_all(dir_);
  }
  int cli(const std::string& args, double timeoutS, std::string* out = nullptr) {
    return firmware::runCli(args, dir_ / ("cli" + std::to_string(++runs_) + ".log"), timeoutS, out);
  }
  std::string port() const { return " --port " + pty_.string(); }

  fs::path dir_, pty_;
  std::unique_ptr<Board> board_;
  int runs_ = 0;
};

TEST_F(FirmwareBoard, FeedHoldWhileIdleIsHold0AndALineWaitsForCycleStart) {
  Wire wire(pty_);
  ASSERT_TRUE(wire.ok());
  wire.send("\x18");  // a reset: the banner says the board is there
  ASSERT_TRUE(wire.waitFor("Grbl 1.1h", 5.0)) << wire.seen();
  wire.send("?");
  ASSERT_TRUE(wire.waitFor("<Idle", 5.0)) << wire.seen();
  wire.send("!");
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  wire.send("?");
  ASSERT_TRUE(wire.waitFor("<Hold:0", 5.0)) << "a hold while Idle is complete at once: " << wire.seen();
  // A dwell sent during the hold: no answer while held.
  wire.send("G4P0.01\n");
  EXPECT_FALSE(wire.waitFor("ok", 1.0)) << "answered during the hold: " << wire.seen();
  wire.send("~");
  EXPECT_TRUE(wire.waitFor("ok", 5.0)) << "no ok after the cycle start: " << wire.seen();
  wire.send("?");
  EXPECT_TRUE(wire.waitFor("<Idle", 5.0)) << wire.seen();
}

TEST_F(FirmwareBoard, ATargetBeyondTheSoftLimitsWhileMovingHoldsThenAlarms) {
  Wire wire(pty_);
  ASSERT_TRUE(wire.ok());
  wire.send("\x18");
  ASSERT_TRUE(wire.waitFor("Grbl 1.1h", 5.0)) << wire.seen();
  // Factory settings: $110 500/min, $120 10/s^2, $130 200. Soft limits need homing on.
  for (const char* line : {"$22=1\n", "$20=1\n", "$X\n"}) {
    wire.send(line);
    ASSERT_TRUE(wire.waitFor("ok", 5.0)) << line << wire.seen();
  }
  wire.send("G1X-150F500\n");
  ASSERT_TRUE(wire.waitFor("ok", 5.0)) << wire.seen();
  std::this_thread::sleep_for(std::chrono::milliseconds(2000));  // at full speed
  wire.send("G1X-201F500\n");
  bool holdMoving = false, alarm = false;
  for (int i = 0; i < 200 && !alarm; ++i) {  // 10 s at most
    wire.send("?");
    alarm = wire.waitFor("ALARM:2", 0.05);
    holdMoving = holdMoving || wire.seen().find("<Hold:1") != std::string::npos;
  }
  ASSERT_TRUE(alarm) << wire.seen();
  EXPECT_TRUE(holdMoving) << "no Hold:1 before the alarm: " << wire.seen();
  // The line is not answered: mc_line waits in the critical event loop for the reset. (grbl-sim
  // does not deliver a reset into that loop, so the "ok" at the reset is not checked here; it
  // follows from protocol.c and is checked on the simulated GRBL.)
  const std::size_t alarmAt = wire.seen().find("ALARM:2");
  const std::size_t lineSent = wire.seen().find("ok", wire.seen().find("MPos:-"));
  EXPECT_TRUE(lineSent == std::string::npos || lineSent > alarmAt) << wire.seen();
  EXPECT_FALSE(wire.waitFor("ok", 1.0)) << "answered in the alarm: " << wire.seen();
}

TEST_F(FirmwareBoard, SendRefusesWhatTheBoardsSoftLimitsWouldAlarmOn) {
  const MachineProfile p = *preset("maker-plotter");
  ASSERT_EQ(cli("setup" + port() + " --machine maker-plotter --write --backup " + (dir_ / "backup.txt").string(), 60), 0);
  ASSERT_EQ(cli("reference" + port() + " --machine maker-plotter --yes", 20), 0);
  // Homing and soft limits on, a travel of 1 deg below the reference (home = machine 0,0).
  std::string out;
  ASSERT_EQ(cli("send" + port() + " '$22=1' '$20=1' '$130=1' '$131=1'", 20, &out), 0) << out;
  char up[96];
  std::snprintf(up, sizeof up, "G1X%.3fY%.3fF600", degFromRad(p.homeAngles.theta1) + 0.5,
                degFromRad(p.homeAngles.theta2));
  EXPECT_EQ(cli("send" + port() + " --machine maker-plotter " + up, 20, &out), 1);
  EXPECT_NE(out.find("not sent"), std::string::npos) << out;
  EXPECT_NE(out.find("ALARM:2"), std::string::npos) << out;
  ASSERT_EQ(cli("send" + port() + " '?'", 20, &out), 0) << out;
  EXPECT_NE(out.find("<Idle"), std::string::npos) << "nothing was sent: " << out;
  // Inside the travel it passes; the refused line, sent unchecked, raises the board's ALARM:2.
  char down[96];
  std::snprintf(down, sizeof down, "G1X%.3fY%.3fF600", degFromRad(p.homeAngles.theta1) - 0.5,
                degFromRad(p.homeAngles.theta2));
  EXPECT_EQ(cli("send" + port() + " --machine maker-plotter " + down, 20, &out), 0) << out;
  cli("send" + port() + " --unchecked --timeout 2 " + up, 20, &out);
  EXPECT_NE(out.find("ALARM:2"), std::string::npos) << out;
}

}  // namespace
}  // namespace fivebar
