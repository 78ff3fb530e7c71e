// SPDX-License-Identifier: GPL-3.0-or-later
// Streaming through a real pseudo-terminal to fivebar-sim emulating a 115200-baud wire.
//  - BM_StreamSendResponse: baseline, one line at a time (wait for each ok);
//  - BM_StreamCharacterCounting: GRBL character counting (128-byte budget), reported as lines/s,
//    as a fraction of what the 128-byte budget allows at 115200 baud (the wire: 11520 bytes/s
//    divided by line length + 1), and as a speed-up over the baseline;
//  - BM_RealSpeedStroke: a long stroke of short segments at real speed: planner starvations
//    inside the stroke (must be 0).
// Run: build/release/tests/bench/fivebar_bench_streaming   (docs/performance/streaming.md)
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/machine/profile.hpp"
#include "core/kinematics/units.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/transport/serial_transport.hpp"

namespace {

constexpr double kBaud = 115200.0;
constexpr int kLines = 1500;
double gBaselineLinesPerS = 0.0;

class Sim {
 public:
  explicit Sim(const QStringList& extra) {
    pty_ = dir_.path() + "/tty";
    record_ = dir_.path() + "/record.json";
    process_.start(FIVEBAR_SIM_EXE, QStringList{"--pty", pty_, "--machine", "maker-plotter",
                                                "--record", record_} + extra);
    for (int i = 0; i < 250 && !QFileInfo::exists(pty_); ++i) QThread::msleep(20);
  }
  ~Sim() { stop(); }
  const QString& pty() const { return pty_; }
  nlohmann::json stop() {
    if (process_.state() != QProcess::NotRunning) {
      process_.terminate();
      process_.waitForFinished(5000);
    }
    std::ifstream in(record_.toStdString());
    return nlohmann::json::parse(in, nullptr, false);
  }

 private:
  QTemporaryDir dir_;
  QString pty_, record_;
  QProcess process_;
};

struct AckCounter : fivebar::grbl::ProtocolListener {
  int acks = 0;
  int errors = 0;
  void onAck(const fivebar::grbl::Ack& a) override {
    ++acks;
    if (!a.ok()) ++errors;
  }
};

// Streams `lines` and returns the seconds from the first byte sent to the last answer.
double streamLines(const QString& pty, const std::vector<std::string>& lines, int budgetBytes) {
  fivebar::SerialTransport port(pty, int(kBaud));
  fivebar::MachineLink link(port, 0.0, 1);
  QString error;
  if (!port.open(&error)) {
    std::fprintf(stderr, "%s\n", error.toStdString().c_str());
    return -1.0;
  }
  AckCounter counter;
  link.protocol().addListener(&counter);
  link.protocol().setRxBufferBytes(budgetBytes);
  QEventLoop settle;
  QTimer::singleShot(300, &settle, &QEventLoop::quit);  // read the simulator's banner first
  settle.exec();
  QElapsedTimer clock;
  clock.start();
  for (const auto& l : lines) link.protocol().enqueue(l);
  QEventLoop loop;
  QObject::connect(&port, &fivebar::Transport::bytesReceived, &loop, [&] {
    if (counter.acks >= int(lines.size())) loop.quit();
  });
  QTimer::singleShot(120000, &loop, &QEventLoop::quit);
  loop.exec();
  const double s = double(clock.nsecsElapsed()) * 1e-9;
  link.protocol().removeListener(&counter);
  port.close();
  if (counter.acks != int(lines.size()) || counter.errors != 0)
    std::fprintf(stderr, "%d of %zu lines answered, %d errors\n", counter.acks, lines.size(), counter.errors);
  return counter.acks == int(lines.size()) && counter.errors == 0 ? s : -1.0;
}

std::vector<std::string> jobLines(int n) {
  const auto p = fivebar::preset("maker-plotter");
  const double t1 = fivebar::degFromRad(p->homeAngles.theta1);
  const double t2 = fivebar::degFromRad(p->homeAngles.theta2);
  std::vector<std::string> lines;
  char buf[96];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "G1X%.4fY%.4fF3000.0", t1 + 0.25 * (i % 9), t2 - 0.25 * (i % 7));
    lines.push_back(buf);
  }
  return lines;
}

double meanCost(const std::vector<std::string>& lines) {
  double bytes = 0;
  for (const auto& l : lines) bytes += double(l.size() + 1);
  return bytes / double(lines.size());
}

void BM_StreamSendResponse(benchmark::State& state) {
  const auto lines = jobLines(kLines);
  for (auto _ : state) {
    Sim sim({"--instant", "--baud", "115200"});
    const double s = streamLines(sim.pty(), lines, 1);
    if (s <= 0) { state.SkipWithError("stream failed"); return; }
    state.SetIterationTime(s);
    gBaselineLinesPerS = double(lines.size()) / s;
  }
  state.counters["lines_per_s"] = gBaselineLinesPerS;
}

void BM_StreamCharacterCounting(benchmark::State& state) {
  const auto lines = jobLines(kLines);
  const double ideal = kBaud / 10.0 / meanCost(lines);
  double rate = 0.0;
  for (auto _ : state) {
    Sim sim({"--instant", "--baud", "115200"});
    const double s = streamLines(sim.pty(), lines, fivebar::grbl::kRxBufferBytes);
    if (s <= 0) { state.SkipWithError("stream failed"); return; }
    state.SetIterationTime(s);
    rate = double(lines.size()) / s;
  }
  state.counters["lines_per_s"] = rate;
  state.counters["wire_limit_lines_per_s"] = ideal;
  state.counters["fraction_of_wire_limit"] = rate / ideal;
  if (gBaselineLinesPerS > 0) state.counters["speedup_vs_send_response"] = rate / gBaselineLinesPerS;
}

void BM_RealSpeedStroke(benchmark::State& state) {
  const auto p = fivebar::preset("maker-plotter");
  const double t1 = fivebar::degFromRad(p->homeAngles.theta1);
  const double t2 = fivebar::degFromRad(p->homeAngles.theta2);
  std::vector<std::string> lines = {"G90", "M3S1000", "G4P0.1"};
  char buf[96];
  for (int i = 1; i <= 400; ++i) {  // 0.3-deg segments at 1200 deg/min: 15 ms each
    std::snprintf(buf, sizeof buf, "G1X%.4fY%.4fF1200.0", t1 + 0.3 * i * 0.8, t2 + 0.3 * i * 0.6 + 0.2 * std::sin(i));
    lines.push_back(buf);
  }
  lines.push_back("M5");
  double starvations = -1, seconds = 0;
  for (auto _ : state) {
    Sim sim({"--baud", "115200", "--speedup", "1"});
    seconds = streamLines(sim.pty(), lines, fivebar::grbl::kRxBufferBytes);
    if (seconds <= 0) { state.SkipWithError("stream failed"); return; }
    state.SetIterationTime(seconds);
    QThread::msleep(100);
    const auto record = sim.stop();
    starvations = record.value("plannerStarvationsInStroke", -1.0);
  }
  state.counters["planner_starvations_in_stroke"] = starvations;
  state.counters["segments"] = 400;
}

BENCHMARK(BM_StreamSendResponse)->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StreamCharacterCounting)->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RealSpeedStroke)->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
