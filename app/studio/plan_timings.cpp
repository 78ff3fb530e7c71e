// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/plan_timings.hpp"

#include <QElapsedTimer>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/studio/main_window.hpp"
#include "widgets/document/import_controller.hpp"
#include "widgets/document/preview_controller.hpp"

namespace fivebar::studio {

void printPlanTimings(MainWindow& window) {
  struct Clock {
    QElapsedTimer sinceOpen;
    qint64 importMs = -1;      // the import's wall time, until the first plan after it is printed
    qint64 planStartMs = 0;    // when the plan in progress started
  };
  auto clock = std::make_shared<Clock>();
  clock->sinceOpen.start();
  QObject::connect(&window.importer(), &widgets::ImportController::finished, &window,
                   [clock](bool ok, const QString&) {
                     if (ok) clock->importMs = clock->sinceOpen.elapsed();
                   });
  QObject::connect(&window.preview(), &widgets::PreviewController::planningStarted, &window,
                   [clock] { clock->planStartMs = clock->sinceOpen.elapsed(); });
  widgets::PreviewController& preview = window.preview();
  QObject::connect(&preview, &widgets::PreviewController::resultChanged, &window, [clock, &preview] {
    if (preview.busy() || preview.result().status == widgets::PreviewStatus::Cancelled) return;
    const qint64 now = clock->sinceOpen.elapsed();
    if (clock->importMs >= 0) {
      std::fprintf(stderr, "fivebar-studio: opened and planned in %lld ms\n", static_cast<long long>(now));
      std::fprintf(stderr, "  import and placement: %lld ms\n", static_cast<long long>(clock->importMs));
      clock->importMs = -1;
    } else {
      std::fprintf(stderr, "fivebar-studio: planned in %lld ms\n",
                   static_cast<long long>(now - clock->planStartMs));
    }
    for (const StageTime& stage : preview.result().timings.stages)
      std::fprintf(stderr, "  %s: %ld ms (cpu %ld ms)\n", stage.name.c_str(), std::lround(stage.wallS * 1000),
                   std::lround(stage.cpuS * 1000));
  });
}

}  // namespace fivebar::studio
