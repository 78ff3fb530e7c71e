// SPDX-License-Identifier: GPL-3.0-or-later
// How close a job comes to what the machine can do (issue 16): plans SVG files as
// `fivebar plan FILE --fit --machine PROFILE --tolerance T` does, and prints per file the GRBL time
// estimate (which the real firmware matches within 0.1 %, tests/firmware), the time-optimal
// reference (core/planning/time_optimal.hpp), their ratio, and both split into pen-down strokes,
// travels and dwells.
// Run: build/release/tests/bench/fivebar_time_ratio --machine PRESET|FILE [--speed MM_PER_S]
//          [--tolerance MM] FILE.svg...        (docs/performance.md)
#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/machine/profile.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/time_optimal.hpp"
#include "job/job_source.hpp"

namespace fivebar {
namespace {

// The plan `fivebar plan FILE --fit` makes: the same job source as the CLI and the studio
// (job/job_source.hpp), the drawing fitted to the workspace.
std::optional<PlanResult> planFile(const QString& path, const MachineProfile& p, double toleranceMm) {
  PlanOptions o;
  o.toleranceMm = toleranceMm;
  o.fit = true;
  job::JobError error;
  auto loaded = job::loadJob(path, p, o, error);
  if (!loaded) return std::nullopt;
  PlanResult r = job::planRefining(loaded->drawing, loaded->source, loaded->profile, loaded->options, error);
  if (!error.empty() || !r.ok()) return std::nullopt;
  return r;
}

struct Split {
  double drawS = 0.0, travelS = 0.0, dwellS = 0.0;
};

Split splitOf(const PlannedJob& job) {
  Split s;
  for (const JobMove& m : job.moves) {
    if (m.kind == JobMoveKind::Draw) s.drawS += m.durationS;
    else if (m.kind == JobMoveKind::Travel) s.travelS += m.durationS;
    else s.dwellS += m.durationS;
  }
  return s;
}

int run(int argc, char** argv) {
  std::string machine = "maker-plotter";
  double speed = 0.0, tolerance = 0.1;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--machine" && i + 1 < argc) machine = argv[++i];
    else if (a == "--speed" && i + 1 < argc) speed = std::atof(argv[++i]);
    else if (a == "--tolerance" && i + 1 < argc) tolerance = std::atof(argv[++i]);
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    } else files.push_back(a);
  }
  std::optional<MachineProfile> p = preset(machine);
  if (!p) {
    ProfileLoad load = loadProfile(machine);
    if (!load.profile) {
      std::fprintf(stderr, "%s: not a preset or a valid profile file\n", machine.c_str());
      return 2;
    }
    p = load.profile;
  }
  if (speed > 0.0) p->drawSpeedMmPerS = speed;
  std::printf("%-28s %8s %8s %6s | %7s %7s %7s | %7s %7s %7s\n", "file", "job_s", "bound_s",
              "ratio", "draw", "travel", "dwell", "b_draw", "b_trav", "b_dwell");
  int failures = 0;
  for (const std::string& f : files) {
    const auto r = planFile(QString::fromStdString(f), *p, tolerance);
    const std::string name = f.substr(f.find_last_of('/') + 1);
    if (!r) {
      std::printf("%-28s planning failed\n", name.c_str());
      ++failures;
      continue;
    }
    const TimeOptimalJob b = timeOptimalJob(r->job, *p);
    const Split s = splitOf(r->job);
    std::printf("%-28s %8.2f %8.2f %6.3f | %7.2f %7.2f %7.2f | %7.2f %7.2f %7.2f\n", name.c_str(),
                r->report.estimatedTimeS, r->report.timeOptimalS,
                r->report.estimatedTimeS / r->report.timeOptimalS, s.drawS, s.travelS, s.dwellS,
                b.drawS, b.travelS, b.dwellS);
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace
}  // namespace fivebar

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);  // the import's worker process needs one
  return fivebar::run(argc, argv);
}
