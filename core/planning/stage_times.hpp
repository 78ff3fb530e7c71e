// SPDX-License-Identifier: GPL-3.0-or-later
// Wall-clock and CPU time of each pipeline stage, for `fivebar plan --timings` and the benchmarks.
#pragma once

#include <chrono>
#include <time.h>
#include <string>
#include <vector>

namespace fivebar {

struct StageTime {
  std::string name;
  double wallS = 0.0;
  double cpuS = 0.0;  // all threads of the process together
};

struct StageTimes {
  std::vector<StageTime> stages;  // in the order first run

  void add(const std::string& name, double wallS, double cpuS) {
    for (StageTime& s : stages)
      if (s.name == name) {
        s.wallS += wallS;
        s.cpuS += cpuS;
        return;
      }
    stages.push_back({name, wallS, cpuS});
  }
  void append(const StageTimes& other) {
    for (const StageTime& s : other.stages) add(s.name, s.wallS, s.cpuS);
  }
};

// Adds the time since construction (or the last lap / restart) to `times` under `name` at each
// lap().
class StageClock {
 public:
  explicit StageClock(StageTimes& times) : times_(times) { restart(); }
  void restart() {
    wall_ = Clock::now();
    cpu_ = processCpuS();
  }
  void lap(const std::string& name) {
    const Clock::time_point wall = Clock::now();
    const double cpu = processCpuS();
    times_.add(name, std::chrono::duration<double>(wall - wall_).count(), cpu - cpu_);
    wall_ = wall;
    cpu_ = cpu;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double processCpuS() {
    std::timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  StageTimes& times_;
  Clock::time_point wall_;
  double cpu_ = 0.0;
};

}  // namespace fivebar
