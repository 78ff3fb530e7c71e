// SPDX-License-Identifier: GPL-3.0-or-later
// End to end through a real pseudo-terminal: QSerialPort <-> pty <-> the fivebar-sim
// executable (started as a QProcess), driven by StreamSession as `fivebar stream` does.
#include <gtest/gtest.h>

#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <fstream>
#include <nlohmann/json.hpp>

#include "drivers/transport/serial_transport.hpp"
#include "drivers/transport/simulated_transport.hpp"
#include "drivers/stream/stream_session.hpp"
#include "sim_harness.hpp"

namespace fivebar::test {
namespace {

// RSS of this process in kB (VmRSS of /proc/self/status).
long rssKb() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmRSS:") {
      long kb = 0;
      in >> kb;
      return kb;
    }
    in.ignore(1 << 12, '\n');
  }
  return -1;
}

class SimProcess {
 public:
  SimProcess(const QString& dir, const QStringList& extra, const QString& tag = "a")
      : pty_(dir + "/tty-" + tag), record_(dir + "/record-" + tag + ".json") {
    // A board set up and referenced for the machine, as a user leaves it.
    QStringList args{"--pty", pty_, "--machine", "maker-plotter", "--record", record_, "--set-up", "--referenced"};
    args += extra;
    process_.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    process_.start(FIVEBAR_SIM_EXE, args);
    for (int i = 0; i < 250 && !QFileInfo::exists(pty_); ++i) QThread::msleep(20);
  }
  ~SimProcess() { stop(); }
  bool ready() const { return QFileInfo::exists(pty_); }
  const QString& pty() const { return pty_; }
  // Ends the simulator (SIGTERM) and returns its record file.
  nlohmann::json stop() {
    if (process_.state() != QProcess::NotRunning) {
      process_.terminate();
      process_.waitForFinished(5000);
    }
    std::ifstream in(record_.toStdString());
    return nlohmann::json::parse(in, nullptr, false);
  }
  bool running() { return process_.state() != QProcess::NotRunning; }
  // True once the process has exited (waitForFinished alone is false for an exited process).
  bool waitExit(int ms) {
    return process_.state() == QProcess::NotRunning || process_.waitForFinished(ms);
  }

 private:
  QString pty_;
  QString record_;
  QProcess process_;
};

struct Outcome {
  bool finished = false;
  bool ok = false;
  std::string message;
};

Outcome runSession(const QString& port, StreamOptions options, double timeoutS) {
  SerialTransport transport(port, 115200);
  MachineLink link(transport);
  link.poseTrust().confirmed();  // the maker referenced this board (it stands at the home pose)
  StreamSession session(link, std::move(options));
  Outcome out;
  QString error;
  if (!transport.open(&error)) {
    out.message = error.toStdString();
    return out;
  }
  std::string problem;
  if (!session.begin(&problem)) {
    out.message = problem;
    return out;
  }
  QEventLoop loop;
  QObject::connect(&session, &StreamSession::finished, [&](bool ok, const QString& m) {
    out = {true, ok, m.toStdString()};
    loop.quit();
  });
  QTimer::singleShot(int(timeoutS * 1000), &loop, &QEventLoop::quit);
  link.start();
  loop.exec();
  transport.close();
  return out;
}

Strokes recordedStrokes(const nlohmann::json& record) {
  Strokes s;
  if (record.is_object() && record.contains("strokesDeg"))
    s = record["strokesDeg"].get<Strokes>();
  return s;
}

struct PtyJob {
  MachineProfile p = testProfile();
  Strokes strokes;
  QTemporaryDir dir;
  std::string jobPath;
  PtyJob() {
    auto rng = fivebar::test::rng();
    strokes = randomStrokes(p, rng, 6, 15, 30.0);
    jobPath = (dir.path() + "/job.gcode").toStdString();
    std::ofstream(jobPath) << jobText(p, strokes, 3000.0);
  }
  StreamOptions options(bool resume) const {
    StreamOptions o;
    o.jobPath = jobPath;
    o.resume = resume;
    o.profile = p;
    o.machineName = "maker-plotter";
    return o;
  }
  double tol() const { return 1.01 / p.motors.stepsPerDeg1; }
};

TEST(PtyEndToEnd, JobStreamsToCompletion) {
  PtyJob job;
  SimProcess sim(job.dir.path(), {"--speedup", "20"});
  ASSERT_TRUE(sim.ready());
  const Outcome o = runSession(sim.pty(), job.options(false), 60.0);
  ASSERT_TRUE(o.finished);
  EXPECT_TRUE(o.ok) << o.message;
  EXPECT_FALSE(QFile::exists(QString::fromStdString(stream::progressPathFor(job.jobPath))));
  const nlohmann::json record = sim.stop();
  ASSERT_TRUE(record.is_object());
  const auto end = record["workPosition"].get<std::array<double, 3>>();
  EXPECT_NEAR(end[0], job.strokes.back().back()[0], job.tol());
  EXPECT_NEAR(end[1], job.strokes.back().back()[1], job.tol());
  EXPECT_EQ(record["rxOverflowBytes"].get<long>(), 0);
  expectStrokesCover(job.strokes, recordedStrokes(record), job.tol());
}

