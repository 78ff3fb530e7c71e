// SPDX-License-Identifier: GPL-3.0-or-later
// The same probe transcript through the REAL GRBL 1.1h firmware (../shared/tools/grbl-sim, a
// host build of gnea/grbl on a pty) and through fivebar-sim: every answer must be the same.
// Skipped when ../shared is absent or the firmware cannot be built.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <string>
#include <vector>

namespace fivebar::test {
namespace {

// A raw client on a pseudo-terminal: writes a probe, collects what comes back for a while.
class PtyClient {
 public:
  explicit PtyClient(const std::string& path) {
    fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    if (fd_ < 0) return;
    termios t{};
    ::tcgetattr(fd_, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(fd_, TCSANOW, &t);
  }
  ~PtyClient() { if (fd_ >= 0) ::close(fd_); }
  bool ok() const { return fd_ >= 0; }
  std::string exchange(const std::string& bytes, int windowMs) {
    if (!bytes.empty() && ::write(fd_, bytes.data(), bytes.size()) < 0) return "<write failed>";
    std::string out;
    for (int waited = 0; waited < windowMs; waited += 10) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 10) > 0) {
        char buf[4096];
        const ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n > 0) out.append(buf, size_t(n));
      }
    }
    return out;
  }

 private:
  int fd_ = -1;
};

// The probes: queries, settings, parser errors, offsets, check mode, program end. None moves the
// machine, so the answers do not depend on timing.
const std::vector<std::string> kProbes = {
    "?", "?", "$I\n", "$#\n", "$N\n", "$$\n", "$20=1\n", "$G\n",
    // The accessory field A: (spindle S/C while its PWM runs, F flood) on the Ov: reports, which
    // a spindle or coolant change brings forward; no Ln: for N-numbered lines (stock config).
    "M3S1000\n", "?", "?", "?", "M5\n", "?", "M3S0\n", "?", "M4S100\n", "?", "M8\n", "?", "M9M5\n",
    "?", "S500\n", "?", "M3\n", "?", "S600\n", "?", "?", "M5\n", "N10G4P0\n", "?", "M1\n", "M7\n",
    "G2X1Y1I1\n", "G2X1Y1R0.2F100\n",
    "G2X10Y10I0J0F100\n", "G1X1\n", "G1 X1 Y1 Z1 F100 G4 P0\n", "$N0=G54\n", "$N\n",
    "G10L20P0X5Y5\n", "?", "?", "?", "$#\n", "M2\n", "$G\n", "$C\n", "G0X50\n", "?", "$C\n", "?",
    "?", "G1 X5 Y5                                                                 F9\n",
    "G4P0." + std::string(74, '0') + "\n", "G4P0." + std::string(75, '0') + "\n", "?", "$22=1\n",
    "$20=1\n", "$X\n", "G1X5F100\n", "?", "$10=3\n", "\x18", "?", "$10=3\n", "?"};
// From this probe on (a soft-limit alarm: the board answers nothing until reset) the answers are
// compared as one text, since when the firmware prints its [MSG:] varies by a few ms.
constexpr std::size_t kJoinFrom = 62;  // one past "G1X5F100"

// Each probe's bytes, and how long its answers are collected.
struct Probe {
  std::string bytes;
  int windowMs = 350;
};

std::vector<std::string> transcript(const std::string& pty, const std::vector<Probe>& probes) {
  PtyClient c(pty);
  std::vector<std::string> answers;
  if (!c.ok()) return answers;
  c.exchange("", 1500);  // a booting firmware's banner, if the pty opened before it
  for (const Probe& p : probes) answers.push_back(p.bytes + " -> " + c.exchange(p.bytes, p.windowMs));
  return answers;
}

bool waitFor(const QString& path) {
  for (int i = 0; i < 500 && !QFileInfo::exists(path); ++i) QThread::msleep(20);
  return QFileInfo::exists(path);
}

