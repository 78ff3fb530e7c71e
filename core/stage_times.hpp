// Wall-clock time of each pipeline stage, for `fivebar plan --timings` and the benchmarks.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace fivebar {

struct StageTimes {
  std::vector<std::pair<std::string, double>> stages;  // name, seconds, in the order run

  void add(const std::string& name, double seconds) {
    for (auto& [n, s] : stages)
      if (n == name) {
        s += seconds;
        return;
      }
    stages.emplace_back(name, seconds);
  }
  void append(const StageTimes& other) {
    for (const auto& [n, s] : other.stages) add(n, s);
  }
};

// Adds the time from construction (or the last lap) to `times` under `name` at each lap().
class StageClock {
 public:
  explicit StageClock(StageTimes& times) : times_(times), last_(Clock::now()) {}
  void restart() { last_ = Clock::now(); }
  void lap(const std::string& name) {
    const Clock::time_point now = Clock::now();
    times_.add(name, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  StageTimes& times_;
  Clock::time_point last_;
};

}  // namespace fivebar