struct PtyFault {
  const char* spec;
  const char* expectInMessage;
};
void PrintTo(const PtyFault& f, std::ostream* os) { *os << f.spec; }

class PtyEndToEndFault : public ::testing::TestWithParam<PtyFault> {};

TEST_P(PtyEndToEndFault, EndsCleanSavesProgressAndResumeCompletes) {
  PtyJob job;
  const std::string spec = GetParam().spec;
  auto sim = std::make_unique<SimProcess>(job.dir.path(), QStringList{"--speedup", "20", "--fault", QString::fromStdString(spec)});
  ASSERT_TRUE(sim->ready());
  const Outcome first = runSession(sim->pty(), job.options(false), 60.0);
  ASSERT_TRUE(first.finished);
  EXPECT_FALSE(first.ok);
  EXPECT_NE(first.message.find(GetParam().expectInMessage), std::string::npos) << first.message;
  EXPECT_NE(first.message.find("--resume"), std::string::npos) << first.message;
  std::string err;
  const auto progress = stream::loadProgress(stream::progressPathFor(job.jobPath), &err);
  ASSERT_TRUE(progress) << err;
  EXPECT_GT(progress->lastAckedLine, 0);
  EXPECT_LE(progress->lastCompletedLine, progress->lastAckedLine);
  Strokes drawn;
  if (spec.rfind("drop", 0) == 0) {
    EXPECT_TRUE(sim->waitExit(5000)) << "the simulator closes the pty when the link drops";
    drawn = recordedStrokes(sim->stop());
    sim = std::make_unique<SimProcess>(job.dir.path(), QStringList{"--speedup", "20"}, "b");
    ASSERT_TRUE(sim->ready());
  }
  const Outcome second = runSession(sim->pty(), job.options(true), 60.0);
  ASSERT_TRUE(second.finished);
  EXPECT_TRUE(second.ok) << second.message;
  const Strokes more = recordedStrokes(sim->stop());
  drawn.insert(drawn.end(), more.begin(), more.end());
  expectStrokesCover(job.strokes, drawn, job.tol());
}

INSTANTIATE_TEST_SUITE_P(Faults, PtyEndToEndFault,
                         ::testing::Values(PtyFault{"reset-after=40", "reset"},
                                           PtyFault{"alarm-after=40", "ALARM:1"},
                                           PtyFault{"error-on=40", "error:20"},
                                           PtyFault{"drop-after=40", "Connection lost"}),
                         [](const auto& instance) {
                           std::string s = instance.param.spec;
                           return s.substr(0, s.find('-'));
                         });

// A fake transport: records writes, replays a board transcript, reports the port vanishing.
class FakeTransport : public Transport {
 public:
  bool open(QString*) override { return open_ = true; }
  void close() override { open_ = false; }
  bool isOpen() const override { return open_; }
  void write(const QByteArray& bytes) override { written += bytes; }
  QString name() const override { return "fake"; }
  void replay(const QByteArray& chunk) { emit bytesReceived(chunk); }
  void vanish(const QString& why) { emit disconnected(why); }
  QByteArray written;
  bool open_ = false;
};

TEST(FakeTransport, TranscriptReplayThroughMachineLinkAndOneDisconnect) {
  FakeTransport fake;
  MachineLink link(fake);
  struct Log : grbl::ProtocolListener {
    int acks = 0, errors = 0, disconnects = 0;
    void onAck(const grbl::Ack& a) override { ++acks; errors += a.ok() ? 0 : 1; }
    void onDisconnected(const std::string&) override { ++disconnects; }
  } log;
  link.protocol().addListener(&log);
  fake.open(nullptr);
  link.protocol().enqueue("G1X10F600");
  link.protocol().enqueue("G1X20");
  link.protocol().enqueue("G2X1Y1I1");
  EXPECT_EQ(fake.written, QByteArray("G1X10F600\nG1X20\nG2X1Y1I1\n"));
  for (const char* chunk : {"o", "k\r\nok", "\r\n<Run|MPos:1.0", "00,0.000,0.000|Bf:13,100|FS:600,0>\r\nerr",
                            "or:20\r\n"})
    fake.replay(chunk);
  EXPECT_EQ(log.acks, 3);
  EXPECT_EQ(log.errors, 1);
  EXPECT_EQ(link.protocol().state(), grbl::MachineState::Run);
  // QSerialPort reports a vanished port again and again; the link goes down once.
  for (int i = 0; i < 1000; ++i) fake.vanish("read error");
  EXPECT_EQ(log.disconnects, 1);
  link.protocol().removeListener(&log);
}