// The transcript through the real firmware, on its second power-up (a first one writes the
// EEPROM: a fresh one answers error:7 and restores the defaults, as a board that is used).
// Empty when the firmware is absent or does not start.
std::vector<std::string> firmwareTranscript(const QTemporaryDir& dir, const std::vector<Probe>& probes) {
  const QString shared = QStringLiteral(FIVEBAR_SHARED_DIR "/tools/grbl-sim");
  std::vector<std::string> expected;
  for (int run = 0; run < 2; ++run) {
    QProcess real;
    real.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    real.start("sh", {shared + "/start.sh", dir.path() + "/real", "1", dir.path() + "/state"});
    if (!waitFor(dir.path() + "/real")) return {};
    QThread::msleep(1000);
    if (run == 0) PtyClient((dir.path() + "/real").toStdString()).exchange("?", 1000);
    else expected = transcript((dir.path() + "/real").toStdString(), probes);
    real.terminate();
    real.waitForFinished(5000);
    for (int i = 0; i < 100 && QFileInfo::exists(dir.path() + "/real"); ++i) QThread::msleep(20);
  }
  return expected;
}

std::vector<std::string> simTranscript(const QTemporaryDir& dir, const std::vector<Probe>& probes) {
  QProcess ours;
  ours.setProcessChannelMode(QProcess::ForwardedErrorChannel);
  ours.start(FIVEBAR_SIM_EXE, {"--pty", dir.path() + "/ours", "--machine", "maker-plotter"});
  if (!waitFor(dir.path() + "/ours")) return {};
  const auto got = transcript((dir.path() + "/ours").toStdString(), probes);
  ours.terminate();
  ours.waitForFinished(5000);
  return got;
}

// Homing on a board without switches (the firmware in ../shared has none wired): $H searches Z
// for 1.5 x $132 at $25, answers no status request meanwhile (a '?' 0.3 s into the cycle), fails
// with ALARM:9, then the $H line's ok, the banner and the unlock message; $H without $22=1 is
// error:5. (A '?' in the same write as "$H" is answered or not as the firmware's timing falls.)
TEST(FirmwareReplay, HomingWithoutSwitchesAsTheRealGrbl) {
  if (!QFileInfo::exists(QStringLiteral(FIVEBAR_SHARED_DIR "/tools/grbl-sim/start.sh")))
    GTEST_SKIP() << "../shared/tools/grbl-sim absent";
  const std::vector<Probe> probes = {
      {"$H\n"}, {"$22=1\n"}, {"$132=2\n"}, {"$25=1000\n"}, {"$H\n", 3500}, {"?"}, {"G0X1\n"}, {"$X\n"},
      {"$H\n", 300}, {"?", 3500}, {"?"}, {"$X\n"}, {"$22=0\n"}, {"$H\n"}, {"?"}};
  QTemporaryDir dir;
  const auto expected = firmwareTranscript(dir, probes);
  if (expected.empty()) GTEST_SKIP() << "the real firmware did not start (build it per its README)";
  const auto got = simTranscript(dir, probes);
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected[i]) << "probe " << i;
}

TEST(FirmwareReplay, FivebarSimAnswersAsTheRealGrbl) {
  const QString shared = QStringLiteral(FIVEBAR_SHARED_DIR "/tools/grbl-sim");
  if (!QFileInfo::exists(shared + "/start.sh")) GTEST_SKIP() << "../shared/tools/grbl-sim absent";
  QTemporaryDir dir;
  std::vector<Probe> probes;
  for (const std::string& p : kProbes) probes.push_back({p});
  const auto expected = firmwareTranscript(dir, probes);
  if (expected.empty()) GTEST_SKIP() << "the real firmware did not start (build it per its README)";
  const auto got = simTranscript(dir, probes);

  ASSERT_EQ(got.size(), expected.size());
  ASSERT_GT(got.size(), kJoinFrom);
  ASSERT_NE(got[kJoinFrom - 1].find("G1X5F100"), std::string::npos);
  for (size_t i = 0; i + 1 < kJoinFrom; ++i) EXPECT_EQ(got[i], expected[i]) << "probe " << i;
  const auto strip = [](const std::vector<std::string>& v) {
    std::string all;
    for (size_t i = kJoinFrom - 1; i < v.size(); ++i) all += v[i].substr(v[i].find(" -> ") + 4);
    return all;
  };
  EXPECT_EQ(strip(got), strip(expected));
}

}  // namespace
}  // namespace fivebar::test