// The same session on the in-process simulated machine (SimulatedTransport, real-time clock
// times 20): the transport seam swaps without changing anything above it.
TEST(SimulatedTransport, StreamsAJobInProcess) {
  PtyJob job;
  sim::SimConfig board;  // set up for the profile and referenced at its home pose
  board.profile = job.p;
  board.setUp = true;
  board.referenced = true;
  SimulatedTransport transport(board, 20.0);
  MachineLink link(transport);
  link.poseTrust().confirmed();  // the maker referenced it
  StreamSession session(link, job.options(false));
  QString error;
  ASSERT_TRUE(transport.open(&error));
  std::string problem;
  ASSERT_TRUE(session.begin(&problem)) << problem;
  Outcome out;
  QEventLoop loop;
  QObject::connect(&session, &StreamSession::finished, [&](bool ok, const QString& m) {
    out = {true, ok, m.toStdString()};
    loop.quit();
  });
  QTimer::singleShot(60000, &loop, &QEventLoop::quit);
  transport.startClock();
  link.start();
  loop.exec();
  ASSERT_TRUE(out.finished);
  EXPECT_TRUE(out.ok) << out.message;
  expectStrokesCover(job.strokes, transport.machine().strokes(), job.tol());
}

TEST(PtyEndToEnd, ResumeRefusesAChangedJob) {
  PtyJob job;
  stream::JobProgress p;
  p.jobHash = "0000";  // saved for another version of the file...
  p.totalLines = 3;
  p.lastPenDownLine = 12;  // ...whose resume point is not the same in this one
  p.penDownAnglesDeg = {1.0, 2.0};
  ASSERT_EQ(stream::saveProgress(p, stream::progressPathFor(job.jobPath)), "");
  SimProcess sim(job.dir.path(), {"--instant"});
  ASSERT_TRUE(sim.ready());
  const Outcome o = runSession(sim.pty(), job.options(true), 10.0);
  EXPECT_FALSE(o.ok);
  EXPECT_NE(o.message.find("another version"), std::string::npos) << o.message;
  EXPECT_NE(o.message.find("line 12"), std::string::npos) << o.message;
}

// Soak: 200,000 lines through the pty to a simulator that acknowledges at once. Memory must
// not grow with the number of lines streamed, and the stream must stay in sync to the end.
TEST(PtyEndToEnd, SoakTwoHundredThousandLines) {
  const MachineProfile p = testProfile();
  QTemporaryDir dir;
  const std::string jobPath = (dir.path() + "/soak.gcode").toStdString();
  constexpr int kLines = 200000;
  {
    std::ofstream out(jobPath);
    const double t1 = degFromRad(p.homeAngles.theta1), t2 = degFromRad(p.homeAngles.theta2);
    out << "G90\nG0X" << fmt(t1) << "Y" << fmt(t2) << "\n";  // starts where the machine stands
    for (int i = 2; i < kLines; ++i)
      out << "G1X" << fmt(t1 + 0.5 * (i % 7)) << "Y" << fmt(t2 - 0.5 * (i % 5)) << "F6000\n";
  }
  SimProcess sim(dir.path(), {"--instant"});
  ASSERT_TRUE(sim.ready());
  SerialTransport transport(sim.pty(), 115200);
  MachineLink link(transport);
  link.poseTrust().confirmed();  // the maker referenced it
  StreamOptions options;
  options.jobPath = jobPath;
  options.profile = p;
  StreamSession session(link, options);
  QString error;
  ASSERT_TRUE(transport.open(&error)) << error.toStdString();
  std::string problem;
  ASSERT_TRUE(session.begin(&problem)) << problem;
  long rssAtTenPercent = -1, rssMax = 0;
  bool ok = false;
  std::string message;
  QEventLoop loop;
  QObject::connect(&session, &StreamSession::finished, [&](bool good, const QString& m) {
    ok = good;
    message = m.toStdString();
    loop.quit();
  });
  QObject::connect(&link, &MachineLink::ticked, [&](double) {
    const auto* r = session.runner();
    if (!r) return;
    const auto acked = r->snapshot().linesAcked;
    if (rssAtTenPercent < 0 && acked > kLines / 10) rssAtTenPercent = rssKb();
    if (rssAtTenPercent > 0) rssMax = std::max(rssMax, rssKb());
  });
  QTimer::singleShot(55000, &loop, &QEventLoop::quit);
  link.start();
  loop.exec();
  transport.close();
  ASSERT_TRUE(ok) << message;
  const nlohmann::json record = sim.stop();
  ASSERT_TRUE(record.is_object());
  // Every line arrived exactly once, after the "$$" the checked stream reads first (the board's
  // soft limits, for the motion check).
  EXPECT_EQ(record["linesReceived"].get<long>(), kLines + 1) << "every line arrived exactly once";
  EXPECT_EQ(record["rxOverflowBytes"].get<long>(), 0);
  ASSERT_GT(rssAtTenPercent, 0);
  EXPECT_LT(rssMax - rssAtTenPercent, 4096) << "RSS grew from " << rssAtTenPercent << " kB to "
                                            << rssMax << " kB";
}

}  // namespace
}  // namespace fivebar::test
